#include "solvers/contact_bridges.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>
#include <string>
#include <utility>
#include <vector>

#include "core/errors.h"
#include "core/parallel.h"
#include "core/progress.h"
#include "mesh/edge_graph.h"
#include "metrics/pose_invariance.h"

namespace unfold {
namespace {

constexpr int kTetEdges[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};

// Across a limb, surface points are about pi/2 times farther apart along the
// surface than in space (half a round cross-section's perimeter over its
// diameter); an edge is a bridge only beyond this detour.
constexpr double kDetour = 4.0;

// Each vertex's nearest surface vertex along the tet edges: itself for a
// surface vertex (one Dijkstra from all of them at once).
std::vector<int> nearest_surface_vertex(const EdgeGraph& graph, const Eigen::MatrixX3d& P,
                                        int num_surface) {
  std::vector<int> nearest(size_t(graph.num_vertices), -1);
  std::vector<double> dist(size_t(graph.num_vertices), std::numeric_limits<double>::infinity());
  using Entry = std::pair<double, int>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> heap;
  for (int v = 0; v < num_surface; ++v) {
    nearest[size_t(v)] = v;
    dist[size_t(v)] = 0;
    heap.push({0.0, v});
  }
  while (!heap.empty()) {
    const auto [d, v] = heap.top();
    heap.pop();
    if (d > dist[size_t(v)]) continue;
    for (int k = graph.offsets[size_t(v)]; k < graph.offsets[size_t(v) + 1]; ++k) {
      const int w = graph.neighbors[size_t(k)];
      const double dw = d + (P.row(v) - P.row(w)).norm();
      if (dw < dist[size_t(w)]) {
        dist[size_t(w)] = dw;
        nearest[size_t(w)] = nearest[size_t(v)];
        heap.push({dw, w});
      }
    }
  }
  return nearest;
}

// Whether each tet edge (by the tet graph's edge index) is a bridge: the
// surface edge-graph distance between its ends' nearest surface vertices
// exceeds both the reach and kDetour times their distance in space. An edge
// inside a limb joins surface points around it (a detour of about pi/2); one
// across a contact joins points that only a long way along the surface
// connects. Each source's Dijkstra stops once its targets are settled or the
// bound is passed, so only the ends of bridges explore a whole ball.
std::vector<char> bridge_edges(const SurfaceMesh& surface, const EdgeGraph& tet_graph,
                               const Eigen::MatrixX3d& P, double geodesic) {
  const int ns = int(surface.V.rows());
  const Eigen::MatrixX3i F = triangulate_faces(surface);
  const EdgeGraph graph = build_edge_graph(ns, Eigen::MatrixXi(F));
  const double reach = geodesic * std::sqrt(surface_area(surface.V, F));
  const std::vector<int> nearest = nearest_surface_vertex(tet_graph, P, ns);
  // the pairs to measure, from their lower end: (other end, tet edge)
  std::vector<std::vector<std::pair<int, int>>> pairs(static_cast<size_t>(ns));
  for (int e = 0; e < tet_graph.num_edges(); ++e) {
    int a = nearest[size_t(tet_graph.edges(e, 0))];
    int b = nearest[size_t(tet_graph.edges(e, 1))];
    if (a == b) continue;
    if (a > b) std::swap(a, b);
    if (std::binary_search(graph.neighbors.begin() + graph.offsets[size_t(a)],
                           graph.neighbors.begin() + graph.offsets[size_t(a) + 1], b))
      continue;  // a surface edge
    pairs[size_t(a)].emplace_back(b, e);
  }
  std::vector<char> bridge(size_t(tet_graph.num_edges()), 0);
#pragma omp parallel if (ns >= kMinParallelRows)
  {
    std::vector<double> dist(size_t(ns), std::numeric_limits<double>::infinity());
    std::vector<int> touched;
    std::vector<int> pending(size_t(ns), 0);  // per vertex, the source's targets on it
    using Entry = std::pair<double, int>;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<>> heap;
#pragma omp for schedule(dynamic, 256)
    for (int i = 0; i < ns; ++i) {
      const auto& targets = pairs[size_t(i)];
      if (targets.empty()) continue;
      const auto bound = [&](int j) {
        return std::max(reach, kDetour * (P.row(i) - P.row(j)).norm());
      };
      double limit = 0;
      for (const auto& t : targets) limit = std::max(limit, bound(t.first));
      int open = int(targets.size());
      for (const auto& t : targets) ++pending[size_t(t.first)];
      dist[size_t(i)] = 0;
      touched.push_back(i);
      heap.push({0.0, i});
      while (!heap.empty() && open > 0) {
        const auto [d, v] = heap.top();
        heap.pop();
        if (d > dist[size_t(v)]) continue;
        if (d > limit) break;
        open -= pending[size_t(v)];
        pending[size_t(v)] = 0;
        for (int k = graph.offsets[size_t(v)]; k < graph.offsets[size_t(v) + 1]; ++k) {
          const int w = graph.neighbors[size_t(k)];
          const double dw = d + (P.row(v) - P.row(w)).norm();
          if (dw < dist[size_t(w)]) {
            if (std::isinf(dist[size_t(w)])) touched.push_back(w);
            dist[size_t(w)] = dw;
            heap.push({dw, w});
          }
        }
      }
      for (const auto& [j, e] : targets)
        if (dist[size_t(j)] > bound(j)) bridge[size_t(e)] = 1;
      for (const auto& t : targets) pending[size_t(t.first)] = 0;
      for (const int v : touched) dist[size_t(v)] = std::numeric_limits<double>::infinity();
      touched.clear();
      heap = {};
    }
  }
  return bridge;
}

}  // namespace

std::vector<int> tets_bridging_contact(const SurfaceMesh& surface, const TetMesh& tets,
                                       double geodesic) {
  const int ns = tets.num_surface_vertices;
  if (surface.V.rows() != ns)
    throw UsageError("tets_bridging_contact: " + std::to_string(surface.V.rows()) +
                     " surface vertices for a tet mesh with " + std::to_string(ns));
  if (!(geodesic > 0) || !std::isfinite(geodesic))
    throw UsageError("tets_bridging_contact: the geodesic bound must be a positive number");
  report_stage("looking for tets that bridge a contact");
  const EdgeGraph graph = build_edge_graph(int(tets.V.rows()), Eigen::MatrixXi(tets.T));
  const std::vector<char> bridge = bridge_edges(surface, graph, tets.V, geodesic);
  std::vector<int> out;
  for (int t = 0; t < tets.T.rows(); ++t)
    for (const auto& [a, b] : kTetEdges) {
      int i = tets.T(t, a), j = tets.T(t, b);
      if (i > j) std::swap(i, j);
      const auto first = graph.neighbors.begin() + graph.offsets[size_t(i)];
      const auto last = graph.neighbors.begin() + graph.offsets[size_t(i) + 1];
      if (bridge[size_t(graph.neighbor_edge[size_t(std::lower_bound(first, last, j) -
                                                   graph.neighbors.begin())])]) {
        out.push_back(t);
        break;
      }
    }
  return out;
}

}  // namespace unfold
