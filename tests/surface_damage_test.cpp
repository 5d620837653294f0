// The damage measure of issue 44 (metrics/surface_damage.h): per-edge length
// ratios after scaling to the input's area, their tail, and bad input.
#include "metrics/surface_damage.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "core/errors.h"
#include "pipeline/result_pictures.h"
#include "test_meshes.h"

namespace unfold {
namespace {

// An n x n grid of unit squares in the plane z = 0, each split by the diagonal
// from its lower left to its upper right corner; vertex (i, j) is i + (n + 1) j.
SurfaceMesh flat_grid(int n) {
  SurfaceMesh m;
  m.V.resize((n + 1) * (n + 1), 3);
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) m.V.row(i + (n + 1) * j) << i, j, 0;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int a = i + (n + 1) * j, b = a + 1, c = a + n + 2, d = a + n + 1;
      m.faces.push_back({a, b, c});
      m.faces.push_back({a, c, d});
    }
  return m;
}

double triangle_area(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  return 0.5 * (b - a).cross(c - a).norm();
}

TEST(SurfaceDamage, ASimilarityTransformDamagesNothing) {
  const SurfaceMesh sphere = test::uv_sphere(12, 16);
  const Eigen::Matrix3d R = test::random_rotation(7);
  const Eigen::MatrixX3d moved =
      ((2.5 * sphere.V) * R.transpose()).rowwise() + Eigen::RowVector3d(4, -2, 9);
  const SurfaceDamage d = surface_damage(sphere.V, moved, sphere.faces);
  // Euler: a closed genus-0 surface has V + F - 2 unique edges.
  EXPECT_EQ(d.edges, int(sphere.V.rows() + sphere.faces.size()) - 2);
  EXPECT_EQ(d.zero_length_edges, 0);
  EXPECT_EQ(d.damaged_edges, 0);
  EXPECT_EQ(d.damaged_edges_percent, 0);
  EXPECT_NEAR(d.scale, 1 / 2.5, 1e-12);
  EXPECT_NEAR(d.ratio_max, 1, 1e-12);
  EXPECT_NEAR(d.ratio_min, 1, 1e-12);
  EXPECT_NEAR(d.ratio_p999, 1, 1e-12);
  ASSERT_EQ(d.per_vertex.size(), sphere.V.rows());
  EXPECT_LT(d.per_vertex.maxCoeff(), 1e-12);
}

// One vertex of a flat 20 x 20 grid pulled 10 units out of the plane: its six
// edges are damaged and no other; the largest ratio is one of its four unit
// edges, sqrt(1 + 10^2) times the area scale.
TEST(SurfaceDamage, OneVertexPulledOutDamagesExactlyItsEdges) {
  const int n = 20, pulled = 10 + 21 * 10;
  const SurfaceMesh grid = flat_grid(n);
  Eigen::MatrixX3d out = grid.V;
  out(pulled, 2) = 10;
  double area_out = 0;
  for (const auto& f : grid.faces)
    area_out += triangle_area(out.row(f[0]), out.row(f[1]), out.row(f[2]));
  const double s = std::sqrt(n * n / area_out);
  const SurfaceDamage d = surface_damage(grid.V, out, grid.faces);
  EXPECT_EQ(d.edges, 3 * n * n + 2 * n);
  EXPECT_NEAR(d.scale, s, 1e-12);
  EXPECT_EQ(d.damaged_edges, 6);
  EXPECT_NEAR(d.damaged_edges_percent, 100.0 * 6 / d.edges, 1e-12);
  EXPECT_NEAR(d.ratio_max, s * std::sqrt(101.0), 1e-10);
  EXPECT_NEAR(d.ratio_min, s, 1e-12);  // every flat edge keeps its length, times the scale
  // 1,240 edges: nearest rank k = 1,239, among the four largest (equal) ratios.
  EXPECT_NEAR(d.ratio_p999, d.ratio_max, 1e-12);
  // Per vertex: the pulled one has the largest damage, its neighbours too are
  // past ln 3, every other vertex keeps |ln s|.
  const std::vector<int> ring = {pulled - 1,  pulled + 1,  pulled - 21,
                                 pulled + 21, pulled - 22, pulled + 22};
  EXPECT_NEAR(d.per_vertex[pulled], std::log(s * std::sqrt(101.0)), 1e-10);
  int past_bound = 0;
  for (int v = 0; v < d.per_vertex.size(); ++v) {
    const bool near = v == pulled || std::find(ring.begin(), ring.end(), v) != ring.end();
    if (d.per_vertex[v] > std::log(kDamagedEdgeRatio)) ++past_bound;
    if (!near) {
      EXPECT_NEAR(d.per_vertex[v], std::abs(std::log(s)), 1e-12) << v;
    }
  }
  EXPECT_EQ(past_bound, 7);
}

