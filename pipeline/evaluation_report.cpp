#include "pipeline/evaluation_report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "core/errors.h"
#include "render/plot_cdf.h"
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

double metric(const BatchRow& r, int k) { return k == 0 ? r.E_rig : k == 1 ? r.E_str : r.E_geo; }
// A row that has metric k: its run succeeded and computed it (metrics.compute).
bool has_metric(const BatchRow& r, int k) { return r.status == "ok" && !std::isnan(metric(r, k)); }
const char* kMetricNames[3] = {"E_rig", "E_str", "E_geo"};

std::string number(double x, const char* format = "%.4f") {
  char text[32];
  std::snprintf(text, sizeof text, format, x);
  return text;
}

// A CSV file of the runs (retrieval.csv) as one Markdown table, the run label
// appended to the method column (the last but one).
std::string csv_table(const std::vector<ReportRun>& runs, const std::string& file) {
  std::ostringstream md;
  bool header = false;
  for (const auto& run : runs) {
    std::ifstream in(run.output_dir + "/" + file);
    std::string line;
    if (!in || !std::getline(in, line)) continue;
    std::vector<std::string> names;
    std::istringstream h(line);
    for (std::string f; std::getline(h, f, ',');) names.push_back(f);
    if (!header) {
      md << '|';
      for (const auto& n : names) md << ' ' << n << " |";
      md << "\n|";
      for (size_t k = 0; k < names.size(); ++k) md << "---|";
      md << '\n';
      header = true;
    }
    while (std::getline(in, line)) {
      std::vector<std::string> f;
      std::istringstream s(line);
      for (std::string x; std::getline(s, x, ',');) f.push_back(x);
      if (f.size() != names.size()) continue;
      if (!run.label.empty() && f.size() >= 2) f[f.size() - 2] += "@" + run.label;
      f.back() = number(std::stod(f.back()));
      md << '|';
      for (const auto& x : f) md << ' ' << x << " |";
      md << '\n';
    }
  }
  return header ? md.str() : "(none)\n";
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
  md << "| class |";
  for (const auto& m : methods) md << ' ' << m << " |";
  md << "\n|---|";
  for (size_t k = 0; k < methods.size(); ++k) md << "---|";
  md << '\n';
  for (const auto& [c, values] : cells) {
    md << "| " << c << " |";
    for (const auto& m : methods) md << ' ' << (values.count(m) ? values.at(m) : "-") << " |";
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
  for (int k = 0; k < 3; ++k) {
    md << "### Mean " << kMetricNames[k]
       << " per class (ok shapes that computed it / all)\n\n| class |";
    for (const auto& m : methods) md << ' ' << m << " |";
    md << "\n|---|";
    for (size_t i = 0; i < methods.size(); ++i) md << "---|";
    md << '\n';
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
  md << "### Failures\n\n";
  int failures = 0;
  for (const auto& r : rows)
    if (r.status != "ok")
      md << "- " << r.shape << ", " << r.method << ": " << r.status << '\n', ++failures;
  if (failures == 0) md << "none\n";
  md << "\n### Retrieval: nearest-neighbour accuracy\n\n" << csv_table(runs, "retrieval.csv");
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
  for (int k = 0; k < 3; ++k) {
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

}  // namespace unfold
