#include "solvers/make_backend.h"

#include "core/errors.h"
#include "solvers/backend_support.h"

namespace unfold {

std::unique_ptr<CascadeBackend> make_backend(const BackendOptions& options,
                                             const UnfoldProblem& problem,
                                             std::shared_ptr<const AmgData> amg) {
  const std::string refused = why_backend_cannot_run(options.method, problem.terms);
  if (!refused.empty()) throw UsageError(refused);
  if (options.method == "local_global")
    return std::make_unique<LocalGlobalBackend>(problem, options.linear_solver, std::move(amg));
  if (options.method == "ceres" || options.method == "dpmu")
    return std::make_unique<CeresBackend>(problem, options.ceres);
  throw UsageError("method '" + options.method + "' has no cascade backend");
}

}  // namespace unfold
