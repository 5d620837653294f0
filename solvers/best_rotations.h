// Local step of the local-global solver (paper Eq. 2): the rotation that best
// maps each cell's rest edges onto its current edges.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "mesh/edge_graph.h"

namespace unfold {

using Rotations = std::vector<Eigen::Matrix3d>;

/// The rotation R minimising sum_k |target_k - R source_k|^2 (Kabsch), with
/// det(R) = +1 enforced by flipping the weakest singular direction. Computed as
/// the polar factor of cov^T by scaled Newton iteration when det(cov) is clearly
/// positive, else by a Jacobi SVD; both agree to roundoff.
/// @param cov sum_k source_k target_k^T (3x3 covariance).
Eigen::Matrix3d best_rotation(const Eigen::Matrix3d& cov);

/// The same rotation, refined from a nearby guess (the cell's rotation one
/// iteration earlier) by Newton's method on the rotation group: quadratic
/// convergence, so one to three cheap steps where the guess is close; far
/// guesses and ill-conditioned cells go to best_rotation(cov). Agrees with it
/// to about 1e-12.
/// @param guess a rotation
Eigen::Matrix3d best_rotation(const Eigen::Matrix3d& cov, const Eigen::Matrix3d& guess);

/// For every vertex i: R_i = argmin_R sum_{j in N_i} |(q_i - q_j) - R (p_i - p_j)|^2,
/// in parallel over vertices. Isolated vertices get the identity.
/// @param rest    rest positions p (n x 3)
/// @param current current positions q (n x 3)
/// @param R       output, resized to n
void best_rotations(const EdgeGraph& graph, const Eigen::MatrixX3d& rest,
                    const Eigen::MatrixX3d& current, Rotations* R);

}  // namespace unfold
