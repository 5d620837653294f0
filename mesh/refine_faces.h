// Local refinement of a triangle mesh: chosen triangles split 1-to-4 at their
// edge midpoints, with a red-green closure so the result stays conforming. It
// makes a differently meshed copy of a surface whose first vertices are the
// input's, to test that a result does not depend on the meshing.
#pragma once

#include <vector>

#include "mesh/surface_mesh.h"

namespace unfold {

/// Splits every selected triangle into four at its edge midpoints ("red").
/// Closure: an unselected triangle with two or three split edges is made red
/// too (repeated until none is left), and one with a single split edge is
/// halved from that edge's midpoint to the opposite corner ("green"). So no
/// midpoint hangs on an unsplit edge (no T-junction): a closed mesh stays
/// closed, every child keeps its parent's orientation, and the surface (the
/// union of the triangles) is unchanged.
/// @param mesh a mesh whose faces are all triangles with valid vertex indices
/// @param selected indices of the faces to split (any order; repeats are ignored)
/// @return the input's vertices first, in their order, then one new vertex per
///         split edge (the midpoint, shared by the faces on that edge); each
///         input face's children in its place, in input face order
/// @throws UsageError if a face is not a triangle or names a vertex out of
///         range, or a selected index is not a face
SurfaceMesh refine_faces(const SurfaceMesh& mesh, const std::vector<int>& selected);

}  // namespace unfold
