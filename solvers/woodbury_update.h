// Solves with A + U U^T from a sparse factorization of A and a few dense
// columns U (Woodbury's identity): the local spread's region centroids
// (energies/stretch_energy.h) are k dense rank-one parts that would fill a
// sparse factor, so they are added after it.
#pragma once

#include <Eigen/Core>
#include <Eigen/Dense>

#include "solvers/sparse_ldlt.h"

namespace unfold {

struct WoodburyUpdate {
  Eigen::MatrixXd U;               ///< n x k
  Eigen::MatrixXd Z;               ///< A^{-1} U
  Eigen::LDLT<Eigen::MatrixXd> S;  ///< I + U^T A^{-1} U
  int negative_eigenvalues = 0;    ///< of S
};

/// Z and S for the A last factorized by ldlt. A + U U^T then has the inertia of
/// A less S's negative eigenvalues (Haynsworth), so negative_eigenvalues
/// corrects ldlt.negative_pivots() (its count for A) to that of A + U U^T.
/// @param U n x k, k >= 0 (k = 0: nothing to do)
/// @throws NumericalError if S is singular (A + U U^T is)
void woodbury_precomputation(const SparseLdlt& ldlt, const Eigen::MatrixXd& U,
                             WoodburyUpdate* update);

/// Turns x = A^{-1} b into (A + U U^T)^{-1} b.
void woodbury_solve(const WoodburyUpdate& update, Eigen::MatrixX3d* x);

}  // namespace unfold
