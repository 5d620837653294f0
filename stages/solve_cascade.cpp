#include "stages/solve_cascade.h"

#include <memory>
#include <utility>

namespace unfold {

CascadeSolve solve_cascade(CascadeSetup setup, const CascadeOptions& options,
                           const Eigen::MatrixX3d* warm) {
  CascadeOptions cascade = options;
  cascade.beta = setup.beta.start;
  const std::unique_ptr<CascadeBackend> backend =
      setup.backend.valid() ? setup.backend.get()
                            : make_backend(setup.backend_options, *setup.problem, setup.amg);
  CascadeSolve out;
  out.cascade = run_cascade(*setup.problem, *backend, cascade, warm);
  const auto* local_global = dynamic_cast<const LocalGlobalBackend*>(backend.get());
  if (!local_global) {
    out.linear_solver = "ceres";
    return out;
  }
  out.linear_solver = setup.backend_options.linear_solver.method;
  out.cg = local_global->data().cg_stats;
  if (out.cg.unconverged_solves > 0)
    out.warnings.push_back(
        std::to_string(out.cg.unconverged_solves) + " of " + std::to_string(out.cg.solves) +
        " global steps stopped at linear_solver.cg_max_iterations (worst relative residual " +
        std::to_string(out.cg.worst_relative_residual) + ")");
  return out;
}

}  // namespace unfold
