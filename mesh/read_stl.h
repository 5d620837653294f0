// Reads STL files, binary or ASCII (through OpenMesh; STL stores floats).
#pragma once

#include <cstdint>
#include <istream>
#include <string>

#include "mesh/surface_mesh.h"

namespace unfold {

/// STL: binary when the size matches the triangle count at byte 80 (the rule
/// OpenMesh applies too), else ASCII, which must be complete ("endsolid").
/// Every triangle's corners are separate vertices, as STL stores them.
/// @throws InputError for a file that is neither, or truncated
SurfaceMesh read_stl(std::istream& in, const std::string& path, std::uintmax_t file_size);

}  // namespace unfold