// Two equal spheres, the second scaled 6x about its centre: at the input's
// area (s = sqrt(2 / 37)) the first is crushed below 1/3 and counts as
// damaged, the second is stretched 6 s = 1.39 and does not.
TEST(SurfaceDamage, OnePartScaledAgainstAnotherCrushesTheOther) {
  const SurfaceMesh sphere = test::uv_sphere(8, 10);
  const Eigen::Index nv = sphere.V.rows();
  Eigen::MatrixX3d in(2 * nv, 3), out(2 * nv, 3);
  in << sphere.V, sphere.V.rowwise() + Eigen::RowVector3d(5, 0, 0);
  out << sphere.V, (6 * sphere.V).rowwise() + Eigen::RowVector3d(5, 0, 0);
  std::vector<std::vector<int>> faces = sphere.faces;
  for (auto f : sphere.faces) {
    for (int& v : f) v += int(nv);
    faces.push_back(f);
  }
  const SurfaceDamage d = surface_damage(in, out, faces);
  const double s = std::sqrt(2.0 / 37.0);
  EXPECT_NEAR(d.scale, s, 1e-12);
  EXPECT_EQ(d.edges, 2 * (int(nv + sphere.faces.size()) - 2));
  EXPECT_EQ(d.damaged_edges, d.edges / 2);
  EXPECT_NEAR(d.damaged_edges_percent, 50, 1e-12);
  EXPECT_NEAR(d.ratio_min, s, 1e-12);
  EXPECT_NEAR(d.ratio_max, 6 * s, 1e-12);
  EXPECT_NEAR(d.ratio_p999, 6 * s, 1e-12);
  EXPECT_NEAR(d.per_vertex.head(nv).minCoeff(), -std::log(s), 1e-12);
  EXPECT_NEAR(d.per_vertex.tail(nv).maxCoeff(), std::log(6 * s), 1e-12);

  // Scaled 2x only: s = sqrt(2 / 5), ratios 0.63 and 1.26, nothing damaged.
  out.bottomRows(nv) = (2 * sphere.V).rowwise() + Eigen::RowVector3d(5, 0, 0);
  const SurfaceDamage mild = surface_damage(in, out, faces);
  EXPECT_EQ(mild.damaged_edges, 0);
  EXPECT_NEAR(mild.ratio_min, std::sqrt(0.4), 1e-12);
  EXPECT_NEAR(mild.ratio_max, 2 * std::sqrt(0.4), 1e-12);
}

// The 99.9th percentile is the nearest rank: 1,000 separate triangles, the
// t-th scaled by 1 + t / 1000 about its centroid; 3,000 edges, k = 2,997, so
// the percentile is the second largest triangle's ratio (ranks 2,995-2,997),
// not the largest nor an interpolation between the two.
TEST(SurfaceDamage, ThePercentileIsTheNearestRank) {
  const int m = 1000;
  Eigen::MatrixX3d in(3 * m, 3), out(3 * m, 3);
  std::vector<std::vector<int>> faces;
  double area_in = 0, area_out = 0;
  for (int t = 0; t < m; ++t) {
    const Eigen::RowVector3d c(3.0 * t, 0, 0);
    in.middleRows(3 * t, 3) << c, c + Eigen::RowVector3d(1, 0, 0), c + Eigen::RowVector3d(0, 1, 0);
    const Eigen::RowVector3d centroid = in.middleRows(3 * t, 3).colwise().mean();
    const double k = 1 + t / 1000.0;
    out.middleRows(3 * t, 3) =
        (k * (in.middleRows(3 * t, 3).rowwise() - centroid)).rowwise() + centroid;
    faces.push_back({3 * t, 3 * t + 1, 3 * t + 2});
    area_in += 0.5, area_out += 0.5 * k * k;
  }
  const double s = std::sqrt(area_in / area_out);
  const SurfaceDamage d = surface_damage(in, out, faces);
  EXPECT_EQ(d.edges, 3 * m);
  EXPECT_NEAR(d.ratio_max, s * (1 + 999 / 1000.0), 1e-12);
  EXPECT_NEAR(d.ratio_p999, s * (1 + 998 / 1000.0), 1e-12);
  EXPECT_NEAR(d.ratio_min, s, 1e-12);
}

// An edge of zero input length is skipped and counted; a polygon's edges are
// its sides (no fan diagonal).
TEST(SurfaceDamage, ZeroLengthInputEdgesAreSkippedAndCounted) {
  Eigen::MatrixX3d V(5, 3);
  V << 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 1, 1, 0;  // vertex 4 on vertex 2
  const std::vector<std::vector<int>> pentagon = {{0, 1, 2, 4, 3}};
  const SurfaceDamage d = surface_damage(V, V, pentagon);
  EXPECT_EQ(d.edges, 4);
  EXPECT_EQ(d.zero_length_edges, 1);
  EXPECT_EQ(d.damaged_edges, 0);
  EXPECT_NEAR(d.ratio_max, 1, 1e-15);
}

