// Binary OFF and PLY and both STL flavours go through OpenMesh's readers,
// which store floats anyway (the text formats have readers of their own:
// OpenMesh passes every position on as float, losing digits).
#pragma once

#include <string>

#include "mesh/surface_mesh.h"

namespace unfold {

/// Reads `path` with OpenMesh's IO layer into a SurfaceMesh with the faces as
/// the file gives them (no halfedge structure: non-manifold faces are kept).
/// @param declared_vertices, declared_faces the header's counts, or -1 if
///        unknown: a reader delivering fewer met a truncated file
/// @throws InputError if OpenMesh cannot parse the file or it is truncated
SurfaceMesh read_with_openmesh(const std::string& path, long long declared_vertices,
                               long long declared_faces);

}  // namespace unfold
