// Runs several configurations on one tet mesh and tabulates the results, so
// solvers and energy terms can be compared on equal terms.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "config/options.h"
#include "core/json.h"
#include "mesh/surface_mesh.h"

namespace unfold {

struct ComparisonRow {
  std::string config;  ///< the config file's stem
  double final_energy = 0;
  double E_rig = 0, E_str = 0, E_geo = 0;
  int iterations = 0;
  double seconds = 0;  ///< lambda_2, solve (not tetrahedralization, shared)
};

/// The row's columns in CSV order: the one list of column names, shared by the
/// CSV and the Python binding's rows.
JsonObject comparison_columns(const ComparisonRow& row);

/// Config overrides that run one beta (relative to n / lambda_2) to
/// convergence instead of the cascade: the fair way to compare final energies.
std::map<std::string, std::string> fixed_beta_overrides(double relative_beta);

/// Options with the name their row gets.
struct NamedOptions {
  std::string name;
  Options options;
};

/// Prepares the surface once (check, simplify, tetrahedralize with the first
/// options' settings) and unfolds it with each of the options.
/// @throws UsageError for no options; otherwise as unfold_surface
std::vector<ComparisonRow> compare_options(const SurfaceMesh& surface,
                                           const std::vector<NamedOptions>& options);

/// compare_options with config files, each row named by its file's stem.
/// @param fixed_beta if set, every config runs with fixed_beta_overrides(*fixed_beta)
/// @throws UsageError for a bad config or no configs; otherwise as unfold_surface
std::vector<ComparisonRow> compare_configs(const SurfaceMesh& surface,
                                           const std::vector<std::string>& config_paths,
                                           std::optional<double> fixed_beta);

/// The rows as an aligned text table.
std::string format_comparison(const std::vector<ComparisonRow>& rows);

/// Writes the comparison_columns of each row as CSV, with a header (atomically).
/// @throws OutputError
void write_comparison_csv(const std::string& path, const std::vector<ComparisonRow>& rows);

}  // namespace unfold
