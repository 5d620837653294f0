#include "mesh/permute_edge_graph.h"

#include <algorithm>
#include <numeric>
#include <string>
#include <utility>

#include "core/errors.h"

namespace unfold {

EdgeGraph permute_edge_graph(const EdgeGraph& g, const std::vector<int>& order,
                             std::vector<int>* edge_order) {
  const int n = g.num_vertices;
  std::vector<int> new_of(size_t(n), -1);
  bool ok = order.size() == size_t(n);
  for (size_t a = 0; ok && a < order.size(); ++a) {
    ok = order[a] >= 0 && order[a] < n && new_of[size_t(order[a])] < 0;
    if (ok) new_of[size_t(order[a])] = int(a);
  }
  if (!ok)
    throw UsageError("permute_edge_graph: order must be a permutation of the " + std::to_string(n) +
                     " vertices");
  // The new edges (i < j) filed under i by a counting sort, then each vertex's
  // few ordered by j: sorted as build_edge_graph sorts them.
  const int m = g.num_edges();
  const auto low = [&](int e) {
    return std::min(new_of[size_t(g.edges(e, 0))], new_of[size_t(g.edges(e, 1))]);
  };
  const auto high = [&](int e) {
    return std::max(new_of[size_t(g.edges(e, 0))], new_of[size_t(g.edges(e, 1))]);
  };
  std::vector<int> start(size_t(n) + 1, 0);
  for (int e = 0; e < m; ++e) ++start[size_t(low(e)) + 1];
  std::partial_sum(start.begin(), start.end(), start.begin());
  std::vector<int> old_edge(static_cast<size_t>(m));
  std::vector<int> fill(start.begin(), start.end() - 1);
  for (int e = 0; e < m; ++e) old_edge[size_t(fill[size_t(low(e))]++)] = e;
  for (int i = 0; i < n; ++i)
    std::sort(old_edge.begin() + start[size_t(i)], old_edge.begin() + start[size_t(i) + 1],
              [&](int a, int b) { return high(a) < high(b); });

  Eigen::MatrixX2i edges(m, 2);
  for (int e = 0; e < m; ++e) {
    edges(e, 0) = low(old_edge[size_t(e)]);
    edges(e, 1) = high(old_edge[size_t(e)]);
  }
  if (edge_order) *edge_order = std::move(old_edge);
  return edge_graph_from_sorted_edges(n, std::move(edges));
}

}  // namespace unfold
