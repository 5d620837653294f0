// The robust route: Delaunay tetrahedralization of the surface vertices plus
// interior grid points, carved by the generalized winding number. It never
// needs the surface to be a valid piecewise-linear complex, so
// self-intersections, non-manifold edges and small holes do not stop it.
#include <omp.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <parallel/algorithm>
#include <vector>

#include "core/errors.h"
#include "core/parallel.h"
#include "core/progress.h"
#include "core/union_find.h"
#include "mesh/edge_graph.h"
#include "mesh/position_order.h"
#include "tetra/delaunay_tets.h"
#include "tetra/fast_winding_number.h"
#include "tetra/interior_grid_points.h"
#include "tetra/tetrahedralize.h"

namespace unfold {
namespace {

uint64_t edge_key(int a, int b) {
  if (a > b) std::swap(a, b);
  return (uint64_t(uint32_t(a)) << 32) | uint32_t(b);
}

// A Delaunay tetrahedralization merges points at equal positions, which would
// drop a surface vertex from the output. Later copies of a position are moved
// by a tiny deterministic offset for it only; tets joining two copies are
// dropped afterwards.
Eigen::MatrixX3d separate_duplicates(const Eigen::MatrixX3d& V, double offset) {
  const std::vector<int> order = position_order(V);
  Eigen::MatrixX3d P = V;
  int copy = 0;
  for (size_t k = 1; k < order.size(); ++k) {
    copy = V.row(order[k]) == V.row(order[k - 1]) ? copy + 1 : 0;
    if (copy == 0) continue;
    // Directions on a golden-angle spiral, so copies of one point stay apart.
    const double z = 1 - 2 * std::fmod(copy * 0.618033988749895, 1.0), phi = copy * 2.39996323;
    const double r = std::sqrt(std::max(0.0, 1 - z * z));
    P.row(order[k]) += offset * Eigen::RowVector3d(r * std::cos(phi), r * std::sin(phi), z);
  }
  return P;
}

// Seconds since `start`, and start moved to now: the phases' times for --v=1.
double lap(std::chrono::steady_clock::time_point* start) {
  const auto now = std::chrono::steady_clock::now();
  const double seconds = std::chrono::duration<double>(now - *start).count();
  *start = now;
  return seconds;
}

}  // namespace

RobustStart robust_start(const SurfaceMesh& surface, double spacing) {
  auto clock = std::chrono::steady_clock::now();
  RobustStart start;
  const Eigen::MatrixX3i F = triangulate_faces(surface);
  if (surface.V.rows() < 4 || F.rows() == 0)
    throw InputError(
        "tetrahedralization (robust route): the surface has fewer than 4 vertices "
        "or no faces");
  start.mean_edge_length = mean_edge_length(surface.V, F);
  start.tree = fast_winding_number_precomputation(surface.V, F);
  // Winding numbers are -1 inside an inward-oriented surface: the signed volume decides.
  double volume = 0;
  for (Eigen::Index t = 0; t < F.rows(); ++t)
    volume += surface.V.row(F(t, 0)).dot(surface.V.row(F(t, 1)).cross(surface.V.row(F(t, 2))));
  start.orientation = volume < 0 ? -1 : 1;
  start.interior =
      interior_grid_points(start.tree, start.orientation,
                           spacing > 0 ? spacing : kInteriorSpacingEdges * start.mean_edge_length);
  start.seconds = lap(&clock);
  return start;
}

TetMesh tetrahedralize_robust(const SurfaceMesh& surface, const RobustStart& start,
                              TetReport* report) {
  auto clock = std::chrono::steady_clock::now();
  const int n = int(surface.V.rows());
  const FastWindingNumberTree& tree = start.tree;
  const Eigen::MatrixX3i& F = tree.F;
  const double orientation = start.orientation;
  const Eigen::MatrixX3d& interior = start.interior;
  const Eigen::MatrixX3d P = separate_duplicates(surface.V, 1e-4 * start.mean_edge_length);
  const double seconds_points = start.seconds + lap(&clock);
  Eigen::MatrixX3d V(n + interior.rows(), 3);
  V << P, interior;
  const Eigen::MatrixX4i T = delaunay_tets(V);  // P's duplicates are apart: every point in a tet
  V.topRows(n) = surface.V;                     // undo the duplicate separation
  const int num_delaunay = int(T.rows());
  const double seconds_delaunay = lap(&clock);

  // Carve: keep a tet when its centroid is inside and none of its edges
  // between two surface vertices leaves the volume. The second test is what
  // keeps touching limbs apart: a tet bridging the gap can have its centroid
  // inside one limb, but its bridging edge's midpoint is in the gap.
  Eigen::MatrixX3d centroids(num_delaunay, 3);
  for (int t = 0; t < num_delaunay; ++t)
    centroids.row(t) = (V.row(T(t, 0)) + V.row(T(t, 1)) + V.row(T(t, 2)) + V.row(T(t, 3))) / 4;
  const ClassifyOptions classify;  // the rescue below counts on its contract
  Eigen::VectorXd w = orientation * fast_winding_number_classify(tree, centroids, classify);
  // Bridging candidates: edges of an inside tet between two surface vertices
  // that are not surface edges. (edge, tet) pairs sorted by edge group each
  // edge's tets, so each edge's midpoint is classified once.
  const EdgeGraph surface_graph = build_edge_graph(n, Eigen::MatrixXi(F));
  const auto surface_edge = [&](int a, int b) {
    const auto first = surface_graph.neighbors.begin() + surface_graph.offsets[size_t(a)];
    const auto last = surface_graph.neighbors.begin() + surface_graph.offsets[size_t(a) + 1];
    return std::find(first, last, b) != last;
  };
  const auto corner = [](int k, int e) {  // the 6 edges of a tet as corner pairs
    static const int pairs[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
    return pairs[e][k];
  };
  std::vector<char> keep(size_t(num_delaunay), 0);
  std::vector<char> degenerate(size_t(num_delaunay), 0);
  // Each thread's candidates from its own block of tets, joined: the sort
  // gives them one order whatever the blocks were.
  std::vector<std::vector<std::pair<uint64_t, int>>> found(
      static_cast<size_t>(omp_get_max_threads()));
#pragma omp parallel if (num_delaunay >= kMinParallelRows)
  {
    std::vector<std::pair<uint64_t, int>>& mine = found[size_t(omp_get_thread_num())];
#pragma omp for schedule(static)
    for (int t = 0; t < num_delaunay; ++t) {
      for (int e = 0; e < 6; ++e) {
        const int a = T(t, corner(0, e)), b = T(t, corner(1, e));
        if (V.row(a) == V.row(b)) degenerate[size_t(t)] = 1;
        if (w(t) <= kInsideWinding || a >= n || b >= n || surface_edge(a, b)) continue;
        mine.emplace_back(edge_key(a, b), t);
      }
      keep[size_t(t)] = w(t) > kInsideWinding && !degenerate[size_t(t)];
    }
  }
  std::vector<std::pair<uint64_t, int>> candidates;
  for (const auto& mine : found) candidates.insert(candidates.end(), mine.begin(), mine.end());
  __gnu_parallel::sort(candidates.begin(), candidates.end());
  std::vector<size_t> group_start;  // first candidate of each distinct edge
  for (size_t k = 0; k < candidates.size(); ++k)
    if (k == 0 || candidates[k].first != candidates[k - 1].first) group_start.push_back(k);
  Eigen::MatrixX3d midpoints(group_start.size(), 3);
  for (size_t g = 0; g < group_start.size(); ++g) {
    const uint64_t key = candidates[group_start[g]].first;
    midpoints.row(Eigen::Index(g)) = (V.row(int(key >> 32)) + V.row(int(key & 0xffffffffu))) / 2;
  }
  const Eigen::VectorXd w_mid = orientation * fast_winding_number_classify(tree, midpoints);
  group_start.push_back(candidates.size());
  for (size_t g = 0; g + 1 < group_start.size(); ++g)
    if (w_mid(Eigen::Index(g)) <= kInsideWinding)
      for (size_t k = group_start[g]; k < group_start[g + 1]; ++k)
        keep[size_t(candidates[k].second)] = 0;

  const double seconds_carve = lap(&clock);

  // Every surface vertex must end up in the one connected tet mesh (else the
  // edge graph falls apart and nothing moves). A surface vertex in no kept tet
  // gets its most-inside incident tet back; then, while the kept tets form
  // several components, the most-inside carved tet joining two of them is put
  // back. Carved tets rather than surface edges are added so that the result
  // stays a tet mesh; the most-inside ones are the least likely to bridge a gap.
  int rescued = 0;
  std::vector<int> best(size_t(n), -1);
  std::vector<char> used(size_t(V.rows()), 0);
  for (int t = 0; t < num_delaunay; ++t)
    for (int k = 0; k < 4; ++k)
      if (keep[size_t(t)]) used[size_t(T(t, k))] = 1;
  // The rescues rank tets by w, and classify's coarse w is only sure to be on
  // the right side of 1/2: the tets they rank get the accurate w, so they pick
  // the tets fast_winding_number_solve's values would.
  const auto make_accurate = [&](const std::vector<int>& ranked) {
    Eigen::MatrixX3d ranked_centroids(ranked.size(), 3);
    for (size_t k = 0; k < ranked.size(); ++k)
      ranked_centroids.row(Eigen::Index(k)) = centroids.row(ranked[k]);
    const Eigen::VectorXd accurate =
        orientation * fast_winding_number_solve(tree, ranked_centroids);
    for (size_t k = 0; k < ranked.size(); ++k) w(ranked[k]) = accurate(Eigen::Index(k));
  };
  // Only the tets that can be the most inside of a vertex in no kept tet need
  // the accurate w. classify refined every coarse w within its margin of 1/2,
  // so a w in that band is accurate already; any other is within the margin of
  // its accurate value (classify's contract). A tet whose w plus that error is
  // below another's w minus its error cannot be the most inside: david0's
  // 55,800 tets ranked -> 33,404 (0.36 -> 0.24 s), the same tets picked.
  const auto error = [&](double x) {
    return classify_refines(x, classify) ? 0.0 : classify.margin;
  };
  std::vector<double> surely(size_t(n), -std::numeric_limits<double>::infinity());
  for (int t = 0; t < num_delaunay; ++t)
    for (int k = 0; k < 4; ++k) {
      const int v = T(t, k);
      if (v < n && !used[size_t(v)] && !degenerate[size_t(t)])
        surely[size_t(v)] = std::max(surely[size_t(v)], w(t) - error(w(t)));
    }
  std::vector<int> ranked;  // those tets, where their w is the coarse one
  for (int t = 0; t < num_delaunay; ++t)
    for (int k = 0; k < 4; ++k) {
      const int v = T(t, k);
      if (v < n && !used[size_t(v)] && !degenerate[size_t(t)] && error(w(t)) > 0 &&
          w(t) + error(w(t)) >= surely[size_t(v)]) {
        ranked.push_back(t);
        break;
      }
    }
  make_accurate(ranked);
  for (int t = 0; t < num_delaunay; ++t)
    for (int k = 0; k < 4; ++k) {
      const int v = T(t, k);
      if (v < n && !degenerate[size_t(t)] && (best[size_t(v)] < 0 || w(t) > w(best[size_t(v)])))
        best[size_t(v)] = t;
    }
  for (int v = 0; v < n; ++v)
    if (!used[size_t(v)] && best[size_t(v)] >= 0) {
      if (!keep[size_t(best[size_t(v)])]) ++rescued;
      keep[size_t(best[size_t(v)])] = 1;
      for (int k = 0; k < 4; ++k) used[size_t(T(best[size_t(v)], k))] = 1;
    }
  // A vertex whose every tet also holds a copy of it (all dropped as
  // degenerate) gets a copy of a kept tet of its twin: same shape, own index.
  std::vector<Eigen::RowVector4i> shared;
  for (int v = 0; v < n; ++v) {
    if (used[size_t(v)]) continue;
    for (int t = 0; t < num_delaunay && !used[size_t(v)]; ++t)
      for (int k = 0; k < 4 && keep[size_t(t)]; ++k)
        if (T(t, k) != v && V.row(T(t, k)) == V.row(v)) {
          shared.push_back(T.row(t));
          shared.back()(k) = v;
          used[size_t(v)] = 1;
          break;
        }
    if (!used[size_t(v)])
      throw NumericalError("tetrahedralization (robust route): surface vertex " +
                           std::to_string(v) + " is in no usable tetrahedron");
  }
  UnionFind components(int(V.rows()));
  for (int t = 0; t < num_delaunay; ++t)
    if (keep[size_t(t)])
      for (int k = 1; k < 4; ++k) components.unite(T(t, 0), T(t, k));
  for (const Eigen::RowVector4i& tet : shared)
    for (int k = 1; k < 4; ++k) components.unite(tet(0), tet(k));
  int num_components = 0;
  for (int v = 0; v < int(V.rows()); ++v)
    num_components += used[size_t(v)] && components.find(v) == v;
  if (num_components > 1) {
    // Only a carved tet with a vertex outside the largest component (or in no
    // kept tet) can ever join two: the others' vertices stay in the one
    // component that holds the largest. Ranking just those picks the same tets
    // and spares the accurate w of the rest (david0: 24 components, 223k
    // carved tets).
    std::vector<int> size(V.rows(), 0);
    for (int v = 0; v < int(V.rows()); ++v)
      if (used[size_t(v)]) ++size[size_t(components.find(v))];
    const int largest = int(std::max_element(size.begin(), size.end()) - size.begin());
    std::vector<int> carved;
    for (int t = 0; t < num_delaunay; ++t) {
      if (keep[size_t(t)] || degenerate[size_t(t)]) continue;
      bool apart = false;
      for (int c = 0; c < 4 && !apart; ++c)
        apart = !used[size_t(T(t, c))] || components.find(T(t, c)) != largest;
      if (apart) carved.push_back(t);
    }
    make_accurate(carved);
    std::stable_sort(carved.begin(), carved.end(), [&](int s, int t) { return w(s) > w(t); });
    for (size_t k = 0; k < carved.size() && num_components > 1; ++k) {
      const int t = carved[k];
      std::vector<int> roots;
      for (int c = 0; c < 4; ++c)
        if (used[size_t(T(t, c))]) roots.push_back(components.find(T(t, c)));
      std::sort(roots.begin(), roots.end());
      const int joined = int(std::unique(roots.begin(), roots.end()) - roots.begin());
      if (joined < 2) continue;
      keep[size_t(t)] = 1;
      ++rescued;
      num_components -= joined - 1;
      for (int c = 0; c < 4; ++c) {
        used[size_t(T(t, c))] = 1;
        components.unite(T(t, 0), T(t, c));
      }
    }
  }

  // Surface vertices first and in order, then the interior points still used.
  std::vector<int> index(size_t(V.rows()), -1);
  int count = 0;
  for (int v = 0; v < int(V.rows()); ++v)
    if (used[size_t(v)] || v < n) index[size_t(v)] = count++;
  TetMesh tets;
  tets.num_surface_vertices = n;
  tets.V.resize(count, 3);
  for (int v = 0; v < int(V.rows()); ++v)
    if (index[size_t(v)] >= 0) tets.V.row(index[size_t(v)]) = V.row(v);
  const int num_kept = int(std::count(keep.begin(), keep.end(), 1));
  tets.T.resize(num_kept + Eigen::Index(shared.size()), 4);
  Eigen::Index row = 0;
  for (int t = 0; t < num_delaunay; ++t)
    if (keep[size_t(t)]) {
      for (int k = 0; k < 4; ++k) tets.T(row, k) = index[size_t(T(t, k))];
      ++row;
    }
  for (const Eigen::RowVector4i& tet : shared) {
    for (int k = 0; k < 4; ++k) tets.T(row, k) = index[size_t(tet(k))];
    ++row;
  }
  report_detail([&](std::ostream& line) {
    line << "robust route: interior points " << seconds_points << " s, Delaunay (" << V.rows()
         << " points, " << num_delaunay << " tets) " << seconds_delaunay << " s, carve ("
         << midpoints.rows() << " edge midpoints) " << seconds_carve << " s, rescue and output "
         << lap(&clock) << " s";
  });
  if (report) {
    report->num_removed_tets = num_delaunay - num_kept;
    report->num_rescued_tets = rescued;
  }
  return tets;
}

}  // namespace unfold
