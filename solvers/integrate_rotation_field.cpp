#include "solvers/integrate_rotation_field.h"

#include <chrono>
#include <utility>

#include "core/errors.h"
#include "solvers/arap_solve.h"

namespace unfold {

Eigen::MatrixX3d integrate_rotation_field(const EdgeGraph& graph, const Eigen::MatrixX3d& P,
                                          const Eigen::MatrixX3d& Q, double lambda2,
                                          const IntegrateOptions& options, IntegrateTimes* times) {
  if (options.iterations < 0 || !(options.anchor >= 0) || !(options.tolerance >= 0) ||
      !(lambda2 > 0))
    throw UsageError(
        "integrate_rotation_field: iterations, anchor and tolerance must be >= 0, lambda_2 > 0");
  if (options.weights != "uniform" && options.weights != "inverse_length")
    throw UsageError("integrate_rotation_field: weights must be uniform or inverse_length, got '" +
                     options.weights + "'");
  const bool inverse_length = options.weights == "inverse_length";
  Eigen::MatrixX3d X = Q;
  if (options.iterations > 0) {
    using Clock = std::chrono::steady_clock;
    const auto start = Clock::now();
    X = arap_solve(graph, P, std::move(X), {1, 1, 0.0, 0.0, 0, inverse_length});
    const auto integrated = Clock::now();
    X = arap_solve(graph, P, std::move(X),
                   {1, options.iterations - 1, options.tolerance, options.anchor * lambda2, 5,
                    inverse_length});
    if (times) {
      times->integration = std::chrono::duration<double>(integrated - start).count();
      times->anchored = std::chrono::duration<double>(Clock::now() - integrated).count();
    }
  }
  X.rowwise() -= X.colwise().mean();
  return X;
}

}  // namespace unfold
