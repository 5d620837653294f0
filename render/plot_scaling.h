// The scaling plot of docs/performance.md: time and peak memory against the
// number of tet vertices, with a dashed line through the origin and the
// largest point of each series, so linear growth reads as points on it.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "render/image.h"

namespace unfold {

/// One timed quantity: its legend name and one value per size.
using ScalingSeries = std::pair<std::string, std::vector<double>>;

/// Two panels: seconds (every series) and peak memory in MB, against n.
/// @param n sizes (tet vertices), ascending, positive
/// @throws UsageError for fewer than two sizes, series of another length,
///         non-finite or negative values, or fewer than 400 x 240 pixels
Image plot_scaling(const std::vector<double>& n, const std::vector<ScalingSeries>& seconds,
                   const std::vector<double>& peak_mb, int width = 900, int height = 420);

}  // namespace unfold
