// The demo animal's head with a closed mouth (issue 44): lips touching, a thin
// cavity behind them, as on real scans. Unfolding the unfolded shape's tets
// used to pull needles out of such mouths; the canonical form must keep the
// mouth intact (no edge stretched or crushed beyond 3x).
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <queue>
#include <vector>

#include "config/options.h"
#include "core/errors.h"
#include "mesh/check_surface_mesh.h"
#include "mesh/edge_graph.h"
#include "metrics/surface_damage.h"
#include "pipeline/unfold_surface.h"
#include "shapes/articulated_shape.h"
#include "test_meshes.h"

namespace unfold {
namespace {

// Fast enough for a test (about 2,000 vertices), fine enough for the mouth.
constexpr int kResolution = 48;

// The jaw hinge of shapes/articulated_shape.cpp: the mouth slot's faces are
// planes through it, the upper one horizontal, the lower one turned down by
// kMouthOpenDegrees at rest.
const Eigen::Vector3d kHinge(1.5, 0, 0.72);

double mean_edge_length(const SurfaceMesh& m) {
  const EdgeGraph graph = build_edge_graph(int(m.V.rows()), triangulate_faces(m));
  double sum = 0;
  int count = 0;
  for (int i = 0; i < graph.num_vertices; ++i)
    for (int k = graph.offsets[size_t(i)]; k < graph.offsets[size_t(i) + 1]; ++k) {
      sum += (m.V.row(i) - m.V.row(graph.neighbors[size_t(k)])).norm();
      ++count;
    }
  return sum / count;
}

// Edges between i and every vertex, breadth first: hops along the surface.
std::vector<int> hops_from(const EdgeGraph& graph, int i) {
  std::vector<int> hops(size_t(graph.num_vertices), -1);
  std::queue<int> queue;
  hops[size_t(i)] = 0;
  queue.push(i);
  while (!queue.empty()) {
    const int v = queue.front();
    queue.pop();
    for (int k = graph.offsets[size_t(v)]; k < graph.offsets[size_t(v) + 1]; ++k) {
      const int w = graph.neighbors[size_t(k)];
      if (hops[size_t(w)] >= 0) continue;
      hops[size_t(w)] = hops[size_t(v)] + 1;
      queue.push(w);
    }
  }
  return hops;
}

// The lips, picked on the open rest surface (the same vertices in every pose of
// the mouth head): vertices on the slot's flat faces in its front half.
struct Lips {
  std::vector<int> upper, lower;
};

Lips find_lips(const SurfaceMesh& open) {
  const double open_angle = kMouthOpenDegrees * M_PI / 180;
  const Eigen::Vector3d lower_normal(-std::sin(open_angle), 0, -std::cos(open_angle));
  Lips lips;
  for (int i = 0; i < int(open.V.rows()); ++i) {
    const Eigen::Vector3d p = open.V.row(i).transpose() - kHinge;
    if (p.x() < 0.2) continue;
    if (std::abs(p.z()) < 0.03) lips.upper.push_back(i);
    if (std::abs(p.dot(lower_normal)) < 0.03) lips.lower.push_back(i);
  }
  return lips;
}

// Outward vertex normals, area weighted.
Eigen::MatrixX3d vertex_normals(const SurfaceMesh& m) {
  const Eigen::MatrixX3i F = triangulate_faces(m);
  Eigen::MatrixX3d N = Eigen::MatrixX3d::Zero(m.V.rows(), 3);
  for (Eigen::Index t = 0; t < F.rows(); ++t) {
    const Eigen::RowVector3d n =
        (m.V.row(F(t, 1)) - m.V.row(F(t, 0))).cross(m.V.row(F(t, 2)) - m.V.row(F(t, 0)));
    for (int a = 0; a < 3; ++a) N.row(F(t, a)) += n;
  }
  N.rowwise().normalize();
  return N;
}

// The head: every vertex in front of the neck, rest positions (the posed
// head is at rest but for the jaw).
std::vector<int> head_vertices(const SurfaceMesh& m) {
  std::vector<int> head;
  for (int i = 0; i < int(m.V.rows()); ++i)
    if (m.V(i, 0) > 1.35) head.push_back(i);
  return head;
}

// Worst edge ratio (max of r and 1/r) among the edges at `vertices`.
double worst_ratio(const SurfaceDamage& damage, const std::vector<int>& vertices) {
  double worst = 0;
  for (const int i : vertices) worst = std::max(worst, damage.per_vertex(i));
  return std::exp(worst);
}

TEST(ClosedMouth, SurfacesAreValidClosedMeshes) {
  for (const int resolution : {kResolution, kDefaultShapeResolution}) {
    const SurfaceMesh m = make_articulated_shape(ShapePose::open_mouth(), resolution);
    const SurfaceReport report = check_surface_mesh(m);
    EXPECT_EQ(report.num_boundary_edges, 0) << resolution;
    EXPECT_EQ(report.num_nonmanifold_edges, 0) << resolution;
    EXPECT_EQ(report.num_misoriented_edges, 0) << resolution;
    EXPECT_EQ(report.num_nonmanifold_vertices, 0) << resolution;
    EXPECT_EQ(report.num_components, 1) << resolution;
    const EdgeGraph graph = build_edge_graph(int(m.V.rows()), triangulate_faces(m));
    EXPECT_EQ(m.V.rows() - graph.num_edges() + int(m.faces.size()), 2)
        << resolution << ": a sphere's Euler characteristic";
    EXPECT_GT(test::signed_volume(m), 0.5) << resolution << ": outward orientation";
  }
}

TEST(ClosedMouth, LipsTouchButAreFarApartAlongTheSurface) {
  for (const int resolution : {kResolution, kDefaultShapeResolution}) {
    const SurfaceMesh open = make_articulated_shape(ShapePose::open_mouth(), resolution);
    const SurfaceMesh closed = make_articulated_shape(ShapePose::closed_mouth(), resolution);
    ASSERT_EQ(closed.faces, open.faces);
    const double edge = mean_edge_length(open);
    const Lips lips = find_lips(open);
    ASSERT_GE(lips.upper.size(), 3u) << resolution;
    ASSERT_GE(lips.lower.size(), 3u) << resolution;
    // The gap from each lower-lip vertex to the nearest upper-lip vertex, along
    // that vertex's outward normal: <= 0 where the lips press into each other.
    const Eigen::MatrixX3d N = vertex_normals(closed);
    double smallest_gap = std::numeric_limits<double>::infinity();
    int pressed = 0, near_upper = 0, near_lower = 0;
    for (const int l : lips.lower) {
      int nearest = lips.upper.front();
      for (const int u : lips.upper)
        if ((closed.V.row(u) - closed.V.row(l)).norm() <
            (closed.V.row(nearest) - closed.V.row(l)).norm())
          nearest = u;
      const double gap = (closed.V.row(l) - closed.V.row(nearest)).dot(N.row(nearest));
      if (gap <= 0) ++pressed;
      if (gap < smallest_gap) smallest_gap = gap, near_upper = nearest, near_lower = l;
    }
    std::cout << "resolution " << resolution << ": edge " << edge << ", smallest gap "
              << smallest_gap << ", lower-lip vertices pressed in " << pressed << " of "
              << lips.lower.size() << "\n";
    EXPECT_LT(smallest_gap, 0.1 * edge) << resolution;
    EXPECT_GE(pressed, 2) << resolution << ": the lips touch along a line, not at a point";
    // Open, the lips are well apart; along the surface, they are always far.
    EXPECT_GT((open.V.row(near_upper) - open.V.row(near_lower)).norm(), 1.5 * edge);
    const EdgeGraph graph = build_edge_graph(int(open.V.rows()), triangulate_faces(open));
    EXPECT_GE(hops_from(graph, near_upper)[size_t(near_lower)], 6) << resolution;
  }
}

struct MouthDamage {
  double head_worst = 0;  // the worst edge ratio (max of r, 1/r) on the head
  SurfaceDamage all;
};

MouthDamage unfold_closed_mouth(const Options& options) {
  const SurfaceMesh input = make_articulated_shape(ShapePose::closed_mouth(), kResolution);
  const UnfoldResult result = unfold_surface(input, options);
  EXPECT_EQ(result.surface.V.rows(), input.V.rows());
  MouthDamage d;
  d.all = surface_damage(result.surface.V, result.canonical.V, result.surface.faces);
  d.head_worst = worst_ratio(d.all, head_vertices(result.surface));
  return d;
}

// The key test: the default keeps the closed mouth intact.
TEST(ClosedMouth, DefaultCanonicalFormKeepsTheMouthIntact) {
  const MouthDamage d = unfold_closed_mouth(Options());
  std::cout << "default: head worst ratio " << d.head_worst << ", everywhere max "
            << d.all.ratio_max << " min " << d.all.ratio_min << ", damaged " << d.all.damaged_edges
            << "\n";
  EXPECT_LE(d.head_worst, kDamagedEdgeRatio);
  EXPECT_EQ(d.all.damaged_edges, 0);
}

// The tets' edges alone (integrate.surface_edges 0, the behaviour before the
// fix). On this mouth it stays intact too (head worst ratio about 1.7 against
// 1.4 with the default, resolution 48): the demo mouth does not yet reproduce
// the scans' needles, so this keeps the figure in view and checks nothing more.
TEST(ClosedMouth, TetEdgesAloneOnTheSameMouth) {
  Options options;
  options.integrate.surface_edges = 0;
  const MouthDamage d = unfold_closed_mouth(options);
  std::cout << "tet edges alone: head worst ratio " << d.head_worst << ", everywhere max "
            << d.all.ratio_max << " min " << d.all.ratio_min << ", damaged " << d.all.damaged_edges
            << "\n";
  EXPECT_TRUE(std::isfinite(d.head_worst));
}

TEST(ClosedMouth, JawNeedsTheMouthHead) {
  ShapePose pose;
  pose.jaw_pitch = 10;
  EXPECT_THROW(make_articulated_shape(pose, 32), UsageError);
  EXPECT_TRUE(ShapePose::named("mouth").mouth);
  EXPECT_TRUE(ShapePose::named("mouth_open").mouth);
  EXPECT_EQ(ShapePose::named("mouth_open").jaw_pitch, 0);
}

}  // namespace
}  // namespace unfold
