#include "pipeline/compare_configs.h"

#include <glog/logging.h>

#include <cstdio>
#include <filesystem>
#include <iomanip>
#include <ostream>
#include <sstream>
#include <variant>

#include "core/atomic_file.h"
#include "core/errors.h"
#include "pipeline/unfold_surface.h"

namespace unfold {
std::map<std::string, std::string> fixed_beta_overrides(double relative_beta) {
  std::ostringstream beta;
  beta << std::setprecision(17) << relative_beta;
  // One cascade, no band, iterations until the energy stops changing.
  return {{"beta.mode", "relative"},
          {"beta.value", beta.str()},
          {"cascade.num", "1"},
          {"cascade.k_iter", "20000"},
          {"cascade.epsilon", "1e-9"},
          {"cascade.edge_ratio_band", "[0, 0]"},
          {"ceres.max_num_iterations", "20000"},
          {"ceres.function_tolerance", "1e-13"}};
}

std::vector<ComparisonRow> compare_options(const SurfaceMesh& surface,
                                           const std::vector<NamedOptions>& options) {
  if (options.empty()) throw UsageError("no configs to compare");
  const PreparedMesh prepared = prepare_mesh(surface, options.front().options);
  std::vector<ComparisonRow> rows;
  for (const auto& [name, config] : options) {
    LOG(INFO) << "config " << name;
    const UnfoldResult r = unfold_prepared(prepared, config);
    rows.push_back({name, r.cascade.final_energy, r.metrics.E_rig, r.metrics.E_str, r.metrics.E_geo,
                    r.cascade.iterations, r.seconds_unfold});
  }
  return rows;
}

std::vector<ComparisonRow> compare_configs(const SurfaceMesh& surface,
                                           const std::vector<std::string>& config_paths,
                                           std::optional<double> fixed_beta) {
  const auto overrides =
      fixed_beta ? fixed_beta_overrides(*fixed_beta) : std::map<std::string, std::string>{};
  std::vector<NamedOptions> options;
  for (const auto& path : config_paths)
    options.push_back({std::filesystem::path(path).stem().string(), load_options(path, overrides)});
  return compare_options(surface, options);
}

std::string format_comparison(const std::vector<ComparisonRow>& rows) {
  std::ostringstream out;
  char line[256];
  std::snprintf(line, sizeof line, "%-20s %16s %8s %8s %8s %10s %9s\n", "config", "final_energy",
                "E_rig", "E_str", "E_geo", "iterations", "seconds");
  out << line;
  for (const auto& r : rows) {
    std::snprintf(line, sizeof line, "%-20s %16.9g %8.4f %8.4f %8.4f %10d %9.3f\n",
                  r.config.c_str(), r.final_energy, r.E_rig, r.E_str, r.E_geo, r.iterations,
                  r.seconds);
    out << line;
  }
  return out.str();
}

JsonObject comparison_columns(const ComparisonRow& r) {
  return {{"config", r.config},  {"final_energy", r.final_energy},
          {"E_rig", r.E_rig},    {"E_str", r.E_str},
          {"E_geo", r.E_geo},    {"iterations", r.iterations},
          {"seconds", r.seconds}};
}

void write_comparison_csv(const std::string& path, const std::vector<ComparisonRow>& rows) {
  write_file_atomically(path, [&](std::ostream& out) {
    const JsonObject header = comparison_columns({});
    for (size_t k = 0; k < header.size(); ++k) out << (k ? "," : "") << header[k].first;
    out << '\n' << std::setprecision(12);
    for (const auto& r : rows) {
      const JsonObject columns = comparison_columns(r);
      for (size_t k = 0; k < columns.size(); ++k) {
        out << (k ? "," : "");
        // The columns are a string, then numbers (comparison_columns).
        const auto& cell = columns[k].second.value;
        if (const auto* text = std::get_if<std::string>(&cell))
          out << *text;
        else if (const auto* count = std::get_if<int64_t>(&cell))
          out << *count;
        else
          out << std::get<double>(cell);
      }
      out << '\n';
    }
  });
}

}  // namespace unfold
