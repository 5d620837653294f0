// Reduces a surface mesh to fewer vertices by quadric-error edge collapses.
#pragma once

#include "mesh/surface_mesh.h"

namespace unfold {

/// Decimates the triangulated mesh (OpenMesh quadric decimater, refusing
/// collapses that flip a face normal) to about `target_vertices` vertices and
/// returns the compacted triangle mesh. Returns `mesh` unchanged when it has
/// no more than `target_vertices` vertices. Faces the halfedge structure
/// cannot take (on non-manifold edges or repeating a vertex) are left out
/// with a glog warning, and vertices then used by no face are dropped. A
/// closed single-component input stays so.
/// @param mesh            faces must refer to existing vertices.
/// @param target_vertices wanted vertex count, >= 4.
/// @throws UsageError if target_vertices < 4; InputError if a face refers to
///         a vertex that does not exist.
SurfaceMesh simplify_surface_mesh(const SurfaceMesh& mesh, int target_vertices);

}  // namespace unfold
