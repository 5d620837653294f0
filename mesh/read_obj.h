// Reads Wavefront OBJ files: positions and faces.
#pragma once

#include <cstdint>
#include <istream>
#include <string>

#include "mesh/surface_mesh.h"

namespace unfold {

/// OBJ: "v x y z" and "f a b c ..." where each corner is "i", "i/t", "i//n" or
/// "i/t/n" with 1-based or negative (relative) i. Other records (vt, vn, g, o,
/// s, usemtl, l, ...) carry nothing unfold needs and are skipped.
/// @throws InputError (naming path and line) for a malformed record
SurfaceMesh read_obj(std::istream& in, const std::string& path);

}  // namespace unfold
