#include "mesh/edge_graph.h"

#include <algorithm>
#include <numeric>
#include <utility>

#include "core/parallel.h"

namespace unfold {

EdgeGraph build_edge_graph(int num_vertices, const Eigen::MatrixXi& elements) {
  // Each element pair (i < j) is filed under i (a counting sort), then each
  // vertex's few higher neighbours are sorted and deduplicated: linear time,
  // where one sort of all pairs took 0.1 s at 260k tets.
  const int k = int(elements.cols());
  const auto for_each_pair = [&](auto&& visit) {
    for (Eigen::Index e = 0; e < elements.rows(); ++e)
      for (int a = 0; a < k; ++a)
        for (int b = a + 1; b < k; ++b) {
          const int i = elements(e, a), j = elements(e, b);
          if (i != j) visit(std::min(i, j), std::max(i, j));
        }
  };
  std::vector<int> start(size_t(num_vertices) + 1, 0);
  for_each_pair([&](int i, int) { ++start[size_t(i) + 1]; });
  std::partial_sum(start.begin(), start.end(), start.begin());
  std::vector<int> higher(size_t(start.back()));
  std::vector<int> fill(start.begin(), start.end() - 1);
  for_each_pair([&](int i, int j) { higher[size_t(fill[size_t(i)]++)] = j; });
  std::vector<int> count(size_t(num_vertices), 0);  // distinct higher neighbours
#pragma omp parallel for schedule(dynamic, 1024) if (num_vertices >= kMinParallelRows)
  for (int i = 0; i < num_vertices; ++i) {
    const auto first = higher.begin() + start[size_t(i)],
               last = higher.begin() + start[size_t(i) + 1];
    std::sort(first, last);
    count[size_t(i)] = int(std::unique(first, last) - first);
  }

  int num_edges = 0;
  for (int i = 0; i < num_vertices; ++i) num_edges += count[size_t(i)];
  Eigen::MatrixX2i edges(num_edges, 2);
  for (int i = 0, e = 0; i < num_vertices; ++i)
    for (int c = 0; c < count[size_t(i)]; ++c, ++e) {
      edges(e, 0) = i;
      edges(e, 1) = higher[size_t(start[size_t(i)] + c)];
    }
  return edge_graph_from_sorted_edges(num_vertices, std::move(edges));
}

EdgeGraph edge_graph_from_sorted_edges(int num_vertices, Eigen::MatrixX2i edges) {
  EdgeGraph g;
  g.num_vertices = num_vertices;
  g.edges = std::move(edges);
  g.offsets.assign(size_t(num_vertices) + 1, 0);
  for (int e = 0; e < g.num_edges(); ++e) {
    ++g.offsets[size_t(g.edges(e, 0)) + 1];
    ++g.offsets[size_t(g.edges(e, 1)) + 1];
  }
  std::partial_sum(g.offsets.begin(), g.offsets.end(), g.offsets.begin());
  g.neighbors.resize(2 * size_t(g.num_edges()));
  g.neighbor_edge.resize(2 * size_t(g.num_edges()));
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
