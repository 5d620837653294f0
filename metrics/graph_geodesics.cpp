#include "metrics/graph_geodesics.h"

#include <functional>
#include <limits>
#include <queue>
#include <string>
#include <utility>

#include "core/errors.h"

namespace unfold {

std::vector<double> graph_geodesics(const EdgeGraph& graph, const Eigen::MatrixX3d& P, int source) {
  if (P.rows() != graph.num_vertices)
    throw UsageError("graph_geodesics: P needs one row per graph vertex");
  if (source < 0 || source >= graph.num_vertices)
    throw UsageError("graph_geodesics: source " + std::to_string(source) + " out of range");
  std::vector<double> dist(size_t(graph.num_vertices), std::numeric_limits<double>::infinity());
  using Entry = std::pair<double, int>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
  dist[size_t(source)] = 0;
  queue.emplace(0.0, source);
  while (!queue.empty()) {
    const auto [d, i] = queue.top();
    queue.pop();
    if (d > dist[size_t(i)]) continue;  // stale entry: i was reached more cheaply
    for (int k = graph.offsets[size_t(i)]; k < graph.offsets[size_t(i) + 1]; ++k) {
      const int j = graph.neighbors[size_t(k)];
      const double candidate = d + (P.row(i) - P.row(j)).norm();
      if (candidate < dist[size_t(j)]) {
        dist[size_t(j)] = candidate;
        queue.emplace(candidate, j);
      }
    }
  }
  return dist;
}

}  // namespace unfold
