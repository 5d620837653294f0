#include "solvers/contact_bridges.h"

#include <algorithm>
#include <array>
#include <atomic>
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

constexpr double kUnbounded = std::numeric_limits<double>::infinity();

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

// One bounded A* search at a time on an edge graph (lengths from P), its
// arrays kept between runs so that each run costs only what it reaches.
class BoundedSearch {
 public:
  BoundedSearch(const EdgeGraph& graph, const Eigen::MatrixX3d& P)
      : graph_(graph), P_(P), dist_(size_t(graph.num_vertices), kUnreached) {}

  /// Settles vertices in order of their distance from the sources plus
  /// estimate(v), a lower bound of what is left to the goal that never
  /// drops by more than an edge's length along it (for instance a distance
  /// in space), up to `limit`, calling settle(v) on each; stops early when it
  /// returns false. Every vertex on a path from a source of length at most
  /// `limit` to a goal is settled before it stops on the limit.
  template <class Estimate, class Settle>
  void run(const int* sources, int count, double limit, Estimate estimate, Settle settle) {
    for (const int v : touched_) dist_[size_t(v)] = kUnreached;
    touched_.clear();
    heap_ = {};
    for (int k = 0; k < count; ++k) reach(sources[k], 0.0, estimate);
    while (!heap_.empty()) {
      const Entry top = heap_.top();
      heap_.pop();
      if (top.dist > dist_[size_t(top.v)]) continue;
      if (top.key > limit || !settle(top.v)) break;
      for (int k = graph_.offsets[size_t(top.v)]; k < graph_.offsets[size_t(top.v) + 1]; ++k) {
        const int w = graph_.neighbors[size_t(k)];
        reach(w, top.dist + (P_.row(top.v) - P_.row(w)).norm(), estimate);
      }
    }
  }

  /// After run: v's distance if settled, an upper bound if only reached,
  /// infinity if neither.
  double distance(int v) const { return dist_[size_t(v)]; }

 private:
  static constexpr double kUnreached = std::numeric_limits<double>::infinity();
  struct Entry {
    double key, dist;
    int v;
    bool operator>(const Entry& o) const { return key > o.key; }
  };
  template <class Estimate>
  void reach(int w, double d, Estimate estimate) {
    if (!(d < dist_[size_t(w)])) return;
    if (dist_[size_t(w)] == kUnreached) touched_.push_back(w);
    dist_[size_t(w)] = d;
    heap_.push({d + estimate(w), d, w});
  }

  const EdgeGraph& graph_;
  const Eigen::MatrixX3d& P_;
  std::vector<double> dist_;
  std::vector<int> touched_;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> heap_;
};

// The length of the path from i to j that always steps to the neighbour
// nearest to j in space, or infinity if it stops nearer to no neighbour or
// grows past `bound`. An upper bound of their distance along the graph: round
// a convex part, such as a limb's cross-section, it reaches j in a few steps.
double greedy_path_length(const EdgeGraph& graph, const Eigen::MatrixX3d& P, int i, int j,
                          double bound) {
  double length = 0;
  double to_j = (P.row(i) - P.row(j)).norm();
  for (int v = i; v != j;) {
    int next = -1;
    for (int k = graph.offsets[size_t(v)]; k < graph.offsets[size_t(v) + 1]; ++k) {
      const int w = graph.neighbors[size_t(k)];
      const double d = (P.row(w) - P.row(j)).norm();
      if (d < to_j) to_j = d, next = w;
    }
    if (next < 0) return kUnbounded;
    length += (P.row(v) - P.row(next)).norm();
    if (length > bound) return kUnbounded;
    v = next;
  }
  return length;
}

