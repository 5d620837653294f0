// Reads OFF files: text (parsed here, full double precision) and binary.
#pragma once

#include <cstdint>
#include <istream>
#include <string>

#include "mesh/surface_mesh.h"

namespace unfold {

/// OFF: "[ST][C][N]OFF [BINARY]", counts "nv nf ne", one vertex per line (x y z
/// first, then optional normal/colour values), one face per line ("k i1..ik",
/// then an optional colour). Binary OFF goes through OpenMesh.
/// @param in the open file; file_size its size in bytes
/// @throws InputError (naming path and line) for anything malformed or truncated
SurfaceMesh read_off(std::istream& in, const std::string& path, std::uintmax_t file_size);

}  // namespace unfold
