// Shape quality of tetrahedra: how far each is from flat.
#pragma once

#include <Eigen/Core>

namespace unfold {

/// The quality of each tetrahedron, 6 sqrt(2) |volume| / l^3 with l the root
/// mean square of its six edge lengths: 1 for a regular tet, 0 for a flat one
/// (a sliver, a needle or a tet with coinciding corners). Invariant to rigid
/// motions, scaling and corner order.
/// @param V positions (rows: vertices)
/// @param T tets (rows of corner indices into V; not checked)
Eigen::VectorXd tet_quality(const Eigen::MatrixX3d& V, const Eigen::MatrixX4i& T);

}  // namespace unfold
