// Runs of one tet mesh at several starting betas (the paper's Fig. 4), so a
// user can pick beta by eye.
#pragma once

#include <string>
#include <vector>

#include "config/options.h"
#include "pipeline/unfold_surface.h"

namespace unfold {

/// Parses a comma-separated list of positive numbers ("0.5,1,2,4").
/// @throws UsageError naming the bad entry for an empty list, a non-number or a value <= 0
std::vector<double> parse_beta_list(const std::string& text);

/// Unfolds `base`'s tet mesh once per beta, beta relative to n / lambda_2
/// (beta.mode = relative whatever options say); everything else as in options.
/// @param base   a result of unfold_surface (its surface and tets are reused)
/// @param betas  positive factors of n / lambda_2
/// @throws as unfold_prepared; UsageError for an empty list, a factor <= 0 or
///         a surface of several connected components
std::vector<UnfoldResult> unfold_beta_sweep(const UnfoldResult& base, const Options& options,
                                            const std::vector<double>& betas);

}  // namespace unfold
