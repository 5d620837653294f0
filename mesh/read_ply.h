// Reads PLY files: ASCII (parsed here, full double precision) and binary.
#pragma once

#include <cstdint>
#include <istream>
#include <string>

#include "mesh/surface_mesh.h"

namespace unfold {

/// PLY: header lines up to "end_header", then ASCII records (one per line) or
/// binary data (through OpenMesh). Positions from the vertex element's x, y, z;
/// faces from the face element's vertex_indices (or vertex_index) list.
/// @throws InputError (naming path and line) for anything malformed or truncated
SurfaceMesh read_ply(std::istream& in, const std::string& path, std::uintmax_t file_size);

}  // namespace unfold
