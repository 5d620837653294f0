#include "solvers/integrate_rotation_field.h"

#include <utility>

#include "core/errors.h"
#include "geometry/best_rotation.h"
#include "mesh/locality_order.h"
#include "mesh/permute_edge_graph.h"

namespace unfold {
namespace {

// Q moved onto X by the similarity s R q + t that best fits it (least squares).
Eigen::MatrixX3d fit_similarity(const Eigen::MatrixX3d& Q, const Eigen::MatrixX3d& X) {
  const Eigen::RowVector3d q_mean = Q.colwise().mean(), x_mean = X.colwise().mean();
  const Eigen::MatrixX3d q = Q.rowwise() - q_mean;
  const Eigen::Matrix3d cov = q.transpose() * (X.rowwise() - x_mean);  // sum q x^T
  const Eigen::Matrix3d R = best_rotation(cov);
  const double length2 = q.squaredNorm();
  const double s = length2 > 0 ? (R * cov).trace() / length2 : 1.0;
  return (s * q * R.transpose()).rowwise() + x_mean;
}

}  // namespace

IntegratedRotations integrate_rotations(const EdgeGraph& graph, const Eigen::MatrixX3d& P,
                                        const Eigen::MatrixX3d& Q, double lambda2,
                                        const IntegrateOptions& options,
                                        const std::vector<double>& edge_factors) {
  if (options.iterations < 0 || !(options.anchor >= 0) || !(options.tolerance >= 0) ||
      options.lbfgs < 0 || !(lambda2 > 0))
    throw UsageError(
        "integrate_rotation_field: iterations, anchor, tolerance and lbfgs must be >= 0, lambda_2 "
        "> 0");
  if (!(options.pose_pull >= 0 && options.pose_pull <= 1))
    throw UsageError("integrate_rotation_field: pose_pull must be in [0, 1]");
  if (options.weights != "uniform" && options.weights != "inverse_length")
    throw UsageError("integrate_rotation_field: weights must be uniform or inverse_length, got '" +
                     options.weights + "'");
  if (options.anchor_weights != "uniform" && options.anchor_weights != "stiffness")
    throw UsageError(
        "integrate_rotation_field: anchor_weights must be uniform or stiffness, got '" +
        options.anchor_weights + "'");
  const int n = graph.num_vertices;
  if (P.rows() != n || Q.rows() != n ||
      !(edge_factors.empty() || edge_factors.size() == size_t(graph.num_edges())))
    throw UsageError(
        "integrate_rotation_field: need P and Q with one row per graph vertex, and no edge "
        "factors or one per edge");
  const bool inverse_length = options.weights == "inverse_length";
  IntegratedRotations out{Q,
                          {1, options.iterations - 1, options.tolerance, options.anchor * lambda2,
                           5, inverse_length, edge_factors},
                          {},
                          {},
                          {},
                          {}};
  out.anchored.anchor_by_stiffness = options.anchor_weights == "stiffness";
  out.anchored.lbfgs = options.lbfgs;
  if (options.iterations == 0) return out;
  const EdgeGraph* g = &graph;
  const Eigen::MatrixX3d* rest = &P;
  const Eigen::MatrixX3d* start = &Q;  // Q in the steps' order: the pull's target
  Eigen::MatrixX3d reordered_Q;
  if (n >= options.locality_order_vertices) {
    auto r = std::make_unique<LocalityOrdered>();
    r->order = locality_order(P, 1);  // the held vertex stays first
    std::vector<int> edge_order;
    r->graph = permute_edge_graph(graph, r->order, &edge_order);
    r->P = P(r->order, Eigen::all);
    reordered_Q = Q(r->order, Eigen::all);
    out.positions = reordered_Q;
    start = &reordered_Q;
    for (size_t e = 0; e < edge_factors.size(); ++e)
      out.anchored.edge_factors[e] = edge_factors[size_t(edge_order[e])];
    g = &r->graph;
    rest = &r->P;
    out.reordered = std::move(r);
  }
  const bool multigrid = options.lbfgs > 0 && n >= options.multigrid_vertices;
  const bool steps_follow = out.anchored.max_iterations > 0 && n > 1;
  if (steps_follow && multigrid)
    out.anchored_multigrid = std::async(std::launch::async, [g, rest, anchored = out.anchored] {
      return arap_multigrid_precomputation(*g, *rest, anchored);
    });
  else if (steps_follow)
    out.anchored_factor = std::async(std::launch::async, [g, rest, anchored = out.anchored] {
      return arap_factorization(*g, *rest, anchored);
    });
  ArapSolveOptions integrate{1, 1, 0.0, 0.0, 0, inverse_length, out.anchored.edge_factors};
  const std::unique_ptr<ArapMultigrid> integration_multigrid =
      multigrid ? arap_multigrid_precomputation(*g, *rest, integrate) : nullptr;
  out.positions = arap_solve(*g, *rest, std::move(out.positions), integrate, nullptr, nullptr,
                             integration_multigrid.get());
  if (options.pose_pull > 0 && steps_follow)
    out.pull = options.pose_pull * (fit_similarity(*start, out.positions) - out.positions);
  return out;
}

Eigen::MatrixX3d anchored_steps(const EdgeGraph& caller_graph, const Eigen::MatrixX3d& caller_P,
                                IntegratedRotations integrated, ArapSolveReport* report) {
  const LocalityOrdered* r = integrated.reordered.get();
  const EdgeGraph& graph = r ? r->graph : caller_graph;
  const Eigen::MatrixX3d& P = r ? r->P : caller_P;
  Eigen::MatrixX3d X = std::move(integrated.positions);
  if (report) *report = {0, true};
  if (integrated.anchored.max_iterations >= 0) {  // iterations > 0: integrated
    const std::unique_ptr<SparseLdlt> factor =
        integrated.anchored_factor.valid() ? integrated.anchored_factor.get() : nullptr;
    const std::unique_ptr<ArapMultigrid> multigrid =
        integrated.anchored_multigrid.valid() ? integrated.anchored_multigrid.get() : nullptr;
    if ((factor || multigrid) && integrated.pull.rows() == X.rows()) {
      // The factor is L + A on the free rows (all but the held first): (L + A)^-1 A
      // passes the modes softer than the anchor (the pose) and damps the stiffer ones.
      const int m = int(X.rows()) - integrated.anchored.num_fixed;
      const Eigen::VectorXd A = arap_anchor_weights(graph, P, integrated.anchored);
      const Eigen::MatrixX3d pull = A.asDiagonal() * integrated.pull.bottomRows(m);
      Eigen::MatrixX3d filtered;
      if (multigrid)
        arap_multigrid_solve(*multigrid, pull, &filtered);
      else
        factor->solve(pull, &filtered);
      X.bottomRows(m) += filtered;
    }
    ArapSolveReport steps;
    X = arap_solve(graph, P, std::move(X), integrated.anchored, factor.get(), &steps,
                   multigrid.get());
    if (report && steps.steps > 0) *report = steps;
  }
  X.rowwise() -= X.colwise().mean();
  if (!r) return X;
  Eigen::MatrixX3d in_caller_order(X.rows(), 3);
  in_caller_order(r->order, Eigen::all) = X;
  return in_caller_order;
}

Eigen::MatrixX3d integrate_rotation_field(const EdgeGraph& graph, const Eigen::MatrixX3d& P,
                                          const Eigen::MatrixX3d& Q, double lambda2,
                                          const IntegrateOptions& options,
                                          const std::vector<double>& edge_factors) {
  return anchored_steps(graph, P, integrate_rotations(graph, P, Q, lambda2, options, edge_factors));
}

}  // namespace unfold
