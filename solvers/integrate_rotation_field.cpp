#include "solvers/integrate_rotation_field.h"

#include <utility>

#include "core/errors.h"

namespace unfold {

IntegratedRotations integrate_rotations(const EdgeGraph& graph, const Eigen::MatrixX3d& P,
                                        const Eigen::MatrixX3d& Q, double lambda2,
                                        const IntegrateOptions& options,
                                        const std::vector<double>& edge_factors) {
  if (options.iterations < 0 || !(options.anchor >= 0) || !(options.tolerance >= 0) ||
      !(lambda2 > 0))
    throw UsageError(
        "integrate_rotation_field: iterations, anchor and tolerance must be >= 0, lambda_2 > 0");
  if (options.weights != "uniform" && options.weights != "inverse_length")
    throw UsageError("integrate_rotation_field: weights must be uniform or inverse_length, got '" +
                     options.weights + "'");
  const bool inverse_length = options.weights == "inverse_length";
  IntegratedRotations out{Q,
                          {1, options.iterations - 1, options.tolerance, options.anchor * lambda2,
                           5, inverse_length, edge_factors},
                          {}};
  if (options.iterations == 0) return out;
  if (out.anchored.max_iterations > 0 && graph.num_vertices > 1)
    out.anchored_factor = std::async(std::launch::async, [&graph, &P, anchored = out.anchored] {
      return arap_factorization(graph, P, anchored);
    });
  out.positions = arap_solve(graph, P, std::move(out.positions),
                             {1, 1, 0.0, 0.0, 0, inverse_length, edge_factors});
  return out;
}

Eigen::MatrixX3d anchored_steps(const EdgeGraph& graph, const Eigen::MatrixX3d& P,
                                IntegratedRotations integrated) {
  Eigen::MatrixX3d X = std::move(integrated.positions);
  if (integrated.anchored.max_iterations >= 0) {  // iterations > 0: integrated
    const std::unique_ptr<SparseLdlt> factor =
        integrated.anchored_factor.valid() ? integrated.anchored_factor.get() : nullptr;
    X = arap_solve(graph, P, std::move(X), integrated.anchored, factor.get());
  }
  X.rowwise() -= X.colwise().mean();
  return X;
}

Eigen::MatrixX3d integrate_rotation_field(const EdgeGraph& graph, const Eigen::MatrixX3d& P,
                                          const Eigen::MatrixX3d& Q, double lambda2,
                                          const IntegrateOptions& options,
                                          const std::vector<double>& edge_factors) {
  return anchored_steps(graph, P, integrate_rotations(graph, P, Q, lambda2, options, edge_factors));
}

}  // namespace unfold
