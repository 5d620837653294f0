#include "mesh/edge_graph.h"

#include <algorithm>
#include <cstdint>
#include <numeric>

namespace unfold {

EdgeGraph build_edge_graph(int num_vertices, const Eigen::MatrixXi& elements) {
  const int k = int(elements.cols());
  std::vector<uint64_t> keys;
  keys.reserve(size_t(elements.rows()) * size_t(k * (k - 1) / 2));
  for (Eigen::Index e = 0; e < elements.rows(); ++e)
    for (int a = 0; a < k; ++a)
      for (int b = a + 1; b < k; ++b) {
        uint64_t i = uint64_t(elements(e, a)), j = uint64_t(elements(e, b));
        if (i == j) continue;
        if (i > j) std::swap(i, j);
        keys.push_back((i << 32) | j);
      }
  std::sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());

  EdgeGraph g;
  g.num_vertices = num_vertices;
  g.edges.resize(Eigen::Index(keys.size()), 2);
  g.offsets.assign(size_t(num_vertices) + 1, 0);
  for (size_t e = 0; e < keys.size(); ++e) {
    g.edges(Eigen::Index(e), 0) = int(keys[e] >> 32);
    g.edges(Eigen::Index(e), 1) = int(keys[e] & 0xffffffffu);
    ++g.offsets[size_t(g.edges(Eigen::Index(e), 0)) + 1];
    ++g.offsets[size_t(g.edges(Eigen::Index(e), 1)) + 1];
  }
  std::partial_sum(g.offsets.begin(), g.offsets.end(), g.offsets.begin());
  g.neighbors.resize(2 * keys.size());
  g.neighbor_edge.resize(2 * keys.size());
  std::vector<int> fill(g.offsets.begin(), g.offsets.end() - 1);
  // Edges are sorted by (i, j), so each vertex's list comes out ascending:
  // lower neighbours arrive (as j of earlier edges) before higher ones.
  for (int e = 0; e < g.num_edges(); ++e) {
    const int i = g.edges(e, 0), j = g.edges(e, 1);
    g.neighbors[size_t(fill[size_t(i)])] = j;
    g.neighbor_edge[size_t(fill[size_t(i)]++)] = e;
    g.neighbors[size_t(fill[size_t(j)])] = i;
    g.neighbor_edge[size_t(fill[size_t(j)]++)] = e;
  }
  return g;
}

Eigen::SparseMatrix<double> graph_laplacian(const EdgeGraph& g) {
  std::vector<Eigen::Triplet<double>> t;
  t.reserve(size_t(g.num_vertices) + 2 * size_t(g.num_edges()));
  for (int i = 0; i < g.num_vertices; ++i) t.emplace_back(i, i, double(g.degree(i)));
  for (int e = 0; e < g.num_edges(); ++e) {
    t.emplace_back(g.edges(e, 0), g.edges(e, 1), -1.0);
    t.emplace_back(g.edges(e, 1), g.edges(e, 0), -1.0);
  }
  Eigen::SparseMatrix<double> L(g.num_vertices, g.num_vertices);
  L.setFromTriplets(t.begin(), t.end());
  return L;
}

int connected_components(const EdgeGraph& g, std::vector<int>* labels) {
  std::vector<int> label(size_t(g.num_vertices), -1);
  std::vector<int> stack;
  int count = 0;
  for (int s = 0; s < g.num_vertices; ++s) {
    if (label[size_t(s)] >= 0) continue;
    label[size_t(s)] = count;
    stack.push_back(s);
    while (!stack.empty()) {
      const int v = stack.back();
      stack.pop_back();
      for (int k = g.offsets[size_t(v)]; k < g.offsets[size_t(v) + 1]; ++k) {
        const int w = g.neighbors[size_t(k)];
        if (label[size_t(w)] < 0) {
          label[size_t(w)] = count;
          stack.push_back(w);
        }
      }
    }
    ++count;
  }
  if (labels) *labels = std::move(label);
  return count;
}

}  // namespace unfold
