// The metrics JSON of one run: quality metrics, counts, timings, the
// tetrahedralization report, the effective options and the iteration history.
#pragma once

#include <string>

#include "config/options.h"
#include "core/json.h"
#include "pipeline/unfold_surface.h"

namespace unfold {

/// The metrics of result as a document: the one list of metric keys, shared by
/// the JSON file and the Python binding's metrics dictionary.
Json metrics_document(const UnfoldResult& result, const Options& options);

/// Writes metrics_document(result, options) to path as JSON (atomically).
/// @throws OutputError if the file cannot be written
void write_metrics_json(const std::string& path, const UnfoldResult& result,
                        const Options& options);

}  // namespace unfold
