#include "solvers/local_global.h"

#include <glog/logging.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <utility>
#include <vector>

#include "core/errors.h"
#include "metrics/edge_ratio.h"
#include "solvers/anderson_acceleration.h"

namespace unfold {
namespace {

// A_fixed and A_beta: the sums of weight * H (the growth Hessian: H for the
// quadratic terms local-global accepts) over the terms that do not / do scale
// with beta, on the union pattern of all terms (explicit zeros kept, so that
// A = A_fixed + beta A_beta keeps one pattern). The triplets are gathered once
// into one reserved buffer: at 10^5 vertices they are ~10^7, and growing such
// vectors by reallocation cost more than the assembly itself.
void assemble(const UnfoldProblem& problem, Eigen::SparseMatrix<double>* A_fixed,
              Eigen::SparseMatrix<double>* A_beta) {
  const int n = problem.num_vertices();
  std::vector<Eigen::Triplet<double>> all;
  all.reserve(size_t(n) + 6 * size_t(problem.graph->num_edges()));
  std::vector<std::pair<size_t, bool>> term_ends;  // end of each term's triplets, scaled?
  for (const auto& term : problem.terms) {
    term->add_growth_hessian(term->weight(1.0), &all);
    term_ends.emplace_back(all.size(), term->scales_with_beta());
  }
  std::vector<Eigen::Triplet<double>> part(all.size());
  for (const bool scaled : {false, true}) {
    size_t k = 0;
    for (const auto& [end, term_scaled] : term_ends)
      for (; k < end; ++k)
        part[k] = Eigen::Triplet<double>(all[k].row(), all[k].col(),
                                         term_scaled == scaled ? all[k].value() : 0.0);
    Eigen::SparseMatrix<double>& A = scaled ? *A_beta : *A_fixed;
    A.resize(n, n);
    A.setFromTriplets(part.begin(), part.end());
  }
}

void assemble_quadratic_part(const UnfoldProblem& problem, LocalGlobalData* data) {
  data->problem = &problem;
  assemble(problem, &data->A_fixed, &data->A_beta);
  data->A = data->A_fixed;
  data->A.makeCompressed();
  data->rhs.resize(problem.num_vertices(), 3);
  data->beta = 0;
}

}  // namespace

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
  for (const auto& term : problem.terms)
    if (!term->quadratic())
      throw UsageError("the " + term->name() +
                       " term is not quadratic: the local_global method cannot minimise it "
                       "(use method: ceres)");
  data->cg = CgOptions{options.cg_tolerance, options.cg_forcing, options.cg_max_iterations};
  assemble_quadratic_part(problem, data);
  data->iterative = use_iterative_solver(options, data->A);
  if (!data->iterative) {
    data->ldlt.analyze(data->A);
  } else {
    if (!amg) {
      auto own = std::make_shared<AmgData>();
      amg_precomputation(data->A_beta, AmgOptions{}, own.get());
      amg = std::move(own);
    }
    data->amg = std::move(amg);
  }
}

bool quadratic_part_bounded(const UnfoldProblem& problem, double beta) {
  LocalGlobalData data;
  assemble_quadratic_part(problem, &data);
  data.ldlt.analyze(data.A);
  local_global_set_beta(beta, &data);
  return energy_bounded(data);
}

void local_global_set_beta(double beta, LocalGlobalData* data) {
  // A_fixed, A_beta and A share one pattern (assemble keeps explicit zeros):
  // only the values change.
  const auto values = [](Eigen::SparseMatrix<double>& M) {
    return Eigen::Map<Eigen::VectorXd>(M.valuePtr(), M.nonZeros());
  };
  values(data->A) = values(data->A_fixed) + beta * values(data->A_beta);
  data->beta = beta;
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
}

void global_step(const LocalGlobalData& data, const Rotations& R, Eigen::MatrixX3d* Q) {
  data.rhs.setZero();
  for (const auto& term : data.problem->terms)
    term->add_linear(R, term->weight(data.beta), &data.rhs);
  if (data.iterative) {
    data.rhs_rows = data.rhs;
    data.x_rows = *Q;
    const CgResult r = projected_cg(CsrView::of_symmetric(data.A), *data.amg, data.rhs_rows,
                                    &data.x_rows, data.cg, &data.cg_workspace);
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
  // Every B_t sums to zero, so Q has zero mean up to roundoff; remove that too.
  Q->rowwise() -= Q->colwise().mean();
}

double energy_after_global_step(const LocalGlobalData& data, const Rotations& R,
                                const Eigen::MatrixX3d& Q) {
  double energy = 0;
  for (const auto& term : data.problem->terms)
    energy += term->weight(data.beta) * term->constant(R);
  energy -= (Q.array() * data.rhs.array()).sum();
  if (data.iterative) {
    const RowMatrixX3d& r = data.cg_workspace.r;
    for (Eigen::Index i = 0; i < Q.rows(); ++i) energy -= Q.row(i).dot(r.row(i));
  }
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
    return total_energy(problem, *Q, R_, data_.beta);
  };
  if (accelerate) level = fit_and_measure();
  const auto in_band = [&](double delta) {
    return delta >= options.edge_ratio_band[0] && delta <= options.edge_ratio_band[1];
  };
  for (int i = 1;; ++i) {
    if (!accelerate) fit_rotations(problem, *Q, data_.beta, &R_, &covariances_);
    const Eigen::MatrixX3d x = accelerate ? *Q : Eigen::MatrixX3d();
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
      const Eigen::MatrixX3d plain = *Q;
      *Q = anderson.next(x.reshaped(), plain.reshaped()).reshaped(Q->rows(), 3);
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
    VLOG(1) << "iteration " << iteration << " cascade " << cascade << " beta " << data_.beta
            << " energy " << energy << " edge ratio " << delta;
    if (options.break_in_band && in_band(delta)) return true;
    const bool converged = std::abs(energy / *previous_energy - 1.0) < options.epsilon;
    *previous_energy = energy;
    if (converged || i >= options.max_iterations) return in_band(delta);
  }
}

}  // namespace unfold
