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
  // The farthest vertex without a scan of all n per seed (O(n count): 27 ms a
  // call on a 52k surface): the largest distance of each block of kBlock
  // vertices, found again only in the blocks a seed's run changed.
  constexpr int kBlock = 256;
  const int num_blocks = (n + kBlock - 1) / kBlock;
  std::vector<int> block_farthest(static_cast<size_t>(num_blocks), 0);
  std::vector<char> changed(size_t(num_blocks), 1);
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
          changed[size_t(arc.neighbor / kBlock)] = 1;
          queue.emplace(candidate, arc.neighbor);
        }
      }
    }
    ++made;
    changed[size_t(seed / kBlock)] = 1;
    // The first vertex of largest distance, as std::max_element finds it.
    for (int b = 0; b < num_blocks; ++b) {
      if (!changed[size_t(b)]) continue;
      const auto first = nearest.begin() + b * kBlock;
      block_farthest[size_t(b)] =
          int(std::max_element(first, nearest.begin() + std::min(n, (b + 1) * kBlock)) -
              nearest.begin());
      changed[size_t(b)] = 0;
    }
    seed = block_farthest[0];
    for (int b = 1; b < num_blocks; ++b)
      if (nearest[size_t(block_farthest[size_t(b)])] > nearest[size_t(seed)])
        seed = block_farthest[size_t(b)];
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

DistanceClusters make_distance_clusters(const Eigen::MatrixX3d& V, const EdgeGraph& graph,
                                        int count) {
  DistanceClusters clusters;
  clusters.cell_of = distance_clusters(V, graph, count, &clusters.count);
  return clusters;
}

}  // namespace unfold
