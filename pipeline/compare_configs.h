// Runs several configurations on one tet mesh and tabulates the results, so
// solvers and energy terms can be compared on equal terms.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "mesh/surface_mesh.h"

namespace unfold {

struct ComparisonRow {
  std::string config;  ///< the config file's stem
  double final_energy = 0;
  double E_rig = 0, E_str = 0, E_geo = 0;
  int iterations = 0;
  double seconds = 0;  ///< lambda_2, solve (not tetrahedralization, shared)
};

/// Config overrides that run one beta (relative to n / lambda_2) to
/// convergence instead of the cascade: the fair way to compare final energies.
std::map<std::string, std::string> fixed_beta_overrides(double relative_beta);

/// Prepares the surface once (check, simplify, tetrahedralize with the first
/// config's settings) and unfolds it with each config.
/// @param fixed_beta if set, every config runs with fixed_beta_overrides(*fixed_beta)
/// @throws UsageError for a bad config or no configs; otherwise as unfold_surface
std::vector<ComparisonRow> compare_configs(const SurfaceMesh& surface,
                                           const std::vector<std::string>& config_paths,
                                           std::optional<double> fixed_beta);

/// The rows as an aligned text table.
std::string format_comparison(const std::vector<ComparisonRow>& rows);

/// Writes config,final_energy,E_rig,E_str,E_geo,iterations,seconds (atomically).
/// @throws OutputError
void write_comparison_csv(const std::string& path, const std::vector<ComparisonRow>& rows);

}  // namespace unfold
