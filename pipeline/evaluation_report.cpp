#include "pipeline/evaluation_report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "core/errors.h"
#include "metrics/retrieval_measures.h"
#include "render/plot_cdf.h"
#include "render/plot_precision_recall.h"
#include "render/write_png.h"

namespace unfold {
namespace {

std::vector<BatchRow> labelled_rows(const std::vector<ReportRun>& runs) {
  std::vector<BatchRow> rows;
  for (const auto& run : runs)
    for (BatchRow r : read_results_csv(run.output_dir + "/results.csv")) {
      if (!run.label.empty()) r.method += "@" + run.label;
      rows.push_back(r);
    }
  return rows;
}

// Methods in first-seen order.
std::vector<std::string> methods_of(const std::vector<BatchRow>& rows) {
  std::vector<std::string> methods;
  for (const auto& r : rows)
    if (std::find(methods.begin(), methods.end(), r.method) == methods.end())
      methods.push_back(r.method);
  return methods;
}

constexpr int kMetrics = 4;
double metric(const BatchRow& r, int k) {
  return k == 0 ? r.E_rig : k == 1 ? r.E_str : k == 2 ? r.E_geo : r.E_geo_surface;
}
// A row that has metric k: its run succeeded and computed it (metrics.compute).
bool has_metric(const BatchRow& r, int k) { return r.status == "ok" && !std::isnan(metric(r, k)); }
const char* kMetricNames[kMetrics] = {"E_rig", "E_str", "E_geo", "E_geo_surface"};

std::string number(double x, const char* format = "%.4f") {
  char text[32];
  std::snprintf(text, sizeof text, format, x);
  return text;
}

// A Markdown table's header: the leading column names, then one per method.
std::string table_header(const std::vector<std::string>& leading,
                         const std::vector<std::string>& methods) {
  std::string head = "|", rule = "|";
  for (const auto& name : leading) head += " " + name + " |", rule += "---|";
  for (const auto& m : methods) head += " " + m + " |", rule += "---|";
  return head + "\n" + rule + "\n";
}

// One line of retrieval.csv (pipeline/batch_run.h), the run label appended to
// the method.
struct RetrievalRow {
  std::string method, framework;
  std::vector<double> measures;   // nn, first_tier, second_tier, e_measure, dcg
  std::vector<double> precision;  // at recall 0.05, ..., 1
};
const char* kMeasureNames[5] = {"NN", "FT", "ST", "E", "DCG"};

std::vector<RetrievalRow> retrieval_rows(const std::vector<ReportRun>& runs) {
  std::vector<RetrievalRow> rows;
  for (const auto& run : runs) {
    std::ifstream in(run.output_dir + "/retrieval.csv");
    std::string line;
    if (!in || !std::getline(in, line) || line.rfind("method,framework,queries,", 0) != 0)
      continue;  // none, or from an older version
    while (std::getline(in, line)) {
      std::vector<std::string> f;
      std::istringstream s(line);
      for (std::string x; std::getline(s, x, ',');) f.push_back(x);
      if (f.size() != size_t(8 + kRecallLevels)) continue;
      RetrievalRow r{run.label.empty() ? f[0] : f[0] + "@" + run.label, f[1], {}, {}};
      for (size_t k = 3; k < f.size(); ++k)
        (k < 8 ? r.measures : r.precision).push_back(std::stod(f[k]));
      rows.push_back(r);
    }
  }
  return rows;
}

// Like the paper's Table 3: a row per framework and measure, a column per method.
std::string retrieval_table(const std::vector<ReportRun>& runs) {
  const std::vector<RetrievalRow> rows = retrieval_rows(runs);
  if (rows.empty()) return "(none)\n";
  std::vector<std::string> methods, frameworks;
  for (const auto& r : rows) {
    if (std::find(methods.begin(), methods.end(), r.method) == methods.end())
      methods.push_back(r.method);
    if (std::find(frameworks.begin(), frameworks.end(), r.framework) == frameworks.end())
      frameworks.push_back(r.framework);
  }
  std::ostringstream md;
  md << table_header({"framework", "measure"}, methods);
  for (const auto& f : frameworks)
    for (int k = 0; k < 5; ++k) {
      md << "| " << f << " | " << kMeasureNames[k] << " |";
      for (const auto& m : methods) {
        std::string cell = "-";
        for (const auto& r : rows)
          if (r.method == m && r.framework == f) cell = number(r.measures[size_t(k)], "%.3f");
        md << ' ' << cell << " |";
      }
      md << '\n';
    }
  return md.str();
}

// pose_invariance.csv of the runs pivoted: classes x methods; the mean
// distance, or (ratios) the mean and largest pair ratio to the raw poses.
std::string pose_table(const std::vector<ReportRun>& runs, bool ratios) {
  std::vector<std::string> methods;
  std::map<std::string, std::map<std::string, std::string>> cells;  // class -> method -> value
  for (const auto& run : runs) {
    std::ifstream in(run.output_dir + "/pose_invariance.csv");
    std::string line;
    std::getline(in, line);  // header
    while (std::getline(in, line)) {
      std::vector<std::string> f;
      std::istringstream s(line);
      for (std::string x; std::getline(s, x, ',');) f.push_back(x);
      if (f.size() < (ratios ? 5u : 3u)) continue;
      const std::string method = run.label.empty() ? f[1] : f[1] + "@" + run.label;
      if (ratios && f[1] == "raw") continue;
      if (std::find(methods.begin(), methods.end(), method) == methods.end())
        methods.push_back(method);
      std::string& cell = cells[f[0]][method];
      if (f[2].empty())  // the class has no correspondence (docs/evaluation.md)
        cell = "no correspondence";
      else if (ratios)
        cell = number(std::stod(f[3]), "%.3f") + " (max " + number(std::stod(f[4]), "%.3f") + ")";
      else
        cell = number(std::stod(f[2]));
    }
  }
  if (cells.empty()) return "(none)\n";
  std::ostringstream md;
  md << table_header({"class"}, methods);
  for (const auto& [c, values] : cells) {
    md << "| " << c << " |";
    for (const auto& m : methods) md << ' ' << (values.count(m) ? values.at(m) : "-") << " |";
    md << '\n';
  }
  return md.str();
}

// The damage measure of a row (metrics/surface_damage.h): 0 damaged-edge
// percent, 1 the 99.9th percentile of the surface edge ratio, 2 the largest,
// 3 inverted tets; the fold measure (metrics/surface_folds.h): 4 folded-edge
// percent, 5 the 99.9th percentile of the dihedral change; NaN for a failed
// run or a results.csv without the columns.
double damage(const BatchRow& r, int k) {
  if (r.status != "ok") return std::nan("");
  switch (k) {
    case 0:
      return r.damaged_edges_percent;
    case 1:
      return r.surface_edge_ratio_p999;
    case 2:
      return r.surface_edge_ratio_max;
    case 3:
      return r.inverted_tets;
    case 4:
      return r.folded_edges_percent;
    default:
      return r.dihedral_change_p999;
  }
}

// Issue 44's damage and fold tables: per class and method, the mean of measure k over
// the ok shapes that report it, and the worst shape (largest value) with its name.
std::string damage_tables(const std::vector<BatchRow>& rows,
                          const std::vector<std::string>& methods,
                          const std::set<std::string>& classes) {
  static const char* const kTitles[6] = {
      "Damaged surface edges (% with length ratio outside [1/3, 3] at the input's area)",
      "Surface edge ratio, 99.9th percentile (nearest rank)",
      "Largest surface edge ratio",
      "Inverted tets in the output",
      "Folded surface edges (% whose bend sharpened by more than 90 degrees)",
      "Sharpening of the bends, 99.9th percentile (degrees)"};
  static const char* const kFormats[6] = {"%.3f", "%.2f", "%.2f", "%.0f", "%.3f", "%.0f"};
  std::vector<std::string> row_classes(classes.begin(), classes.end());
  row_classes.push_back("all");
  std::ostringstream md;
  for (int k = 0; k < 6; ++k) {
    md << "### " << kTitles[k]
       << " per class: mean, worst shape (ok shapes that report it / all)\n\n"
       << table_header({"class"}, methods);
    for (const auto& c : row_classes) {
      md << "| " << c << " |";
      for (const auto& m : methods) {
        double sum = 0, worst = -1;
        std::string worst_shape;
        int ok = 0, all = 0;
        for (const auto& r : rows)
          if (r.method == m && (c == "all" || r.shape_class == c)) {
            ++all;
            const double x = damage(r, k);
            if (std::isnan(x)) continue;
            sum += x, ++ok;
            if (x > worst) worst = x, worst_shape = r.shape;
          }
        md << ' '
           << (ok > 0 ? number(sum / ok, kFormats[k]) + " (worst " + number(worst, kFormats[k]) +
                            " " + worst_shape + ")"
                      : "-")
           << " (" << ok << "/" << all << ") |";
      }
      md << '\n';
    }
    md << '\n';
  }
  return md.str();
}

}  // namespace

std::string evaluation_report_markdown(const std::vector<ReportRun>& runs) {
  const std::vector<BatchRow> rows = labelled_rows(runs);
  const std::vector<std::string> methods = methods_of(rows);
  std::set<std::string> classes;
  for (const auto& r : rows) classes.insert(r.shape_class);
  std::ostringstream md;
  for (int k = 0; k < kMetrics; ++k) {
    md << "### Mean " << kMetricNames[k] << " per class (ok shapes that computed it / all)\n\n"
       << table_header({"class"}, methods);
    std::vector<std::string> row_classes(classes.begin(), classes.end());
    row_classes.push_back("all");
    for (const auto& c : row_classes) {
      md << "| " << c << " |";
      for (const auto& m : methods) {
        double sum = 0;
        int ok = 0, all = 0;
        for (const auto& r : rows)
          if (r.method == m && (c == "all" || r.shape_class == c)) {
            ++all;
            if (has_metric(r, k)) sum += metric(r, k), ++ok;
          }
        md << ' ' << (ok > 0 ? number(sum / ok) : "-") << " (" << ok << "/" << all << ") |";
      }
      md << '\n';
    }
    md << '\n';
  }
  md << damage_tables(rows, methods, classes);
  md << "### Failures\n\n";
  int failures = 0;
  for (const auto& r : rows)
    if (r.status != "ok")
      md << "- " << r.shape << ", " << r.method << ": " << r.status << '\n', ++failures;
  if (failures == 0) md << "none\n";
  md << "\n### Retrieval: NN, first and second tier, E-measure (32), DCG (docs/evaluation.md)\n\n"
     << retrieval_table(runs);
  md << "\n### Pose invariance: mean aligned vertex distance / sqrt(area) between poses\n\n"
     << pose_table(runs, false);
  md << "\n### Pose invariance: canonical / raw distance of each pair of poses, mean (largest)\n\n"
     << pose_table(runs, true);
  md << "\n### Mean seconds per shape (solve and metrics)\n\n| method | seconds |\n|---|---|\n";
  for (const auto& m : methods) {
    double sum = 0;
    int n = 0;
    for (const auto& r : rows)
      if (r.method == m && r.status == "ok") sum += r.seconds, ++n;
    md << "| " << m << " | " << (n > 0 ? number(sum / n, "%.1f") : "-") << " |\n";
  }
  return md.str();
}

void write_cdf_plots(const std::vector<ReportRun>& runs, const std::string& dir) {
  const std::vector<BatchRow> rows = labelled_rows(runs);
  for (int k = 0; k < kMetrics; ++k) {
    std::vector<CdfSeries> series;
    for (const auto& m : methods_of(rows)) {
      std::vector<double> values;
      for (const auto& r : rows)
        if (r.method == m && has_metric(r, k)) values.push_back(metric(r, k));
      if (!values.empty()) series.push_back({m, values});
    }
    if (series.empty()) continue;
    write_png(dir + "/cdf_" + kMetricNames[k] + ".png", plot_cdf(series, kMetricNames[k]));
  }
}

void write_precision_recall_plots(const std::vector<ReportRun>& runs, const std::string& dir) {
  const std::vector<RetrievalRow> rows = retrieval_rows(runs);
  std::vector<std::string> frameworks;
  for (const auto& r : rows)
    if (std::find(frameworks.begin(), frameworks.end(), r.framework) == frameworks.end())
      frameworks.push_back(r.framework);
  for (const auto& f : frameworks) {
    std::vector<PrecisionRecallSeries> series;
    for (const auto& r : rows)
      if (r.framework == f) series.push_back({r.method, r.precision});
    write_png(dir + "/pr_" + f + ".png",
              plot_precision_recall(series, "precision (" + f + " retrieval)"));
  }
}

}  // namespace unfold
