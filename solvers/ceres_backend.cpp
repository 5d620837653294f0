#include "solvers/ceres_backend.h"

#include <ceres/gradient_problem.h>
#include <ceres/gradient_problem_solver.h>

#include "core/errors.h"
#include "core/progress.h"
#include "geometry/row_major.h"
#include "metrics/edge_ratio.h"
#include "solvers/quadratic_part.h"

namespace unfold {
namespace {

using Factor = Eigen::SimplicialLLT<Eigen::SparseMatrix<double>>;

// Q from the preconditioned variables z (row-major n x 3): Q = P^T L^-T z.
Eigen::MatrixX3d positions(const Factor& factor, const double* z, int n) {
  const Eigen::MatrixX3d Z = Eigen::Map<const RowMatrixX3d>(z, n, 3);
  return factor.permutationPinv() * factor.matrixU().solve(Z);
}

// What Ceres minimises: CeresBackend::objective.
class UnfoldFunction : public ceres::FirstOrderFunction {
 public:
  UnfoldFunction(const CeresBackend& backend, int num_parameters)
      : backend_(backend), num_parameters_(num_parameters) {}
  bool Evaluate(const double* z, double* cost, double* gradient) const override {
    *cost = backend_.objective(z, gradient);
    return std::isfinite(*cost);
  }
  int NumParameters() const override { return num_parameters_; }

 private:
  const CeresBackend& backend_;
  int num_parameters_;
};

// Records each iteration (energy and edge ratio) in the cascade's history.
class HistoryCallback : public ceres::IterationCallback {
 public:
  HistoryCallback(const UnfoldProblem& problem, const Factor& factor, const double* z, int cascade,
                  double beta, std::vector<IterationRecord>* history)
      : problem_(problem),
        factor_(factor),
        z_(z),
        cascade_(cascade),
        beta_(beta),
        history_(history) {}
  ceres::CallbackReturnType operator()(const ceres::IterationSummary& summary) override {
    if (summary.iteration == 0) return ceres::SOLVER_CONTINUE;  // the starting point
    const Eigen::MatrixX3d Q = positions(factor_, z_, problem_.num_vertices());
    const double delta = edge_ratio(*problem_.graph, problem_.rest, Q);
    history_->push_back({int(history_->size()) + 1, cascade_, beta_, summary.cost, delta});
    report_detail([&](std::ostream& line) {
      line << "ceres iteration " << history_->size() << " cascade " << cascade_ << " energy "
           << summary.cost << " edge ratio " << delta;
    });
    return ceres::SOLVER_CONTINUE;
  }

 private:
  const UnfoldProblem& problem_;
  const Factor& factor_;
  const double* z_;
  int cascade_;
  double beta_;
  std::vector<IterationRecord>* history_;
};

}  // namespace

void validate_ceres_options(const CeresOptions& o) {
  ceres::LineSearchDirectionType type;
  std::string name = o.line_search_direction_type;
  if (!ceres::StringToLineSearchDirectionType(name, &type))
    throw UsageError(
        "config key 'ceres.line_search_direction_type' must be LBFGS, BFGS, "
        "NONLINEAR_CONJUGATE_GRADIENT or STEEPEST_DESCENT, got '" +
        o.line_search_direction_type + "'");
  if (o.max_num_iterations < 1)
    throw UsageError("config key 'ceres.max_num_iterations' must be at least 1");
  if (!(o.function_tolerance >= 0) || !(o.gradient_tolerance >= 0) || !(o.parameter_tolerance >= 0))
    throw UsageError("config keys 'ceres.*_tolerance' must be finite numbers >= 0");
  if (o.max_lbfgs_rank < 1) throw UsageError("config key 'ceres.max_lbfgs_rank' must be >= 1");
}

CeresBackend::CeresBackend(const UnfoldProblem& problem, const CeresOptions& options)
    : problem_(problem), options_(options) {
  validate_ceres_options(options);
}

void CeresBackend::set_beta(double beta) {
  beta_ = beta;
  bounded_ = quadratic_part_bounded(problem_, beta);
  std::vector<Eigen::Triplet<double>> triplets;
  for (const auto& term : problem_.terms)
    if (term->scales_with_beta()) term->add_preconditioner(term->weight(beta), &triplets);
  Eigen::SparseMatrix<double> M(problem_.num_vertices(), problem_.num_vertices());
  M.setFromTriplets(triplets.begin(), triplets.end());
  const double shift = 1e-8 * M.diagonal().cwiseAbs().maxCoeff();
  for (int i = 0; i < M.rows(); ++i) M.coeffRef(i, i) += shift;
  preconditioner_.compute(M);
  if (preconditioner_.info() != Eigen::Success)
    throw NumericalError("factorizing the Ceres preconditioner failed at beta = " +
                         std::to_string(beta));
}

double CeresBackend::objective(const double* z, double* gradient) const {
  const int n = problem_.num_vertices();
  const Eigen::MatrixX3d Q = positions(preconditioner_, z, n);
  Rotations R;
  fit_rotations(problem_, Q, beta_, &R);
  Eigen::MatrixX3d grad;
  const double cost = total_energy(problem_, Q, R, beta_, gradient ? &grad : nullptr);
  // dE/dz = L^-1 P dE/dQ.
  if (gradient)
    Eigen::Map<RowMatrixX3d>(gradient, n, 3) =
        preconditioner_.matrixL().solve(preconditioner_.permutationP() * grad);
  return cost;
}

bool CeresBackend::run_stage(const StageOptions& options, int cascade, Eigen::MatrixX3d* Q,
                             double* previous_energy, std::vector<IterationRecord>* history) {
  const Factor& factor = preconditioner_;
  RowMatrixX3d z = factor.matrixU() * (factor.permutationP() * *Q);
  ceres::GradientProblem gradient_problem(new UnfoldFunction(*this, 3 * problem_.num_vertices()));
  ceres::GradientProblemSolver::Options solver_options;
  std::string name = options_.line_search_direction_type;
  ceres::StringToLineSearchDirectionType(name, &solver_options.line_search_direction_type);
  solver_options.max_num_iterations = options_.max_num_iterations;
  solver_options.function_tolerance = options_.function_tolerance;
  solver_options.gradient_tolerance = options_.gradient_tolerance;
  solver_options.parameter_tolerance = options_.parameter_tolerance;
  solver_options.max_lbfgs_rank = options_.max_lbfgs_rank;
  solver_options.update_state_every_iteration = true;  // the callback reads x
  HistoryCallback callback(problem_, factor, z.data(), cascade, beta_, history);
  solver_options.callbacks.push_back(&callback);
  ceres::GradientProblemSolver::Summary summary;
  ceres::Solve(solver_options, gradient_problem, z.data(), &summary);
  if (!z.allFinite() || summary.termination_type == ceres::FAILURE)
    throw NumericalError("the Ceres solve failed at beta = " + std::to_string(beta_) + ": " +
                         summary.message);
  report_detail([&](std::ostream& line) { line << summary.BriefReport(); });
  *Q = positions(factor, z.data(), problem_.num_vertices());
  Q->rowwise() -= Q->colwise().mean();
  *previous_energy = summary.final_cost;
  // Each cascade is solved to convergence; the band is checked at its end.
  const double delta = edge_ratio(*problem_.graph, problem_.rest, *Q);
  return in_band(delta, options.edge_ratio_band);
}

}  // namespace unfold
