// The alternating local-global solver of the paper (Sec. 3-4), libigl style:
// a precomputation (symbolic factorization, once per mesh), a per-beta
// numeric factorization, and cheap iterations that reuse it.
//
// Global step (docs/method.md): with rotations fixed, the gradient of Eq. 3 is
//   4 ((beta+1) L - n I + 1 1^T) Q - 2 beta b,  b_i = sum_{j in N_i} (R_i + R_j)(p_i - p_j).
// b sums to zero, so the minimiser has zero mean and solves the sparse system
//   ((beta+1) L - n I) Q = (beta / 2) b.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCholesky>

#include "mesh/edge_graph.h"
#include "solvers/best_rotations.h"

namespace unfold {

struct LocalGlobalData {
  const EdgeGraph* graph = nullptr;
  Eigen::MatrixX3d rest;          ///< rest positions P
  Eigen::SparseMatrix<double> L;  ///< graph Laplacian
  double beta = 0;                ///< beta of the current factorization
  int negative_pivots = 0;        ///< inertia of (beta+1) L - n I: 1 iff the energy is bounded
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt;
};

/// Builds L and the fill-reducing ordering and symbolic factorization.
/// @param graph edge graph of the tet mesh; kept by pointer, must outlive data
/// @param rest  rest positions (graph.num_vertices x 3)
void local_global_precomputation(const EdgeGraph& graph, const Eigen::MatrixX3d& rest,
                                 LocalGlobalData* data);

/// Numeric factorization of (beta+1) L - n I.
/// @throws NumericalError if the factorization breaks down
void local_global_set_beta(double beta, LocalGlobalData* data);

/// True when (beta+1) lambda_2 > n, i.e. the quadratic part is positive
/// definite off the constant vector and the global step is a minimiser. The
/// one negative direction (the constant vector, eigenvalue -n) can vanish in
/// rounding when beta is huge, so no negative pivot counts as bounded too.
inline bool energy_bounded(const LocalGlobalData& data) { return data.negative_pivots <= 1; }

/// Global step: the zero-mean minimiser of Eq. 3 over Q for fixed rotations R.
void global_step(const LocalGlobalData& data, const Rotations& R, Eigen::MatrixX3d* Q);

}  // namespace unfold
