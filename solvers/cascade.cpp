#include "solvers/cascade.h"

#include <glog/logging.h>

#include <iomanip>
#include <sstream>

#include "core/errors.h"
#include "core/progress.h"
#include "metrics/edge_ratio.h"
#include "solvers/unfold_problem.h"

namespace unfold {

CascadeResult run_cascade(const UnfoldProblem& problem, CascadeBackend& backend,
                          const CascadeOptions& options, const Eigen::MatrixX3d* start) {
  CascadeResult result;
  Eigen::MatrixX3d Q = start ? *start : problem.rest;
  if (Q.rows() != problem.num_vertices())
    throw UsageError("run_cascade: the start needs one row per vertex");
  double beta = options.beta;
  // At the rest positions the identities are the best rotations.
  Rotations R(size_t(problem.num_vertices()), Eigen::Matrix3d::Identity());
  if (start) fit_rotations(problem, Q, beta, &R);
  double energy = total_energy(problem, Q, R, beta);  // f_s of Algorithm 1
  const StageOptions stage{options.k_iter, options.epsilon, options.edge_ratio_band,
                           options.break_in_band, options.anderson};
  for (int cascade = 1; cascade <= options.num_cascades; ++cascade) {
    if (cascade > 1) beta *= options.growth;
    std::ostringstream name;
    name << std::setprecision(3) << "cascade " << cascade << "/" << options.num_cascades
         << ", beta " << beta << ", " << problem.num_vertices() << " vertices";
    report_stage(name.str());
    backend.set_beta(beta);
    const size_t before = result.history.size();
    result.reached_band = backend.run_stage(stage, cascade, &Q, &energy, &result.history);
    // After the stage: an iterative backend learns it from its solves.
    if (!backend.bounded()) {
      result.bounded = false;
      LOG(WARNING) << "beta = " << beta << " is below the boundedness bound: the energy is "
                   << "unbounded and the solve overstretches";
    }
    result.cascades = cascade;
    if (result.history.size() > before)
      LOG(INFO) << std::setprecision(3) << "cascade " << cascade << "/" << options.num_cascades
                << ": beta " << beta << ", " << result.history.size() - before
                << " iterations, energy " << result.history.back().energy << ", edge ratio "
                << result.history.back().edge_ratio << (result.reached_band ? " in band" : "");
    if (result.reached_band) break;
  }
  result.final_beta = beta;
  result.iterations = int(result.history.size());
  R.clear();  // a fresh fit, not one refined from the start's rotations
  fit_rotations(problem, Q, beta, &R);
  result.final_energy = total_energy(problem, Q, R, beta);
  result.edge_ratio = edge_ratio(*problem.graph, problem.rest, Q);
  result.positions = std::move(Q);
  return result;
}

}  // namespace unfold
