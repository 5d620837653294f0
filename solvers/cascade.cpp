#include "solvers/cascade.h"

#include <glog/logging.h>

#include <cmath>
#include <sstream>

#include "core/errors.h"
#include "energies/unfold_energy.h"
#include "metrics/edge_ratio.h"
#include "solvers/local_global.h"

namespace unfold {
namespace {

void factorize(double beta, LocalGlobalData* data, CascadeResult* result) {
  local_global_set_beta(beta, data);
  if (!energy_bounded(*data)) {
    result->bounded = false;
    LOG(WARNING) << "beta = " << beta << " is below the bound n/lambda_2 - 1: the energy is "
                 << "unbounded and the solve will overstretch (" << data->negative_pivots
                 << " negative directions)";
  }
}

}  // namespace

CascadeResult run_cascade(const EdgeGraph& graph, const Eigen::MatrixX3d& rest,
                          const CascadeOptions& options) {
  const Eigen::MatrixX3d& P = rest;
  CascadeResult result;
  LocalGlobalData data;
  local_global_precomputation(graph, P, &data);
  double beta = options.beta;
  factorize(beta, &data, &result);

  Eigen::MatrixX3d Q = P;
  Rotations R(size_t(graph.num_vertices), Eigen::Matrix3d::Identity());
  double f_s = unfold_energy(graph, P, Q, R, beta);
  int i = 1, j = 1;
  int total = 0;
  while (true) {
    best_rotations(graph, P, Q, &R);
    global_step(data, R, &Q);
    ++total;
    if (!Q.allFinite()) {
      std::ostringstream what;
      what << "non-finite positions at iteration " << total << " (cascade " << j
           << ", beta = " << beta << ")";
      throw NumericalError(what.str());
    }
    const double delta = edge_ratio(graph, P, Q);
    const double f_e = unfold_energy(graph, P, Q, R, beta);
    result.history.push_back({total, j, beta, f_e, delta});
    VLOG(1) << "iteration " << total << " cascade " << j << " beta " << beta << " energy " << f_e
            << " edge ratio " << delta;
    if (delta >= options.edge_ratio_band[0] && delta <= options.edge_ratio_band[1]) {
      result.reached_band = true;
      break;
    }
    if (std::abs(f_e / f_s - 1.0) < options.epsilon || i >= options.k_iter) {
      LOG(INFO) << "cascade " << j << ": beta " << beta << ", " << i << " iterations, energy "
                << f_e << ", edge ratio " << delta;
      ++j;
      if (j > options.num_cascades) break;
      beta *= options.growth;
      factorize(beta, &data, &result);
      i = 0;
    }
    ++i;
    f_s = f_e;
  }
  if (result.reached_band)
    LOG(INFO) << "cascade " << j << ": beta " << beta << ", " << i << " iterations, edge ratio "
              << result.history.back().edge_ratio << " in band";
  result.positions = Q;
  result.iterations = total;
  result.cascades = std::min(j, options.num_cascades);
  result.final_beta = beta;
  result.edge_ratio = result.history.back().edge_ratio;
  return result;
}

}  // namespace unfold