// A collapsed edge (r = 0) is damaged, the smallest ratio is 0 and every
// per-vertex value stays finite.
TEST(SurfaceDamage, ACollapsedEdgeIsDamagedAndFinite) {
  const SurfaceMesh grid = flat_grid(4);
  Eigen::MatrixX3d out = grid.V;
  out.row(6) = out.row(7);  // edge 6-7 collapses; the surface keeps area
  const SurfaceDamage d = surface_damage(grid.V, out, grid.faces);
  EXPECT_EQ(d.ratio_min, 0);
  EXPECT_GE(d.damaged_edges, 1);
  EXPECT_TRUE(d.per_vertex.allFinite());
  EXPECT_NEAR(d.per_vertex[6], -std::log(std::numeric_limits<double>::min()), 1e-9);
}

TEST(SurfaceDamage, TheMatrixOverloadAgreesWithThePolygonOne) {
  const SurfaceMesh sphere = test::uv_sphere(6, 9);
  Eigen::MatrixX3d out = sphere.V;
  out.col(0) *= 20;  // anisotropic: edges along x past 3x, others below 1/3
  Eigen::MatrixXi F(sphere.faces.size(), 3);
  for (size_t f = 0; f < sphere.faces.size(); ++f)
    F.row(Eigen::Index(f)) << sphere.faces[f][0], sphere.faces[f][1], sphere.faces[f][2];
  const SurfaceDamage a = surface_damage(sphere.V, out, sphere.faces);
  const SurfaceDamage b = surface_damage(sphere.V, out, F);
  EXPECT_GT(a.damaged_edges, 0);
  EXPECT_EQ(a.damaged_edges, b.damaged_edges);
  EXPECT_EQ(a.ratio_p999, b.ratio_p999);
  EXPECT_EQ(a.per_vertex, b.per_vertex);
  // A looser bound counts fewer edges as damaged.
  EXPECT_LT(surface_damage(sphere.V, out, F, 10).damaged_edges, a.damaged_edges);
}

TEST(SurfaceDamage, BadInputThrowsTheTypedError) {
  const SurfaceMesh grid = flat_grid(3);
  const Eigen::MatrixX3d& V = grid.V;
  EXPECT_THROW(surface_damage(V, V.topRows(V.rows() - 1), grid.faces), UsageError);
  EXPECT_THROW(surface_damage(V, V, grid.faces, 1.0), UsageError);
  EXPECT_THROW(surface_damage(V, V, grid.faces, std::nan("")), UsageError);
  auto faces = grid.faces;
  faces[3][1] = int(V.rows());
  EXPECT_THROW(surface_damage(V, V, faces), InputError);
  faces[3][1] = -1;
  EXPECT_THROW(surface_damage(V, V, faces), InputError);
  EXPECT_THROW(surface_damage(V, V, std::vector<std::vector<int>>{{0, 1}}), InputError);
  EXPECT_THROW(surface_damage(V, V, std::vector<std::vector<int>>{}), InputError);
  EXPECT_THROW(surface_damage(Eigen::MatrixX3d::Zero(V.rows(), 3), V, grid.faces), InputError);
  Eigen::MatrixX3d bad = V;
  bad(2, 1) = std::numeric_limits<double>::infinity();
  EXPECT_THROW(surface_damage(V, bad, grid.faces), NumericalError);
  EXPECT_THROW(surface_damage(V, Eigen::MatrixX3d::Ones(V.rows(), 3), grid.faces),
               NumericalError);  // collapsed to a point: zero area
  EXPECT_NO_THROW(surface_damage(V, V, grid.faces));
}

// --render_color damage: the canonical half coloured by metrics.damage.per_vertex,
// the pulled vertex's region in the top colour (yellow); plain shading has none.
TEST(SurfaceDamage, TheDamageColouringMarksThePulledVertex) {
  UnfoldResult result;
  result.surface = flat_grid(20);
  result.canonical = result.surface;
  result.canonical.V(10 + 21 * 10, 2) = 6;
  result.metrics.damage =
      surface_damage(result.surface.V, result.canonical.V, result.surface.faces);
  RenderOptions render;
  render.up_axis = 1;  // the grid seen from the side is a line; from y up, its face
  const auto yellow_pixels = [&](const Image& image) {
    int count = 0;
    for (int y = kCaptionHeight; y < image.height - 20; ++y)  // above the colour bar
      for (int x = image.width / 2; x < image.width; ++x) {
        const Rgb c = image.at(x, y);
        count += c.r > 180 && c.g > 160 && c.b < 90;
      }
    return count;
  };
  EXPECT_GT(yellow_pixels(render_before_after(result, render, surface_coloring("damage"))), 20);
  EXPECT_EQ(yellow_pixels(render_before_after(result, render, surface_coloring("shading"))), 0);
  EXPECT_THROW(surface_coloring("damaged"), UsageError);
  result.metrics.damage.per_vertex.resize(3);
  EXPECT_THROW(render_before_after(result, render, SurfaceColoring::kDamage), UsageError);
}

}  // namespace
}  // namespace unfold
