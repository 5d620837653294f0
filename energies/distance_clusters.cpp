#include "energies/distance_clusters.h"

#include <algorithm>
#include <functional>
#include <limits>
#include <queue>
#include <string>
#include <utility>

#include "core/errors.h"
#include "metrics/graph_geodesics.h"

namespace unfold {

std::vector<int> distance_clusters(const Eigen::MatrixX3d& V, const EdgeGraph& graph, int count,
                                   int* cells) {
  const int n = graph.num_vertices;
  if (V.rows() != n)
    throw UsageError("distance_clusters: " + std::to_string(V.rows()) + " positions for " +
                     std::to_string(n) + " graph vertices");
  if (count < 1) throw UsageError("config key 'stretch.distance_clusters' must be at least 1");
  const NeighborLengths lengths = neighbor_lengths(graph, V);
  std::vector<double> nearest(size_t(n), std::numeric_limits<double>::infinity());
  std::vector<int> cell(size_t(n), -1);
  using Entry = std::pair<double, int>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> queue;
  int made = 0, seed = 0;
  while (made < count && n > 0) {
    // Dijkstra from the new seed, pruned where an earlier seed is nearer: each
    // run visits only the vertices it takes over and their rim.
    nearest[size_t(seed)] = 0;
    cell[size_t(seed)] = made;
    queue.emplace(0.0, seed);
    while (!queue.empty()) {
      const auto [d, v] = queue.top();
      queue.pop();
      if (d > nearest[size_t(v)]) continue;
      for (int k = graph.offsets[size_t(v)]; k < graph.offsets[size_t(v) + 1]; ++k) {
        const NeighborArc& arc = lengths.arcs[size_t(k)];
        const double candidate = d + arc.length;
        if (candidate < nearest[size_t(arc.neighbor)]) {
          nearest[size_t(arc.neighbor)] = candidate;
          cell[size_t(arc.neighbor)] = made;
          queue.emplace(candidate, arc.neighbor);
        }
      }
    }
    ++made;
    seed = int(std::max_element(nearest.begin(), nearest.end()) - nearest.begin());
    if (!(nearest[size_t(seed)] > 0)) break;  // every vertex is a seed
  }
  for (int i = 0; i < n; ++i)
    if (cell[size_t(i)] < 0)
      throw InputError("stretch.distance: vertex " + std::to_string(i) +
                       " is in no cluster: the mesh has more connected parts than the " +
                       std::to_string(count) + " of stretch.distance_clusters");
  *cells = made;
  return cell;
}

}  // namespace unfold
