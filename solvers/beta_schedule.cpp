#include "solvers/beta_schedule.h"

namespace unfold {

BetaStart starting_beta(const std::string& mode, double value, bool raise_to_bound, int n,
                        double lambda2, double spread_weight) {
  const double scale = n / lambda2;
  BetaStart beta;
  beta.requested = mode == "relative" ? value * scale : value;
  beta.start = beta.requested;
  if (raise_to_bound && beta.start <= beta_bound(n, lambda2, spread_weight)) {
    beta.start = spread_weight * (1.01 * scale - 1);
    beta.raised = true;
  }
  return beta;
}

}  // namespace unfold
