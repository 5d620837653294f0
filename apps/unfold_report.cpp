// unfold_report: Markdown tables (per-class means like the paper's Table 1,
// retrieval, pose invariance) and CDF plots (Fig. 6) from unfold_batch runs.
//   unfold_report --runs O1,O2 [--labels a,b] --markdown report.md [--plots_dir DIR]
#include <cstdio>
#include <sstream>

#include "apps/app_main.h"
#include "core/atomic_file.h"
#include "pipeline/evaluation_report.h"

DEFINE_string(runs, "", "comma-separated unfold_batch output directories (required)");
DEFINE_string(labels, "", "comma-separated labels, one per run, appended to method names");
DEFINE_string(markdown, "", "write the report here; empty: print it");
DEFINE_string(
    plots_dir, "",
    "write cdf_E_rig.png, cdf_E_str.png, cdf_E_geo.png, pr_icp.png, pr_ort.png, pr_cmbof.png here");

namespace {
std::vector<std::string> split(const std::string& text) {
  std::vector<std::string> items;
  std::istringstream list(text);
  for (std::string item; std::getline(list, item, ',');) items.push_back(item);
  return items;
}
}  // namespace

int main(int argc, char** argv) {
  unfold::app::AppHelp help;
  help.usage = "unfold_report --runs O1,O2 [--labels a,b] [--markdown report.md] [--plots_dir DIR]";
  help.summary =
      "Markdown tables (per-class means, retrieval, pose invariance) and CDF plots from "
      "unfold_batch runs.";
  help.groups = {
      {"Input and output", {"runs", "labels", "markdown"}},
      {"Metrics and pictures", {"plots_dir"}},
  };
  return unfold::app::run_main("unfold_report", help, argc, argv, [] {
    const std::vector<std::string> dirs = split(FLAGS_runs), labels = split(FLAGS_labels);
    if (dirs.empty()) throw unfold::UsageError("--runs is required");
    if (!labels.empty() && labels.size() != dirs.size())
      throw unfold::UsageError("--labels needs one label per run");
    std::vector<unfold::ReportRun> runs;
    for (size_t k = 0; k < dirs.size(); ++k)
      runs.push_back({dirs[k], labels.empty() ? "" : labels[k]});
    const std::string md = unfold::evaluation_report_markdown(runs);
    if (FLAGS_markdown.empty())
      std::fputs(md.c_str(), stdout);
    else
      unfold::write_file_atomically(FLAGS_markdown, [&](std::ostream& s) { s << md; });
    if (!FLAGS_plots_dir.empty()) {
      unfold::write_cdf_plots(runs, FLAGS_plots_dir);
      unfold::write_precision_recall_plots(runs, FLAGS_plots_dir);
    }
    return 0;
  });
}
