// Algorithm 1 of the paper: local-global iterations in cascades of growing
// beta, stopped when the mean edge-length ratio enters a band around 1.
#pragma once

#include <Eigen/Core>
#include <array>
#include <vector>

#include "mesh/edge_graph.h"
#include "solvers/best_rotations.h"

namespace unfold {

struct CascadeOptions {
  double beta = 0;         ///< starting beta (absolute), > 0
  int k_iter = 15;         ///< iterations per cascade at most
  double epsilon = 1e-4;   ///< a cascade ends when |f_e / f_s - 1| < epsilon
  int num_cascades = 4;    ///< cascades at most ("num")
  double growth = 2.0;     ///< beta factor between cascades
  std::array<double, 2> edge_ratio_band = {0.95, 1.05};  ///< stop once the edge ratio is inside
};

struct IterationRecord {
  int iteration;  ///< 1-based over the whole run
  int cascade;    ///< 1-based
  double beta;
  double energy;      ///< Eq. 3 after the global step, at that iteration's rotations
  double edge_ratio;  ///< delta after the global step
};

struct CascadeResult {
  Eigen::MatrixX3d positions;  ///< canonical pose, zero mean
  int iterations = 0;
  int cascades = 0;  ///< number of beta values used
  double final_beta = 0;
  double edge_ratio = 0;
  bool reached_band = false;  ///< false: stopped by the cascade limit instead
  bool bounded = true;        ///< false if some beta was below the n / lambda_2 bound
  std::vector<IterationRecord> history;
};

/// Runs Algorithm 1 from Q = P.
/// @param graph edge graph of the tet mesh (connected)
/// @param rest  rest positions P (n x 3)
/// @throws NumericalError if a factorization fails or a non-finite position appears
CascadeResult run_cascade(const EdgeGraph& graph, const Eigen::MatrixX3d& rest,
                          const CascadeOptions& options);

}  // namespace unfold