// Whether each tet edge (by the tet graph's edge index) is a bridge: the
// surface edge-graph distance between its ends' nearest surface vertices
// exceeds both the reach and kDetour times their distance in space. An edge
// inside a limb joins surface points around it (a detour of about pi/2); one
// across a contact joins points that only a long way along the surface
// connects. A greedy path within the bound proves nearly every pair no
// bridge; the others (bridges, pairs round a concave part) take A*, which
// explores the whole bound only for a bridge. With `first_only`, the pairs
// after the first bridge (in edge order) are left unmeasured: the answer to
// "is there one" at the cost of the first, the same whatever the threads do.
std::vector<char> bridge_edges(const SurfaceMesh& surface, const EdgeGraph& tet_graph,
                               const Eigen::MatrixX3d& P, double geodesic, bool first_only) {
  const int ns = int(surface.V.rows());
  const Eigen::MatrixX3i F = triangulate_faces(surface);
  const EdgeGraph graph = build_edge_graph(ns, Eigen::MatrixXi(F));
  const double reach = geodesic * std::sqrt(surface_area(surface.V, F));
  const std::vector<int> nearest = nearest_surface_vertex(tet_graph, P, ns);
  // the pairs to measure: (one end, the other, tet edge)
  std::vector<std::array<int, 3>> pairs;
  for (int e = 0; e < tet_graph.num_edges(); ++e) {
    int a = nearest[size_t(tet_graph.edges(e, 0))];
    int b = nearest[size_t(tet_graph.edges(e, 1))];
    if (a == b) continue;
    if (a > b) std::swap(a, b);
    if (std::binary_search(graph.neighbors.begin() + graph.offsets[size_t(a)],
                           graph.neighbors.begin() + graph.offsets[size_t(a) + 1], b))
      continue;  // a surface edge
    pairs.push_back({a, b, e});
  }
  std::vector<char> bridge(size_t(tet_graph.num_edges()), 0);
  std::atomic<size_t> first_bridge = pairs.size();
#pragma omp parallel if (ns >= kMinParallelRows)
  {
    BoundedSearch search(graph, P);
#pragma omp for schedule(dynamic, 256)
    for (size_t k = 0; k < pairs.size(); ++k) {
      if (first_only && k > first_bridge.load(std::memory_order_relaxed)) continue;
      const auto [i, j, e] = pairs[k];
      const double bound = std::max(reach, kDetour * (P.row(i) - P.row(j)).norm());
      if (greedy_path_length(graph, P, i, j, bound) <= bound) continue;
      const Eigen::RowVector3d goal = P.row(j);
      search.run(
          &i, 1, bound, [&](int v) { return (P.row(v) - goal).norm(); },
          [j = j](int v) { return v != j; });
      // unsettled, j is beyond the bound, or its tentative distance bounds it
      if (!(search.distance(j) > bound)) continue;
      bridge[size_t(e)] = 1;
      size_t seen = first_bridge.load();  // lowered to k unless a lower one came first
      while (k < seen && !first_bridge.compare_exchange_weak(seen, k)) {
      }
    }
  }
  return bridge;
}

void check_geodesic(double geodesic, const char* who) {
  if (!(geodesic > 0) || !std::isfinite(geodesic))
    throw UsageError(std::string(who) + ": the geodesic bound must be a positive number");
}

// The tets' edge graph and which of its edges bridge a contact (bridge_edges),
// the arguments checked first for `who`.
struct TetBridges {
  EdgeGraph graph;
  std::vector<char> bridge;  // per edge of graph
};

TetBridges tet_bridges(const SurfaceMesh& surface, const TetMesh& tets, double geodesic,
                       bool first_only, const char* who) {
  if (surface.V.rows() != tets.num_surface_vertices)
    throw UsageError(std::string(who) + ": " + std::to_string(surface.V.rows()) +
                     " surface vertices for a tet mesh with " +
                     std::to_string(tets.num_surface_vertices));
  check_geodesic(geodesic, who);
  report_stage(first_only ? "looking for a tet that bridges a contact"
                          : "looking for tets that bridge a contact");
  TetBridges out{build_edge_graph(int(tets.V.rows()), Eigen::MatrixXi(tets.T)), {}};
  out.bridge = bridge_edges(surface, out.graph, tets.V, geodesic, first_only);
  return out;
}

}  // namespace

std::vector<int> tets_bridging_contact(const SurfaceMesh& surface, const TetMesh& tets,
                                       double geodesic) {
  const auto [graph, bridge] = tet_bridges(surface, tets, geodesic, false, "tets_bridging_contact");
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

bool some_tet_bridges_contact(const SurfaceMesh& surface, const TetMesh& tets, double geodesic) {
  const std::vector<char> bridge =
      tet_bridges(surface, tets, geodesic, true, "some_tet_bridges_contact").bridge;
  return std::find(bridge.begin(), bridge.end(), 1) != bridge.end();
}

int count_intersections_far_along_surface(const SurfaceMesh& surface,
                                          const std::vector<std::pair<int, int>>& pairs,
                                          double geodesic) {
  check_geodesic(geodesic, "count_intersections_far_along_surface");
  const Eigen::MatrixX3i F = triangulate_faces(surface);
  for (const auto& [s, t] : pairs)
    if (s < 0 || t < 0 || s >= F.rows() || t >= F.rows())
      throw UsageError("count_intersections_far_along_surface: face pair (" + std::to_string(s) +
                       ", " + std::to_string(t) + ") out of range");
  if (pairs.empty()) return 0;
  const EdgeGraph graph = build_edge_graph(int(surface.V.rows()), Eigen::MatrixXi(F));
  const double reach = geodesic * std::sqrt(surface_area(surface.V, F));
  int far = 0;
#pragma omp parallel reduction(+ : far) if (pairs.size() >= 64)
  {
    BoundedSearch search(graph, surface.V);
#pragma omp for schedule(dynamic, 16)
    for (size_t k = 0; k < pairs.size(); ++k) {
      const Eigen::Vector3i from = F.row(pairs[k].first), to = F.row(pairs[k].second);
      const auto estimate = [&](int v) {
        double d = kUnbounded;
        for (const int c : to) d = std::min(d, (surface.V.row(v) - surface.V.row(c)).norm());
        return d;
      };
      bool near = false;
      search.run(from.data(), 3, reach, estimate, [&](int v) {
        near = v == to[0] || v == to[1] || v == to[2];
        return !near;
      });
      far += !near;
    }
  }
  return far;
}

}  // namespace unfold
