// The betas of the cascades: the first from the options and the boundedness
// bound, each next one growth times the last (run_cascade). The energy is
// bounded iff (beta + 1) lambda_2 > n (docs/method.md), so n / lambda_2 sets
// the scale of beta.
#pragma once

#include <string>

namespace unfold {

struct BetaStart {
  double requested = 0;  ///< from beta.mode and beta.value
  double start = 0;      ///< the first cascade's beta: requested, or raised above the bound
  bool raised = false;   ///< requested was at or below n / lambda_2 - 1 and was raised
};

/// The first cascade's beta.
/// @param mode           relative (value times n / lambda_2) or absolute (value)
/// @param raise_to_bound raise a start at or below the bound n / lambda_2 - 1 to
///                       1.01 n / lambda_2 - 1 (1% room for the error in lambda_2)
/// @param lambda2        the Fiedler value of the problem's beta_laplacian, > 0
BetaStart starting_beta(const std::string& mode, double value, bool raise_to_bound, int n,
                        double lambda2);

}  // namespace unfold
