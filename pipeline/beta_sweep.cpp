#include "pipeline/beta_sweep.h"

#include <cmath>
#include <sstream>

#include "core/errors.h"
#include "mesh/edge_graph.h"

namespace unfold {

std::vector<double> parse_beta_list(const std::string& text) {
  std::vector<double> betas;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) {
    size_t used = 0;
    double value = 0;
    try {
      value = std::stod(item, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == 0 || item.find_first_not_of(" \t", used) != std::string::npos ||
        !std::isfinite(value) || value <= 0)
      throw UsageError("beta sweep: '" + item + "' in '" + text +
                       "' is not a positive number (expected e.g. 0.5,1,2,4)");
    betas.push_back(value);
  }
  if (betas.empty()) throw UsageError("beta sweep: empty list (expected e.g. 0.5,1,2,4)");
  return betas;
}

std::vector<UnfoldResult> unfold_beta_sweep(const UnfoldResult& base, const Options& options,
                                            const std::vector<double>& betas) {
  if (betas.empty()) throw UsageError("beta sweep: empty list of betas");
  // Components unfolded separately share no beta scale (n / lambda_2 is per
  // component) and their merged tet mesh is no single problem to solve.
  const int components = connected_components(build_edge_graph(
      int(base.surface.V.rows()), Eigen::MatrixXi(triangulate_faces(base.surface))));
  if (components > 1)
    throw UsageError("beta sweep: the surface has " + std::to_string(components) +
                     " connected components (components: separately); a sweep needs one");
  PreparedMesh prepared;
  prepared.surface = base.surface;
  prepared.tets = base.tets;
  prepared.tet_report = base.tet_report;
  std::vector<UnfoldResult> results;
  for (double beta : betas) {
    if (!(beta > 0)) throw UsageError("beta sweep: beta " + std::to_string(beta) + " is not > 0");
    Options run = options;
    run.beta_mode = "relative";
    run.beta_value = beta;
    results.push_back(unfold_prepared(prepared, run));
  }
  return results;
}

}  // namespace unfold
