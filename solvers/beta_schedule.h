// The betas of the cascades: the first from the options and the boundedness
// bound, each next one growth times the last (run_cascade). With the squared
// spread at weight k (stretch.weight) the energy is bounded iff (beta + k)
// lambda_2 > k n (docs/method.md): n / lambda_2 sets the scale of beta, and the
// bound is k (n / lambda_2 - 1).
#pragma once

#include <string>

namespace unfold {

struct BetaStart {
  double requested = 0;  ///< from beta.mode and beta.value
  double start = 0;      ///< the first cascade's beta: requested, or raised above the bound
  bool raised = false;   ///< requested was at or below the bound and was raised
};

/// The first cascade's beta.
/// @param mode           relative (value times n / lambda_2) or absolute (value)
/// @param raise_to_bound raise a start at or below the bound k (n / lambda_2 - 1)
///                       to k (1.01 n / lambda_2 - 1) (1% room for the error in lambda_2)
/// @param lambda2        the Fiedler value of the problem's beta_laplacian, > 0
/// @param spread_weight  k, the squared spread's weight (stretch.weight)
BetaStart starting_beta(const std::string& mode, double value, bool raise_to_bound, int n,
                        double lambda2, double spread_weight = 1.0);

/// The bound k (n / lambda_2 - 1) below which the energy is unbounded.
inline double beta_bound(int n, double lambda2, double spread_weight = 1.0) {
  return spread_weight * (n / lambda2 - 1);
}

}  // namespace unfold
