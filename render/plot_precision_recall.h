// Precision-recall plots (the shape benchmarks' PR curves): precision against
// recall in [0, 1], one polyline per series, one colour per series (as the CDF
// plots), with a legend.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "render/image.h"

namespace unfold {

/// One curve: a name for the legend and its precision at recall (k + 1) / n,
/// k < n (metrics/retrieval_measures.h).
using PrecisionRecallSeries = std::pair<std::string, std::vector<double>>;

/// The plot, titled `title`.
/// @throws UsageError for no series, a series of fewer than 2 values, a value outside
///         [0, 1] or a size below 200 x 200 pixels
Image plot_precision_recall(const std::vector<PrecisionRecallSeries>& series,
                            const std::string& title, int width = 640, int height = 440);

}  // namespace unfold
