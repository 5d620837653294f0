#include "solvers/integrate_rotation_field.h"

#include <chrono>
#include <future>
#include <utility>

#include "core/errors.h"
#include "solvers/arap_solve.h"

namespace unfold {

Eigen::MatrixX3d integrate_rotation_field(const EdgeGraph& graph, const Eigen::MatrixX3d& P,
                                          const Eigen::MatrixX3d& Q, double lambda2,
                                          const IntegrateOptions& options, IntegrateTimes* times,
                                          const std::vector<double>& edge_factors) {
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
    const ArapSolveOptions anchored{
        1, options.iterations - 1, options.tolerance, options.anchor * lambda2,
        5, inverse_length,         edge_factors};
    // The anchored steps' factor depends on neither the integration nor its
    // result: it is made on the other core meanwhile (CHOLMOD factorizes on one
    // thread, and so does the integration's own factor).
    std::future<std::unique_ptr<SparseLdlt>> pending;
    if (anchored.max_iterations > 0 && graph.num_vertices > 1)
      pending =
          std::async(std::launch::async, [&] { return arap_factorization(graph, P, anchored); });
    X = arap_solve(graph, P, std::move(X), {1, 1, 0.0, 0.0, 0, inverse_length, edge_factors});
    const auto integrated = Clock::now();
    const std::unique_ptr<SparseLdlt> factor = pending.valid() ? pending.get() : nullptr;
    X = arap_solve(graph, P, std::move(X), anchored, factor.get());
    if (times) {
      times->integration = std::chrono::duration<double>(integrated - start).count();
      times->anchored = std::chrono::duration<double>(Clock::now() - integrated).count();
    }
  }
  X.rowwise() -= X.colwise().mean();
  return X;
}

}  // namespace unfold
