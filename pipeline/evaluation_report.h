// Reports from batch runs (pipeline/batch_run.h): the per-class table of mean
// metrics like the paper's Table 1, retrieval (Table 3) and pose invariance
// tables in Markdown, CDF plots of E_rig, E_str, E_geo like Fig. 6, and
// precision-recall plots of retrieval.
#pragma once

#include <string>
#include <vector>

#include "pipeline/batch_run.h"

namespace unfold {

/// One batch output directory; a non-empty label is appended to its method
/// names ("default@full") so runs of one config at two resolutions stay apart.
struct ReportRun {
  std::string output_dir;
  std::string label;
};

/// The Markdown report: for each of E_rig, E_str, E_geo a table of means over
/// the ok rows (classes x methods, with a row over all shapes); for each of the
/// damage measure's damaged-edge percent, 99.9th percentile and largest
/// surface edge ratio, the inverted tets, and the fold measure's folded-edge
/// percent and 99.9th percentile of the bends' sharpening, a table of the mean
/// and the worst shape (rows without those columns left out); the failures,
/// the retrieval measures of retrieval.csv (a row per framework and measure, a
/// column per method, like the paper's Table 3) and pose_invariance.csv.
/// @throws InputError for a missing or malformed results.csv
std::string evaluation_report_markdown(const std::vector<ReportRun>& runs);

/// Writes cdf_E_rig.png, cdf_E_str.png, cdf_E_geo.png into dir: per method,
/// the distribution of the metric over the ok shapes.
/// @throws InputError as above, OutputError when writing fails
void write_cdf_plots(const std::vector<ReportRun>& runs, const std::string& dir);

/// Writes pr_<framework>.png into dir for each retrieval framework in the runs'
/// retrieval.csv: the precision-recall curve of each method.
/// @throws OutputError when writing fails
void write_precision_recall_plots(const std::vector<ReportRun>& runs, const std::string& dir);

}  // namespace unfold
