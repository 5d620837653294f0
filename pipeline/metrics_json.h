// The metrics JSON of one run: quality metrics, counts, timings, the
// tetrahedralization report, the effective options and the iteration history.
#pragma once

#include <string>

#include "config/options.h"
#include "pipeline/unfold_surface.h"

namespace unfold {

/// Writes the metrics of result to path as JSON (atomically).
/// @throws OutputError if the file cannot be written
void write_metrics_json(const std::string& path, const UnfoldResult& result,
                        const Options& options);

}  // namespace unfold
