// The boundary of a tet mesh (the triangles of one tet only) as a surface,
// and the check that a given surface is that boundary.
#pragma once

#include <Eigen/Core>
#include <string>

#include "mesh/surface_mesh.h"

namespace unfold {

/// The boundary surface of tets T over vertices V: its vertices are the
/// boundary vertices in their order in V (surface vertex k is the k-th
/// boundary row of V), its triangles oriented away from their tets.
/// @throws InputError if T is empty or an index is outside V
SurfaceMesh tet_mesh_boundary(const Eigen::MatrixX3d& V, const Eigen::MatrixX4i& T);

/// The row of V that each surface vertex is (same position, exactly), and how
/// far the surface's triangles are from the boundary triangles of T.
/// @param mismatch set to "" when they are the same triangles, else to how many
///        the surface and the boundary do not share (a carved tet mesh, such as
///        the robust route's, has its surface's vertices but not always its
///        triangles on its boundary)
/// @throws InputError naming the first surface vertex not in V
Eigen::VectorXi match_tet_mesh_boundary(const SurfaceMesh& surface, const Eigen::MatrixX3d& V,
                                        const Eigen::MatrixX4i& T, std::string* mismatch);

}  // namespace unfold
