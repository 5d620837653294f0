#include "metrics/graph_geodesics.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <utility>

#include "core/errors.h"

namespace unfold {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

void heap_dijkstra(const EdgeGraph& graph, const std::vector<NeighborArc>& arcs, int source,
                   std::vector<double>* distance) {
  std::vector<double>& dist = *distance;
  // Lazy deletion: a popped entry whose vertex has since got closer is skipped.
  using Entry = std::pair<double, int>;
  std::vector<Entry> heap;
  heap.reserve(size_t(graph.num_vertices));
  const auto later = std::greater<Entry>();
  heap.emplace_back(0.0, source);
  while (!heap.empty()) {
    std::pop_heap(heap.begin(), heap.end(), later);
    const auto [d, i] = heap.back();
    heap.pop_back();
    if (d > dist[size_t(i)]) continue;
    for (int k = graph.offsets[size_t(i)]; k < graph.offsets[size_t(i) + 1]; ++k) {
      const int j = arcs[size_t(k)].neighbor;
      const double candidate = d + arcs[size_t(k)].length;
      if (candidate < dist[size_t(j)]) {
        dist[size_t(j)] = candidate;
        heap.emplace_back(candidate, j);
        std::push_heap(heap.begin(), heap.end(), later);
      }
    }
  }
}

// Buckets of width `width` kept in a ring (Dial's, with wider buckets): a
// vertex is pushed into the bucket of its new distance (never one already
// passed) and relaxes its neighbours when its bucket comes up, once per
// distance it has. A vertex improved by another of its own bucket (possible
// when width > the shortest length) is pushed into that bucket again and
// relaxes again, so every distance still ends at the shortest path's.
void bucket_dijkstra(const EdgeGraph& graph, const std::vector<NeighborArc>& arcs, double width,
                     size_t ring, int source, std::vector<double>* distance) {
  std::vector<double>& dist = *distance;
  // Kept per thread from one run to the next: fresh arrays cost every run their
  // allocation and page faults (a fifth of the run on a 75k-vertex tet mesh).
  thread_local std::vector<double> relaxed_at;
  thread_local std::vector<std::vector<int>> buckets;
  relaxed_at.assign(dist.size(), -1.0);
  if (buckets.size() < ring) buckets.resize(ring);
  buckets[0].push_back(source);
  size_t pending = 1;
  for (size_t current = 0; pending > 0; ++current) {
    std::vector<int>& bucket = buckets[current % ring];
    for (size_t e = 0; e < bucket.size(); ++e) {  // the bucket may grow meanwhile
      --pending;
      // The vertices to come are known: their neighbour lists are fetched
      // while this one is relaxed (a cache miss per vertex was most of the run).
      if (e + 8 < bucket.size()) {
        const int ahead = bucket[e + 8];
        const char* list =
            reinterpret_cast<const char*>(arcs.data() + graph.offsets[size_t(ahead)]);
        __builtin_prefetch(list);
        __builtin_prefetch(list + 64);
        __builtin_prefetch(list + 128);
        __builtin_prefetch(&dist[size_t(ahead)]);
        __builtin_prefetch(&relaxed_at[size_t(ahead)]);
      }
      if (e + 16 < bucket.size()) __builtin_prefetch(&graph.offsets[size_t(bucket[e + 16])]);
      const int i = bucket[e];
      const double d = dist[size_t(i)];
      if (relaxed_at[size_t(i)] == d) continue;
      relaxed_at[size_t(i)] = d;
      const NeighborArc* arc = arcs.data() + graph.offsets[size_t(i)];
      const NeighborArc* const end = arcs.data() + graph.offsets[size_t(i) + 1];
      for (; arc != end; ++arc) {
        const int j = arc->neighbor;
        const double candidate = d + arc->length;
        if (candidate < dist[size_t(j)]) {
          dist[size_t(j)] = candidate;
          const size_t b = std::max(current, size_t(candidate / width));
          buckets[b % ring].push_back(j);
          ++pending;
        }
      }
    }
    bucket.clear();
  }
}

}  // namespace

NeighborLengths neighbor_lengths(const EdgeGraph& graph, const Eigen::MatrixX3d& P) {
  if (P.rows() != graph.num_vertices)
    throw UsageError("graph_geodesics: P needs one row per graph vertex");
  NeighborLengths result;
  result.arcs.resize(graph.neighbors.size());
#pragma omp parallel for schedule(static)
  for (int i = 0; i < graph.num_vertices; ++i)
    for (int k = graph.offsets[size_t(i)]; k < graph.offsets[size_t(i) + 1]; ++k) {
      const int j = graph.neighbors[size_t(k)];
      result.arcs[size_t(k)] = {j, (P.row(i) - P.row(j)).norm()};
    }
  if (!result.arcs.empty()) {
    const auto [shortest, longest] = std::minmax_element(
        result.arcs.begin(), result.arcs.end(),
        [](const NeighborArc& a, const NeighborArc& b) { return a.length < b.length; });
    result.shortest = shortest->length;
    result.longest = longest->length;
  }
  return result;
}

void graph_geodesics(const EdgeGraph& graph, const NeighborLengths& lengths, int source,
                     std::vector<double>* distance) {
  if (lengths.arcs.size() != graph.neighbors.size())
    throw UsageError("graph_geodesics: need one length per neighbour entry");
  if (source < 0 || source >= graph.num_vertices)
    throw UsageError("graph_geodesics: source " + std::to_string(source) + " out of range");
  distance->assign(size_t(graph.num_vertices), kInfinity);
  (*distance)[size_t(source)] = 0;
  // A vertex's new bucket is at most longest / width + 1 ahead of the current
  // one. Width: a 32nd of the longest length (the shortest, when longer). Far
  // fewer buckets than width = shortest (808 on a 62k-vertex FAUST tet mesh),
  // few re-relaxations: 20 % faster there (docs/history/performance.md).
  const double width = std::max(lengths.shortest, lengths.longest / 32);
  const double span = lengths.longest / width;
  if (lengths.shortest > 0 && std::isfinite(span) && span < 4.0 * graph.num_vertices)
    bucket_dijkstra(graph, lengths.arcs, width, size_t(span) + 3, source, distance);
  else
    heap_dijkstra(graph, lengths.arcs, source, distance);
}

std::vector<double> graph_geodesics(const EdgeGraph& graph, const Eigen::MatrixX3d& P, int source) {
  std::vector<double> distance;
  graph_geodesics(graph, neighbor_lengths(graph, P), source, &distance);
  return distance;
}

}  // namespace unfold
