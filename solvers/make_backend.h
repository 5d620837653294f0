// The solver backend a run's method picks: the local-global iterations of
// Algorithm 1 (local_global) or the full Ceres solve (ceres, dpmu), over one
// UnfoldProblem.
#pragma once

#include <memory>
#include <string>

#include "solvers/cascade.h"
#include "solvers/ceres_backend.h"
#include "solvers/local_global.h"
#include "solvers/unfold_problem.h"

namespace unfold {

struct BackendOptions {
  std::string method = "local_global";  ///< local_global, ceres or dpmu (Options::method)
  LinearSolverOptions linear_solver;    ///< local_global: the global step's solver
  CeresOptions ceres;                   ///< ceres and dpmu
};

/// The backend of options.method for `problem`.
/// @param problem kept by reference, must outlive the backend
/// @param amg     local_global with the iterative solver: an AMG hierarchy of a
///                multiple of the problem's A_beta to reuse (e.g. lambda_2's); may be null
/// @throws UsageError for another method, or a term the backend cannot run
///         (why_backend_cannot_run)
std::unique_ptr<CascadeBackend> make_backend(const BackendOptions& options,
                                             const UnfoldProblem& problem,
                                             std::shared_ptr<const AmgData> amg = nullptr);

}  // namespace unfold
