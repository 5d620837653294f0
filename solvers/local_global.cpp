#include "solvers/local_global.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <utility>
#include <vector>

#include "core/errors.h"
#include "core/progress.h"
#include "energies/concave_term.h"
#include "energies/quadratic_term.h"
#include "energies/rotation_term.h"
#include "metrics/edge_ratio.h"
#include "solvers/anderson_acceleration.h"
#include "solvers/backend_support.h"
#include "solvers/block_kernels.h"

namespace unfold {
bool use_iterative_solver(const LinearSolverOptions& options,
                          const Eigen::SparseMatrix<double>& A) {
  if (options.method != "auto") return options.method == "iterative";
  return predicted_factorization_flops(A) > 1e9 * options.direct_max_gflop;
}

void validate_linear_solver_options(const LinearSolverOptions& o) {
  const auto require = [](bool ok, const std::string& key, const std::string& what) {
    if (!ok) throw UsageError("config key '" + key + "' " + what);
  };
  require(o.method == "auto" || o.method == "direct" || o.method == "iterative",
          "linear_solver.method", "must be auto, direct or iterative, got '" + o.method + "'");
  require(std::isfinite(o.direct_max_gflop) && o.direct_max_gflop >= 0,
          "linear_solver.direct_max_gflop", "must be a finite number >= 0");
  require(std::isfinite(o.cg_tolerance) && o.cg_tolerance > 0 && o.cg_tolerance < 1,
          "linear_solver.cg_tolerance", "must be a number in (0, 1)");
  require(std::isfinite(o.cg_forcing) && o.cg_forcing >= 0 && o.cg_forcing < 1,
          "linear_solver.cg_forcing", "must be a number in [0, 1)");
  require(o.cg_max_iterations >= 1, "linear_solver.cg_max_iterations", "must be at least 1");
}

void local_global_precomputation(const UnfoldProblem& problem, LocalGlobalData* data,
                                 const LinearSolverOptions& options,
                                 std::shared_ptr<const AmgData> amg) {
  const std::string refused = why_backend_cannot_run("local_global", problem.terms);
  if (!refused.empty()) throw UsageError(refused);
  data->cg = CgOptions{options.cg_tolerance, options.cg_forcing, options.cg_max_iterations};
  data->problem = &problem;
  data->part = assemble_quadratic_part(problem);
  data->A = data->part.A_fixed;
  data->A.makeCompressed();
  data->rhs.resize(problem.num_vertices(), 3);
  data->beta = 0;
  data->rotation_terms.clear();
  data->concave_terms.clear();
  for (const auto& term : problem.terms) {
    if (dynamic_cast<const RotationTerm*>(term.get()))
      data->rotation_terms.push_back(static_cast<const QuadraticTerm*>(term.get()));
    if (dynamic_cast<const ConcaveTerm*>(term.get())) data->concave_terms.push_back(term.get());
  }
  data->iterative = use_iterative_solver(options, data->A);
  if (!data->iterative) {
    data->ldlt.analyze(data->A);
  } else {
    if (!amg) {
      auto own = std::make_shared<AmgData>();
      amg_precomputation(data->part.A_beta, AmgOptions{}, own.get());
      amg = std::move(own);
    }
    data->amg = std::move(amg);
  }
}

void local_global_set_beta(double beta, LocalGlobalData* data) {
  // A_fixed, A_beta and A share one pattern (assemble keeps explicit zeros):
  // only the values change.
  const auto values = [](Eigen::SparseMatrix<double>& M) {
    return Eigen::Map<Eigen::VectorXd>(M.valuePtr(), M.nonZeros());
  };
  values(data->A) = values(data->part.A_fixed) + beta * values(data->part.A_beta);
  data->beta = beta;
  data->B_free = data->part.B_fixed + beta * data->part.B_beta;
  data->c_free = data->part.c_fixed + beta * data->part.c_beta;
  if (data->iterative) {
    data->cg_stats.negative_curvature = false;
    return;
  }
  try {
    data->ldlt.factorize(data->A);
  } catch (const NumericalError& e) {
    std::ostringstream what;
    what << "factorizing the global matrix failed at beta = " << beta << ": " << e.what();
    throw NumericalError(what.str());
  }
  data->negative_pivots = data->ldlt.negative_pivots();
  woodbury_precomputation(data->ldlt, data->part.U_regions, &data->regions);
  data->negative_pivots -= data->regions.negative_eigenvalues;
}

void global_step(const LocalGlobalData& data, const Rotations& R, Eigen::MatrixX3d* Q) {
  data.rhs = data.B_free;
  for (const QuadraticTerm* term : data.rotation_terms)
    term->add_linear(R, term->weight(data.beta), &data.rhs);
  if (!data.concave_terms.empty()) {
    data.tangent.setZero(Q->rows(), 3);
    for (const EnergyTerm* term : data.concave_terms)
      dynamic_cast<const ConcaveTerm&>(*term).add_tangent(*Q, term->weight(data.beta),
                                                          &data.tangent);
    data.rhs += data.tangent;
  }
  if (data.iterative) {
    data.rhs_rows = data.rhs;
    data.x_rows = *Q;
    const CgResult r = projected_cg(CsrView::of_symmetric(data.A), *data.amg, data.rhs_rows,
                                    &data.x_rows, data.cg, &data.cg_workspace, &data.part.U_fixed);
    CgStats& s = data.cg_stats;
    ++s.solves;
    s.iterations += r.iterations;
    s.worst_relative_residual = std::max(s.worst_relative_residual, r.relative_residual);
    if (!r.converged && !r.negative_curvature) ++s.unconverged_solves;
    s.negative_curvature = s.negative_curvature || r.negative_curvature;
    *Q = data.x_rows;
    return;
  }
  data.ldlt.solve(data.rhs, Q);
  woodbury_solve(data.regions, Q);
  // Every B_t sums to zero, so Q has zero mean up to roundoff; remove that too.
  Q->rowwise() -= Q->colwise().mean();
}

double energy_after_global_step(const LocalGlobalData& data, const Rotations& R,
                                const Eigen::MatrixX3d& Q) {
  double energy = data.c_free;
  for (const QuadraticTerm* term : data.rotation_terms)
    energy += term->weight(data.beta) * term->constant(R);
  energy -= (Q.array() * data.rhs.array()).sum();
  if (data.iterative) {
    const RowMatrixX3d& r = data.cg_workspace.r;
    for (Eigen::Index i = 0; i < Q.rows(); ++i) energy -= Q.row(i).dot(r.row(i));
  }
  // The concave terms' tangent is in rhs but not in A: with A Q = B + T - r the
  // quadratic part is -tr(Q^T rhs) + 2 tr(Q^T T) - tr(Q^T r) + c; the terms' own
  // values at Q then replace their tangent.
  if (!data.concave_terms.empty()) {
    energy += 2 * (Q.array() * data.tangent.array()).sum();
    for (const EnergyTerm* term : data.concave_terms)
      energy += term->evaluate(Q, R, term->weight(data.beta), nullptr);
  }
  return energy;
}

double energy_from_covariances(const LocalGlobalData& data, const Eigen::MatrixX3d& Q,
                               const Rotations& R, const std::vector<Eigen::Matrix3d>& S) {
  // Every term is translation invariant but A stands for the true Hessian on
  // zero-mean Q only (quadratic_term.h): the form is taken at Q less its mean.
  const CsrView A = CsrView::of_symmetric(data.A);
  const Eigen::RowVector3d mean = Q.colwise().mean();
  using Sum = Eigen::Array<double, 1, 1>;
  const Sum sum = chunked_row_sum(A.rows, [&](int i) {
    const Eigen::RowVector3d q = Q.row(i) - mean;
    double e = 0;
    for (int k = A.outer[i]; k < A.outer[i + 1]; ++k)
      e += A.values[k] * q.dot(Q.row(A.inner[k]) - mean);
    e -= 2 * q.dot(data.B_free.row(i));
    if (!data.rotation_terms.empty()) e -= 2 * (R[size_t(i)] * S[size_t(i)]).trace();
    return Sum(e);
  });
  double energy = sum(0) + data.c_free;
  if (data.part.U_fixed.cols() > 0)
    energy += (data.part.U_fixed.transpose() * (Q.rowwise() - mean)).squaredNorm();
  for (const QuadraticTerm* term : data.rotation_terms)
    energy += term->weight(data.beta) * term->constant(R);
  for (const EnergyTerm* term : data.concave_terms)
    energy += term->evaluate(Q, R, term->weight(data.beta), nullptr);
  return energy;
}

LocalGlobalBackend::LocalGlobalBackend(const UnfoldProblem& problem,
                                       const LinearSolverOptions& options,
                                       std::shared_ptr<const AmgData> amg)
    : rest_lengths_(edge_lengths(*problem.graph, problem.rest)) {
  local_global_precomputation(problem, &data_, options, std::move(amg));
}

void LocalGlobalBackend::set_beta(double beta) { local_global_set_beta(beta, &data_); }

bool LocalGlobalBackend::run_stage(const StageOptions& options, int cascade, Eigen::MatrixX3d* Q,
                                   double* previous_energy, std::vector<IterationRecord>* history) {
  const UnfoldProblem& problem = *data_.problem;
  const bool accelerate = options.anderson > 0;
  AndersonAcceleration anderson(std::max(1, options.anderson));
  // With acceleration the rotations are fitted at the end of each iteration
  // (the safeguard needs the energy at them), and reused by the next.
  double level = 0;  // energy of the current iterate at its best rotations
  const auto fit_and_measure = [&] {
    fit_rotations(problem, *Q, data_.beta, &R_, &covariances_);
    return energy_from_covariances(data_, *Q, R_, covariances_);
  };
  if (accelerate) level = fit_and_measure();
  // The iterate before the global step and the plain step after it, their
  // storage reused from iteration to iteration.
  Eigen::MatrixX3d x, plain;
  for (int i = 1;; ++i) {
    if (!accelerate) fit_rotations(problem, *Q, data_.beta, &R_, &covariances_);
    if (accelerate) x = *Q;
    global_step(data_, R_, Q);
    const int iteration = int(history->size()) + 1;
    if (!Q->allFinite()) {
      std::ostringstream what;
      what << "non-finite positions at iteration " << iteration << " (cascade " << cascade
           << ", beta = " << data_.beta << ")";
      throw NumericalError(what.str());
    }
    double energy;
    if (accelerate) {
      // Accept the extrapolation only if it lowers the energy; the plain
      // step always does (docs/method.md), so the iterates stay monotone.
      plain = *Q;
      anderson.next(x.reshaped(), plain.reshaped(), Q->reshaped());
      energy = fit_and_measure();
      if (!(energy <= level)) {
        anderson.reset();
        *Q = plain;
        energy = fit_and_measure();
      }
      level = energy;
    } else {
      energy = energy_after_global_step(data_, R_, *Q);
    }
    const double delta = edge_ratio(*problem.graph, rest_lengths_, *Q);
    history->push_back({iteration, cascade, data_.beta, energy, delta});
    report_step(i, options.max_iterations);
    report_detail([&](std::ostream& line) {
      line << "iteration " << iteration << " cascade " << cascade << " beta " << data_.beta
           << " energy " << energy << " edge ratio " << delta;
    });
    if (options.break_in_band && in_band(delta, options.edge_ratio_band)) return true;
    const bool converged = std::abs(energy / *previous_energy - 1.0) < options.epsilon;
    *previous_energy = energy;
    if (converged || i >= options.max_iterations) return in_band(delta, options.edge_ratio_band);
  }
}

}  // namespace unfold
