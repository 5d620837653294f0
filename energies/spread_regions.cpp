#include "energies/spread_regions.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "core/errors.h"
#include "metrics/graph_geodesics.h"

namespace unfold {

SpreadRegions spread_regions(const Eigen::MatrixX3d& V, const EdgeGraph& graph,
                             const SpreadRegionsOptions& options) {
  const int n = graph.num_vertices;
  if (V.rows() != n)
    throw UsageError("spread_regions: " + std::to_string(V.rows()) + " positions for " +
                     std::to_string(n) + " graph vertices");
  if (options.count < 1) throw UsageError("config key 'stretch.local_regions' must be at least 1");
  if (!(options.radius > 0) || !std::isfinite(options.radius))
    throw UsageError("config key 'stretch.local_radius' must be a finite number > 0");
  if (!(options.local >= 0 && options.local < 1))
    throw UsageError("config key 'stretch.local' must be a number in [0, 1)");
  if (n == 0) return {};
  const int count = std::min(options.count, n);
  const NeighborLengths lengths = neighbor_lengths(graph, V);
  // Farthest-point sampling: an unreached vertex is infinitely far, so every
  // part of a disconnected graph gets a landmark while there are some left.
  std::vector<std::vector<double>> distance(count);
  std::vector<double> nearest(n, std::numeric_limits<double>::infinity());
  graph_geodesics(graph, lengths, 0, &distance[0]);
  int source = int(std::max_element(distance[0].begin(), distance[0].end()) - distance[0].begin());
  double diameter = 0;
  for (int k = 0; k < count; ++k) {
    graph_geodesics(graph, lengths, source, &distance[k]);
    for (int i = 0; i < n; ++i) {
      const double d = distance[k][i];
      nearest[i] = std::min(nearest[i], d);
      if (std::isfinite(d)) diameter = std::max(diameter, d);
    }
    source = int(std::max_element(nearest.begin(), nearest.end()) - nearest.begin());
  }
  const double s2 = std::pow(options.radius * std::max(diameter, 1e-300), 2);
  SpreadRegions regions;
  regions.count = count;
  regions.local = options.local;
  regions.weights.reserve(4 * n);
  std::vector<double> w(count);
  for (int i = 0; i < n; ++i) {
    const double g0 = nearest[i];
    if (!std::isfinite(g0))
      throw UsageError("stretch.local: vertex " + std::to_string(i) +
                       " is reached by none of the " + std::to_string(count) +
                       " regions (more parts than stretch.local_regions)");
    // Relative to the nearest landmark's weight (1), so nothing underflows.
    double total = 0;
    for (int k = 0; k < count; ++k) {
      const double g = distance[k][i];
      w[k] = std::isfinite(g) ? std::exp(-0.5 * (g * g - g0 * g0) / s2) : 0.0;
      if (w[k] < 1e-4) w[k] = 0;
      total += w[k];
    }
    for (int k = 0; k < count; ++k)
      if (w[k] > 0) regions.weights.emplace_back(i, k, w[k] / total);
  }
  return regions;
}

}  // namespace unfold
