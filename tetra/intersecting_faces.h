// Self-intersections of a triangle mesh: the pairs of faces that cross,
// touch or overlap anywhere other than at the vertices and edges they share.
// The conforming tetrahedralization cannot use such a surface, and the robust
// route reports how many there are (TetReport::intersecting_faces).
#pragma once

#include <Eigen/Core>
#include <utility>
#include <vector>

namespace unfold {

/// The pairs (s, t), s < t, of triangles of F that intersect beyond the
/// vertices and edge they share. Vertices at equal positions count as one
/// vertex. Triangles sharing an edge intersect only when they are coplanar and
/// folded onto each other; triangles sharing a vertex only when they meet at
/// another point too; a triangle listed twice intersects its copy. Touching
/// counts as intersecting (closed triangles). A triangle with two corners at
/// one position (rejected by check_surface_mesh) is skipped.
/// Exact: every decision is a sign of Shewchuk's orient3d (TetGen's robust
/// predicate), so nearly coplanar or nearly touching triangles are decided
/// correctly. Candidate pairs come from a uniform grid of the triangles'
/// bounding boxes, tested in parallel.
/// @param V vertex positions (finite)
/// @param F triangles, indices into V
/// @returns the pairs, sorted
/// @throws UsageError if an index of F is out of range
std::vector<std::pair<int, int>> intersecting_face_pairs(const Eigen::MatrixX3d& V,
                                                         const Eigen::MatrixX3i& F);

}  // namespace unfold
