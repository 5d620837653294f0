#include "solvers/beta_schedule.h"

namespace unfold {

BetaStart starting_beta(const std::string& mode, double value, bool raise_to_bound, int n,
                        double lambda2) {
  const double bound = n / lambda2;
  BetaStart beta;
  beta.requested = mode == "relative" ? value * bound : value;
  beta.start = beta.requested;
  if (raise_to_bound && beta.start <= bound - 1) {
    beta.start = 1.01 * bound - 1;
    beta.raised = true;
  }
  return beta;
}

}  // namespace unfold
