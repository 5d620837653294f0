// The rotation that best maps a set of source vectors onto target vectors
// (Kabsch), given their 3x3 covariance: what the local step (fit_rotations,
// solvers/unfold_problem.h) and the rigidity metrics solve for every cell.
#pragma once

#include <Eigen/Core>

namespace unfold {

/// The rotation R minimising sum_k |target_k - R source_k|^2 (Kabsch), with
/// det(R) = +1 enforced by flipping the weakest singular direction. Computed as
/// the polar factor of cov^T by scaled Newton iteration when det(cov) is clearly
/// positive, else by a Jacobi SVD; both agree to roundoff.
/// @param cov sum_k source_k target_k^T (3x3 covariance).
Eigen::Matrix3d best_rotation(const Eigen::Matrix3d& cov);

/// The same rotation, refined from a nearby guess (the cell's rotation one
/// iteration earlier) by Newton's method on the rotation group: quadratic
/// convergence, so one to three cheap steps where the guess is close, flat
/// (rank 2) and reflected (det(cov) < 0) cells included; far guesses and
/// degenerate cells (the weakest two singular values alike) go to
/// best_rotation(cov). Agrees with it to about 1e-12.
/// @param guess a rotation
Eigen::Matrix3d best_rotation(const Eigen::Matrix3d& cov, const Eigen::Matrix3d& guess);

/// Cells a call of best_rotations_from_guesses takes at most.
inline constexpr int kRotationPacket = 8;

/// *rotation[k] = best_rotation(*cov[k], *rotation[k]) for k < count, the
/// same values bit for bit, a packet of cells at once (vectorized: the local
/// steps' loops call it a packet at a time).
/// @param count at most kRotationPacket
void best_rotations_from_guesses(const Eigen::Matrix3d* const* cov,
                                 Eigen::Matrix3d* const* rotation, int count);

}  // namespace unfold
