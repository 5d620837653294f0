#include "tetra/interior_grid_points.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <vector>

#include "core/union_find.h"
#include "mesh/boundary_chain.h"

namespace unfold {
namespace {

// The lattice's cells along x whose winding number can be above 1/2, for
// each line along x (index y * cells(2) + z): [first, last], empty where
// first > last. The winding number w_S of the surface S is 1/4 or less
// wherever a ray along x meets none of what is marked here:
// - S's triangles (their boxes);
// - each connected part k of S's boundary chain (of K) closed by the cone C_k
//   from its vertices' mean (triangles to its edges, each its multiplicity
//   times): S + the cones has no boundary, so its winding number is an integer,
//   0 where a ray to infinity meets neither S nor a cone, and there w_S is
//   minus the cones' winding numbers. A point e_k from C_k's box sees it under
//   a solid angle of at most area_k / e_k^2, so with e_k^2 = K area_k / pi the
//   box grown by e_k is marked, and beyond the K boxes their sum is at most 1/4.
// A closed, consistently oriented surface has no boundary chain.
struct LineRanges {
  std::vector<int> first, last;
};

LineRanges line_ranges(const FastWindingNumberTree& tree, const Eigen::RowVector3d& low,
                       double spacing, const Eigen::Array3i& cells) {
  const size_t lines = size_t(cells(1)) * size_t(cells(2));
  LineRanges r{std::vector<int>(lines, INT_MAX), std::vector<int>(lines, INT_MIN)};
  // Cell centre j's coordinate is low + spacing (j + 1/2): the cells from
  // floor to ceil of (c - low) / spacing - 1/2 take in every centre between
  // two coordinates, with half a cell to spare against rounding.
  const auto below = [&](double c, int k) {
    return int(std::max(std::floor((c - low(k)) / spacing - 0.5), -1.0));
  };
  const auto above = [&](double c, int k) {
    return int(std::min(std::ceil((c - low(k)) / spacing - 0.5), double(cells(k))));
  };
  const auto mark = [&](const Eigen::RowVector3d& lo, const Eigen::RowVector3d& hi) {
    const int x0 = below(lo(0), 0), x1 = above(hi(0), 0);
    const int y1 = std::min(above(hi(1), 1), cells(1) - 1);
    const int z1 = std::min(above(hi(2), 2), cells(2) - 1);
    for (int y = std::max(below(lo(1), 1), 0); y <= y1; ++y)
      for (int z = std::max(below(lo(2), 2), 0); z <= z1; ++z) {
        const size_t line = size_t(y) * size_t(cells(2)) + size_t(z);
        r.first[line] = std::min(r.first[line], x0);
        r.last[line] = std::max(r.last[line], x1);
      }
  };
  const Eigen::MatrixX3d& V = tree.V;
  for (Eigen::Index t = 0; t < tree.F.rows(); ++t) {
    Eigen::RowVector3d lo = V.row(tree.F(t, 0)), hi = lo;
    for (int c = 1; c < 3; ++c) {
      lo = lo.cwiseMin(V.row(tree.F(t, c)));
      hi = hi.cwiseMax(V.row(tree.F(t, c)));
    }
    mark(lo, hi);
  }
  const std::vector<ChainEdge> chain = boundary_chain(tree.F);
  if (chain.empty()) return r;
  UnionFind parts(int(V.rows()));
  for (const ChainEdge& e : chain) parts.unite(e.from, e.to);
  std::vector<int> part_of(size_t(V.rows()), -1);  // by the part's root
  std::vector<char> seen(size_t(V.rows()), 0);
  struct Part {
    Eigen::RowVector3d sum, lo, hi;
    int count = 0;
    double area = 0;
  };
  std::vector<Part> part;
  for (const ChainEdge& e : chain)
    for (const int v : {e.from, e.to}) {
      if (seen[size_t(v)]) continue;
      seen[size_t(v)] = 1;
      int& k = part_of[size_t(parts.find(v))];
      if (k < 0) {
        k = int(part.size());
        part.push_back({Eigen::RowVector3d::Zero(), V.row(v), V.row(v)});
      }
      Part& p = part[size_t(k)];
      p.sum += V.row(v);
      ++p.count;
      p.lo = p.lo.cwiseMin(V.row(v));
      p.hi = p.hi.cwiseMax(V.row(v));
    }
  for (const ChainEdge& e : chain) {
    Part& p = part[size_t(part_of[size_t(parts.find(e.from))])];
    const Eigen::RowVector3d o = p.sum / p.count;
    p.area += e.multiplicity * 0.5 * (V.row(e.from) - o).cross(V.row(e.to) - o).norm();
  }
  for (const Part& p : part) {
    const double grow = std::sqrt(double(part.size()) * p.area / M_PI);
    mark(p.lo.array() - grow, p.hi.array() + grow);
  }
  return r;
}

}  // namespace

Eigen::MatrixX3d interior_grid_points(const FastWindingNumberTree& tree, double orientation,
                                      double spacing) {
  const Eigen::MatrixX3d& V = tree.V;
  const Eigen::RowVector3d low = V.colwise().minCoeff(), high = V.colwise().maxCoeff();
  const Eigen::Array3i cells = ((high - low) / spacing).array().ceil().cast<int>().max(1);
  const LineRanges ranges = line_ranges(tree, low, spacing, cells);
  // Surface vertices sorted into the grid's cells (one cell of margin all
  // round), for the distance test: a cell's vertices are
  // vertex_of[first[c], first[c + 1]).
  const auto cell_of = [&](const Eigen::RowVector3d& p) {
    return Eigen::Array3i(((p - low) / spacing).array().floor().cast<int>());
  };
  const auto key = [&](const Eigen::Array3i& c) {
    return (int64_t(c(0) + 1) * (cells(1) + 3) + (c(1) + 1)) * (cells(2) + 3) + (c(2) + 1);
  };
  const int64_t num_keys = int64_t(cells(0) + 3) * (cells(1) + 3) * (cells(2) + 3);
  std::vector<int> first(size_t(num_keys) + 1, 0), vertex_of(size_t(V.rows()));
  std::vector<int64_t> vertex_key(size_t(V.rows()));
  for (int i = 0; i < int(V.rows()); ++i) {
    vertex_key[size_t(i)] = key(cell_of(V.row(i)));
    ++first[size_t(vertex_key[size_t(i)]) + 1];
  }
  std::partial_sum(first.begin(), first.end(), first.begin());
  {
    std::vector<int> next(first.begin(), first.end() - 1);
    for (int i = 0; i < int(V.rows()); ++i)
      vertex_of[size_t(next[size_t(vertex_key[size_t(i)])]++)] = i;
  }
  // Each x slab on its own (in parallel), joined in x order: the order of the
  // points is the serial loop's.
  std::vector<std::vector<Eigen::RowVector3d>> slab_points(size_t(cells(0))),
      slab_shifts(size_t(cells(0)));
#pragma omp parallel for schedule(dynamic, 1)
  for (int x = 0; x < cells(0); ++x)
    for (int y = 0; y < cells(1); ++y)
      for (int z = 0; z < cells(2); ++z) {
        const size_t line = size_t(y) * size_t(cells(2)) + size_t(z);
        if (x < ranges.first[line] || x > ranges.last[line]) continue;
        const Eigen::RowVector3d p = low + spacing * Eigen::RowVector3d(x + 0.5, y + 0.5, z + 0.5);
        const Eigen::Array3i c = cell_of(p);
        bool far = true;
        for (int dx = -1; dx <= 1 && far; ++dx)
          for (int dy = -1; dy <= 1 && far; ++dy)
            for (int dz = -1; dz <= 1 && far; ++dz) {
              const int64_t k = key(c + Eigen::Array3i(dx, dy, dz));
              for (int j = first[size_t(k)]; j < first[size_t(k) + 1] && far; ++j)
                far = !((V.row(vertex_of[size_t(j)]) - p).norm() < spacing / 2);
            }
        if (far) {
          slab_points[size_t(x)].push_back(p);
          slab_shifts[size_t(x)].push_back(kInteriorGridShear * spacing *
                                           Eigen::RowVector3d(y + z, x + z, x + y));
        }
      }
  std::vector<Eigen::RowVector3d> candidates, shifts;
  for (int x = 0; x < cells(0); ++x) {
    candidates.insert(candidates.end(), slab_points[size_t(x)].begin(),
                      slab_points[size_t(x)].end());
    shifts.insert(shifts.end(), slab_shifts[size_t(x)].begin(), slab_shifts[size_t(x)].end());
  }
  Eigen::MatrixX3d Q(candidates.size(), 3);
  for (size_t k = 0; k < candidates.size(); ++k) Q.row(Eigen::Index(k)) = candidates[k];
  const Eigen::VectorXd w = orientation * fast_winding_number_classify(tree, Q);
  Eigen::MatrixX3d inside((w.array() > kInsideWinding).count(), 3);
  for (Eigen::Index k = 0, row = 0; k < Q.rows(); ++k)
    if (w(k) > kInsideWinding) inside.row(row++) = Q.row(k) + shifts[size_t(k)];
  return inside;
}

}  // namespace unfold
