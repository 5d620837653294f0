// Stage: the cascade (solvers/cascade.h) on a set-up problem: the paper's
// local/global solve, or the ceres and dpmu backends'.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "solvers/cascade.h"
#include "solvers/local_global.h"
#include "stages/setup_cascade.h"

namespace unfold {

struct CascadeSolve {
  CascadeResult cascade;
  std::string linear_solver;          ///< direct, iterative, or ceres (the ceres and dpmu backends)
  CgStats cg;                         ///< iterative: what the CG global steps did
  std::vector<std::string> warnings;  ///< global steps stopped at cg_max_iterations
};

/// Runs the cascade of `options` (cascade.*) from setup's starting beta.
/// @param warm  start positions (n x 3), or null: the rest positions
/// @throws NumericalError when the solve fails
CascadeSolve solve_cascade(CascadeSetup setup, const CascadeOptions& options,
                           const Eigen::MatrixX3d* warm = nullptr);

}  // namespace unfold
