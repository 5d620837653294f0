// Cumulative distribution plots (the paper's Fig. 6): for each series, the
// fraction of values <= x, as a step curve, one colour per series, with a legend.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "render/image.h"

namespace unfold {

/// One curve: a name for the legend and its values (any order).
using CdfSeries = std::pair<std::string, std::vector<double>>;

/// The CDF plot of the series over x in [0, the largest value].
/// @throws UsageError for no series, a series without values, a non-finite
///         value or a size below 200 x 200 pixels
Image plot_cdf(const std::vector<CdfSeries>& series, const std::string& xlabel, int width = 640,
               int height = 440);

}  // namespace unfold
