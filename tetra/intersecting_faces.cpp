#include "tetra/intersecting_faces.h"

#include <tetgen.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "core/errors.h"
#include "mesh/position_order.h"

namespace unfold {
namespace {

using Point = Eigen::Vector3d;

// Exact sign (-1, 0, 1) of TetGen's orient3d.
int orient(const Point& a, const Point& b, const Point& c, const Point& d) {
  const double det = orient3d(const_cast<double*>(a.data()), const_cast<double*>(b.data()),
                              const_cast<double*>(c.data()), const_cast<double*>(d.data()));
  return (det > 0) - (det < 0);
}

// Exact sign of the 2D orientation of p, q, r projected along axis k: with s
// equal to p except along axis k, orient3d(p, q, s, r) is a nonzero multiple
// of that 2x2 determinant (the sign is flipped for some k, the same for every
// call, which the tests below never notice: they only compare signs).
int orient_2d(const Point& p, const Point& q, const Point& r, int k) {
  Point s = p;
  s(k) += std::max(1.0, std::abs(p(k)));  // never rounds back to p(k)
  return orient(p, q, s, r);
}

// Closed segments pq and rs meet, in the projection along axis k.
bool segments_meet_2d(const Point& p, const Point& q, const Point& r, const Point& s, int k) {
  const int o1 = orient_2d(p, q, r, k), o2 = orient_2d(p, q, s, k);
  const int o3 = orient_2d(r, s, p, k), o4 = orient_2d(r, s, q, k);
  if (o1 * o2 > 0 || o3 * o4 > 0) return false;
  if (o1 != 0 || o2 != 0 || o3 != 0 || o4 != 0) return true;
  // Collinear: the intervals overlap in both projected coordinates.
  for (int i = 0; i < 3; ++i)
    if (i != k && (std::max(p(i), q(i)) < std::min(r(i), s(i)) ||
                   std::max(r(i), s(i)) < std::min(p(i), q(i))))
      return false;
  return true;
}

// Closed segment de meets closed triangle abc, in the projection along axis k.
bool segment_meets_triangle_2d(const Point& d, const Point& e, const Point& a, const Point& b,
                               const Point& c, int k) {
  if (segments_meet_2d(d, e, a, b, k) || segments_meet_2d(d, e, b, c, k) ||
      segments_meet_2d(d, e, c, a, k))
    return true;
  // Otherwise the segment is inside the triangle or away from it; a
  // degenerate (flat) projected triangle is its edges, tested above.
  const int o = orient_2d(a, b, c, k);
  return o != 0 && orient_2d(a, b, d, k) == o && orient_2d(b, c, d, k) == o &&
         orient_2d(c, a, d, k) == o;
}

// A test of coplanar points holds in 3D when it holds in all three axis
// projections: the projection along an axis not parallel to their plane (or
// line) is one-to-one on it, and the others cannot turn a meeting into a miss.
template <typename Test>
bool in_every_projection(Test test) {
  return test(0) && test(1) && test(2);
}

// Closed segments pq and rs meet (in 3D).
bool segments_meet(const Point& p, const Point& q, const Point& r, const Point& s) {
  return orient(p, q, r, s) == 0 &&
         in_every_projection([&](int k) { return segments_meet_2d(p, q, r, s, k); });
}

// Collinear (or coincident) corners: the triangle is the union of its edges.
bool collinear(const Point& a, const Point& b, const Point& c) {
  return orient_2d(a, b, c, 0) == 0 && orient_2d(a, b, c, 1) == 0 && orient_2d(a, b, c, 2) == 0;
}

// Closed segment de meets closed triangle abc, for any degeneracy of either.
bool segment_meets_triangle(const Point& d, const Point& e, const Point& a, const Point& b,
                            const Point& c) {
  const int od = orient(a, b, c, d), oe = orient(a, b, c, e);
  if (od * oe > 0) return false;
  if (od == 0 && oe == 0) {
    if (collinear(a, b, c))
      return segments_meet(d, e, a, b) || segments_meet(d, e, b, c) || segments_meet(d, e, c, a);
    return in_every_projection([&](int k) { return segment_meets_triangle_2d(d, e, a, b, c, k); });
  }
  // The segment reaches the plane at one point: inside the triangle when the
  // line de passes no edge on the wrong side.
  const int s1 = orient(d, e, a, b), s2 = orient(d, e, b, c), s3 = orient(d, e, c, a);
  return (s1 >= 0 && s2 >= 0 && s3 >= 0) || (s1 <= 0 && s2 <= 0 && s3 <= 0);
}

// Closed triangles meet: their intersection, if any, has a point on an edge
// of one of them (the extreme points of a nonempty intersection do).
bool triangles_meet(const std::array<Point, 3>& s, const std::array<Point, 3>& t) {
  for (size_t i = 0; i < 3; ++i)
    if (segment_meets_triangle(s[i], s[(i + 1) % 3], t[0], t[1], t[2]) ||
        segment_meets_triangle(t[i], t[(i + 1) % 3], s[0], s[1], s[2]))
      return true;
  return false;
}

// Triangles s and t (corner indices after merging equal positions) intersect
// beyond what they share.
bool faces_intersect(const Eigen::MatrixX3d& V, const Eigen::RowVector3i& fs,
                     const Eigen::RowVector3i& ft) {
  std::array<Point, 3> s, t;
  for (int k = 0; k < 3; ++k) {
    s[size_t(k)] = V.row(fs(k)).transpose();
    t[size_t(k)] = V.row(ft(k)).transpose();
  }
  // Reorder both so that shared corners come first, in the same order.
  std::array<int, 3> is{0, 1, 2}, it{0, 1, 2};
  int shared = 0;
  for (int i = 0; i < 3; ++i)
    for (int j = shared; j < 3; ++j)
      if (fs(is[size_t(i)]) == ft(it[size_t(j)])) {
        std::swap(is[size_t(i)], is[size_t(shared)]);
        std::swap(it[size_t(j)], it[size_t(shared)]);
        ++shared;
        break;
      }
  const auto at = [](const std::array<Point, 3>& p, const std::array<int, 3>& order,
                     int k) -> const Point& { return p[size_t(order[size_t(k)])]; };
  switch (shared) {
    case 0:
      return triangles_meet(s, t);
    case 1:
      // Their intersection is the shared corner alone unless its point
      // farthest from that corner, which lies on an edge opposite it, is elsewhere.
      return segment_meets_triangle(at(s, is, 1), at(s, is, 2), t[0], t[1], t[2]) ||
             segment_meets_triangle(at(t, it, 1), at(t, it, 2), s[0], s[1], s[2]);
    case 2: {
      // Across the shared edge unless coplanar with both far corners on one
      // side, decided in a projection where s keeps its area (one-to-one on
      // the plane); a flat s is its edges, so nothing lies beyond the shared one.
      const Point &a = at(s, is, 0), &b = at(s, is, 1), &c = at(s, is, 2), &d = at(t, it, 2);
      if (orient(a, b, c, d) != 0) return false;
      for (int k = 0; k < 3; ++k)
        if (const int side = orient_2d(a, b, c, k)) return side == orient_2d(a, b, d, k);
      return false;
    }
    default:
      return true;  // the same triangle twice
  }
}

}  // namespace

std::vector<std::pair<int, int>> intersecting_face_pairs(const Eigen::MatrixX3d& V,
                                                         const Eigen::MatrixX3i& F) {
  const int nv = int(V.rows()), nf = int(F.rows());
  if (nf > 0 && (F.minCoeff() < 0 || F.maxCoeff() >= nv))
    throw UsageError("intersecting_face_pairs: a face index is out of range (" +
                     std::to_string(nv) + " vertices)");
  if (nf < 2) return {};
  // Exact arithmetic, no static filter (it would need the coordinate bounds).
  // TetGen itself only runs in forked children (run_tetgen), so nothing in
  // this process changes these settings afterwards.
  static const bool predicates_ready = (exactinit(0, 0, 1, 1, 1, 1), true);
  (void)predicates_ready;

  // Vertices at equal positions become one (the lowest index).
  const std::vector<int> order = position_order(V);
  std::vector<int> same(V.rows());
  for (size_t k = 0; k < order.size(); ++k)
    same[size_t(order[k])] =
        k > 0 && V.row(order[k]) == V.row(order[k - 1]) ? same[size_t(order[k - 1])] : order[k];
  Eigen::MatrixX3i G(nf, 3);
  std::vector<char> repeats(F.rows());  // two corners at one position: skipped
  for (int t = 0; t < nf; ++t) {
    for (int k = 0; k < 3; ++k) G(t, k) = same[size_t(F(t, k))];
    repeats[size_t(t)] = G(t, 0) == G(t, 1) || G(t, 1) == G(t, 2) || G(t, 2) == G(t, 0);
  }

  // Uniform grid, cells about as large as an average triangle's bounding box:
  // each triangle is listed in every cell its box overlaps, and a pair is
  // tested in the one cell holding the low corner of the boxes' overlap.
  Eigen::MatrixX3d low(nf, 3), high(nf, 3);
  double size = 0;
  for (int t = 0; t < nf; ++t) {
    low.row(t) = V.row(F(t, 0)).cwiseMin(V.row(F(t, 1))).cwiseMin(V.row(F(t, 2)));
    high.row(t) = V.row(F(t, 0)).cwiseMax(V.row(F(t, 1))).cwiseMax(V.row(F(t, 2)));
    size += (high.row(t) - low.row(t)).maxCoeff();
  }
  const Eigen::RowVector3d origin = low.colwise().minCoeff();
  const double extent = (high.colwise().maxCoeff() - origin).maxCoeff();
  // Cells no smaller than 1/1000 of the mesh, so that a few huge triangles or
  // a cloud of tiny ones cannot make the grid blow up.
  const double cell = std::max({size / nf, extent / 1000, 1e-300});
  const auto cell_of = [&](const Eigen::RowVector3d& p) {
    return Eigen::Array3i(((p - origin) / cell).array().floor().cast<int>());
  };
  const auto key = [](const Eigen::Array3i& c) {
    return (uint64_t(c(0)) << 42) | (uint64_t(c(1)) << 21) | uint64_t(c(2));
  };
  std::vector<std::pair<uint64_t, int>> listed;  // (cell, triangle)
  for (int t = 0; t < nf; ++t) {
    const Eigen::Array3i a = cell_of(low.row(t)), b = cell_of(high.row(t));
    for (int x = a(0); x <= b(0); ++x)
      for (int y = a(1); y <= b(1); ++y)
        for (int z = a(2); z <= b(2); ++z) listed.emplace_back(key({x, y, z}), t);
  }
  std::sort(listed.begin(), listed.end());
  std::vector<size_t> starts;
  for (size_t k = 0; k < listed.size(); ++k)
    if (k == 0 || listed[k].first != listed[k - 1].first) starts.push_back(k);
  starts.push_back(listed.size());

  std::vector<std::pair<int, int>> pairs;
  // Threads only pay off beyond a few thousand listings.
#pragma omp parallel if (listed.size() > 4096)
  {
    std::vector<std::pair<int, int>> found;
#pragma omp for schedule(dynamic, 64)
    for (int c = 0; c < int(starts.size()) - 1; ++c)
      for (size_t i = starts[size_t(c)]; i < starts[size_t(c) + 1]; ++i)
        for (size_t j = i + 1; j < starts[size_t(c) + 1]; ++j) {
          const int s = std::min(listed[i].second, listed[j].second),
                    t = std::max(listed[i].second, listed[j].second);
          const Eigen::RowVector3d overlap = low.row(s).cwiseMax(low.row(t));
          if ((overlap.array() > high.row(s).cwiseMin(high.row(t)).array()).any() ||
              key(cell_of(overlap)) != listed[i].first || repeats[size_t(s)] || repeats[size_t(t)])
            continue;
          if (faces_intersect(V, G.row(s), G.row(t))) found.emplace_back(s, t);
        }
#pragma omp critical
    pairs.insert(pairs.end(), found.begin(), found.end());
  }
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

}  // namespace unfold
