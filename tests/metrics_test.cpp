#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "core/errors.h"
#include "mesh/edge_graph.h"
#include "metrics/edge_ratio.h"
#include "metrics/geodesic_error.h"
#include "metrics/graph_geodesics.h"
#include "metrics/rigid_alignment.h"
#include "metrics/rigidity_error.h"
#include "metrics/stretch_error.h"
#include "test_meshes.h"

namespace unfold {
namespace {

// A regular grid of points (spacing 1), x fastest.
Eigen::MatrixX3d grid_points(int nx, int ny, int nz) {
  Eigen::MatrixX3d P(nx * ny * nz, 3);
  for (int k = 0, r = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) P.row(r++) << i, j, k;
  return P;
}

// The Kuhn tetrahedra of that grid's cubes, as an edge graph.
EdgeGraph grid_tet_graph(int nx, int ny, int nz) {
  static const int kPerm[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  Eigen::MatrixXi T(6 * (nx - 1) * (ny - 1) * (nz - 1), 4);
  int row = 0;
  for (int k = 0; k + 1 < nz; ++k)
    for (int j = 0; j + 1 < ny; ++j)
      for (int i = 0; i + 1 < nx; ++i)
        for (const auto& perm : kPerm) {
          int c[3] = {i, j, k};
          T(row, 0) = c[0] + nx * (c[1] + ny * c[2]);
          for (int s = 0; s < 3; ++s) {
            ++c[perm[s]];
            T(row, s + 1) = c[0] + nx * (c[1] + ny * c[2]);
          }
          ++row;
        }
  return build_edge_graph(nx * ny * nz, T);
}

Eigen::Matrix3d random_rotation(std::mt19937& rng) {
  std::normal_distribution<double> normal;
  return Eigen::Quaterniond(normal(rng), normal(rng), normal(rng), normal(rng))
      .normalized()
      .toRotationMatrix();
}

Eigen::MatrixX3d rigidly_moved(const Eigen::MatrixX3d& P, std::mt19937& rng) {
  const Eigen::Matrix3d R = random_rotation(rng);
  return (P * R.transpose()).rowwise() + Eigen::RowVector3d(3.0, -1.5, 0.25);
}

Eigen::MatrixX3d random_points(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  Eigen::MatrixX3d P(n, 3);
  for (int i = 0; i < n; ++i) P.row(i) << u(rng), u(rng), u(rng);
  return P;
}

TEST(MetricRigidity, ZeroForRigidMotion) {
  std::mt19937 rng(7);
  const EdgeGraph g = grid_tet_graph(4, 4, 4);
  const Eigen::MatrixX3d P = grid_points(4, 4, 4);
  const RigidityError e = rigidity_error(g, P, rigidly_moved(P, rng));
  EXPECT_LT(e.mean, 1e-10);
  EXPECT_LT(e.per_vertex.maxCoeff(), 1e-10);
  EXPECT_EQ(e.per_vertex.size(), P.rows());
}

TEST(MetricRigidity, GrowsAsAnisotropicScaleLeavesOne) {
  const EdgeGraph g = grid_tet_graph(4, 4, 4);
  const Eigen::MatrixX3d P = grid_points(4, 4, 4);
  double previous = 0;
  for (const double s : {1.1, 1.3, 1.6, 2.0}) {
    const Eigen::MatrixX3d Q = P * Eigen::Vector3d(s, 1, 1).asDiagonal();
    const RigidityError e = rigidity_error(g, P, Q);
    EXPECT_GT(e.mean, previous + 1e-3) << "s = " << s;
    EXPECT_NEAR(e.mean, e.per_vertex.mean(), 1e-12);
    previous = e.mean;
  }
  EXPECT_GT(rigidity_error(g, P, P * Eigen::Vector3d(0.8, 1, 1).asDiagonal()).mean, 1e-3);
}

TEST(MetricRigidity, RejectsBadInput) {
  const EdgeGraph g = grid_tet_graph(2, 2, 2);
  const Eigen::MatrixX3d P = grid_points(2, 2, 2);
  EXPECT_THROW(rigidity_error(g, P, P.topRows(3)), UsageError);
  Eigen::MatrixX3d degenerate = P;
  degenerate.row(1) = degenerate.row(0);
  EXPECT_THROW(rigidity_error(g, degenerate, P), InputError);
}

TEST(MetricStretch, ZeroForRigidMotionAndSMinusOneForUniformScale) {
  std::mt19937 rng(3);
  const Eigen::MatrixX3d P = random_points(500, 1);
  const StretchError rigid = stretch_error(P, rigidly_moved(P, rng));
  EXPECT_TRUE(rigid.exact);
  EXPECT_EQ(rigid.pairs_used, 500 * 499 / 2);
  EXPECT_NEAR(rigid.value, 0, 1e-12);
  EXPECT_EQ(rigid.standard_error, 0);
  EXPECT_NEAR(stretch_error(P, 1.7 * P).value, 0.7, 1e-12);
  EXPECT_NEAR(stretch_error(P, 0.5 * P).value, -0.5, 1e-12);
}

TEST(MetricStretch, SampledEstimateAgreesWithExact) {
  const Eigen::MatrixX3d P = random_points(3000, 2);
  const Eigen::MatrixX3d Q = P + 0.3 * (3 * P).array().sin().matrix();
  const StretchError exact = stretch_error(P, Q);
  StretchErrorOptions options;
  options.exact_limit = 100;
  options.sample_pairs = 200000;
  const StretchError sampled = stretch_error(P, Q, options);
  EXPECT_TRUE(exact.exact);
  EXPECT_FALSE(sampled.exact);
  EXPECT_EQ(sampled.pairs_used, 200000);
  EXPECT_GT(sampled.standard_error, 0);
  EXPECT_LT(std::abs(sampled.value - exact.value), 4 * sampled.standard_error)
      << "exact " << exact.value << " sampled " << sampled.value;
  // Same seed, same estimate.
  EXPECT_EQ(stretch_error(P, Q, options).value, sampled.value);
}

TEST(MetricStretch, SkipsCoincidentRestPoints) {
  Eigen::MatrixX3d P = random_points(20, 4);
  P.row(5) = P.row(2);
  P.row(9) = P.row(2);
  const StretchError e = stretch_error(P, 2.0 * P);
  EXPECT_EQ(e.pairs_skipped, 3);
  EXPECT_EQ(e.pairs_used, 20 * 19 / 2 - 3);
  EXPECT_NEAR(e.value, 1.0, 1e-12);
  EXPECT_THROW(stretch_error(P, P.topRows(4)), UsageError);
  EXPECT_THROW(stretch_error(Eigen::MatrixX3d::Zero(4, 3), Eigen::MatrixX3d::Zero(4, 3)),
               InputError);
}

TEST(MetricGraphGeodesics, KnownValuesOnGridGraph) {
  // 3 x 3 grid with axis-aligned edges only: distances are Manhattan; vertex 9
  // is isolated.
  Eigen::MatrixX3d P = Eigen::MatrixX3d::Zero(10, 3);
  P.topRows(9) = grid_points(3, 3, 1);
  Eigen::MatrixXi edges(12, 2);
  int e = 0;
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) {
      if (i < 2) edges.row(e++) << 3 * j + i, 3 * j + i + 1;
      if (j < 2) edges.row(e++) << 3 * j + i, 3 * j + i + 3;
    }
  const EdgeGraph g = build_edge_graph(10, edges);
  const std::vector<double> d = graph_geodesics(g, P, 0);
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) EXPECT_DOUBLE_EQ(d[size_t(3 * j + i)], i + j);
  EXPECT_TRUE(std::isinf(d[9]));
  EXPECT_DOUBLE_EQ(graph_geodesics(g, 2.5 * P, 4)[8], 5.0);
  EXPECT_THROW(graph_geodesics(g, P, 10), UsageError);
}

// Points along a straight line with irregular spacing, joined as a path.
struct Path {
  Eigen::MatrixX3d P;
  EdgeGraph graph;
};
Path straight_path(int n) {
  Path path;
  path.P = Eigen::MatrixX3d::Zero(n, 3);
  Eigen::MatrixXi edges(n - 1, 2);
  for (int i = 1; i < n; ++i) {
    path.P(i, 0) = path.P(i - 1, 0) + 1 + 0.5 * std::sin(i);
    edges.row(i - 1) << i - 1, i;
  }
  path.graph = build_edge_graph(n, edges);
  return path;
}

// Dijkstra with buckets (the default) and with a binary heap (what lengths
// too uneven for buckets get; forced here by hiding the shortest length) give
// the same distances, bit for bit, on a random geometric graph.
TEST(MetricGraphGeodesics, BucketsAndHeapAgreeExactly) {
  std::mt19937 random(5);
  std::uniform_real_distribution<double> unit(0, 1);
  const int n = 400;
  Eigen::MatrixX3d P(n, 3);
  for (int i = 0; i < n; ++i) P.row(i) << unit(random), unit(random), unit(random);
  std::vector<int> pairs;
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j)
      if ((P.row(i) - P.row(j)).norm() < 0.2) pairs.insert(pairs.end(), {i, j});
  const EdgeGraph g =
      build_edge_graph(n, Eigen::Map<const Eigen::Matrix<int, Eigen::Dynamic, 2, Eigen::RowMajor>>(
                              pairs.data(), Eigen::Index(pairs.size() / 2), 2));
  const NeighborLengths lengths = neighbor_lengths(g, P);
  ASSERT_GT(lengths.shortest, 0);
  NeighborLengths heap_only = lengths;
  heap_only.shortest = 0;
  for (int source : {0, 17, 399}) {
    std::vector<double> buckets, heap;
    graph_geodesics(g, lengths, source, &buckets);
    graph_geodesics(g, heap_only, source, &heap);
    EXPECT_EQ(buckets, heap) << "source " << source;
    // A shortest path: no edge shortens any distance.
    for (int i = 0; i < n; ++i)
      for (int k = g.offsets[size_t(i)]; k < g.offsets[size_t(i) + 1]; ++k)
        EXPECT_LE(buckets[size_t(g.neighbors[size_t(k)])],
                  buckets[size_t(i)] + lengths.arcs[size_t(k)].length + 1e-15);
  }
}

TEST(MetricGeodesic, ZeroWhenEuclideanEqualsGeodesic) {
  const Path path = straight_path(50);
  const GeodesicError e = geodesic_error(path.graph, path.P, path.P);
  EXPECT_TRUE(e.exact);
  EXPECT_EQ(e.sources_used, 50);
  EXPECT_LT(e.value, 1e-6);
}

TEST(MetricGeodesic, InvariantToRigidMotionAndUniformScaleOfQ) {
  std::mt19937 rng(11);
  const Path path = straight_path(60);
  Eigen::MatrixX3d bent = path.P;  // fold the path into an arc
  for (int i = 0; i < 60; ++i)
    bent.row(i) << 20 * std::cos(path.P(i, 0) / 20), 20 * std::sin(path.P(i, 0) / 20), 0;
  const double value = geodesic_error(path.graph, path.P, bent).value;
  EXPECT_GT(value, 0.01);
  EXPECT_NEAR(geodesic_error(path.graph, path.P, 3.0 * rigidly_moved(bent, rng)).value, value,
              1e-9);
}

TEST(MetricGeodesic, LandmarkEstimateApproximatesExact) {
  const EdgeGraph g = grid_tet_graph(12, 10, 8);
  const Eigen::MatrixX3d P = grid_points(12, 10, 8);
  const Eigen::MatrixX3d Q = P + 0.5 * (0.4 * P).array().sin().matrix();
  const GeodesicError exact = geodesic_error(g, P, Q);
  GeodesicErrorOptions options;
  options.exact_limit = 100;
  options.sources = 200;
  const GeodesicError estimate = geodesic_error(g, P, Q, options);
  EXPECT_TRUE(exact.exact);
  EXPECT_FALSE(estimate.exact);
  EXPECT_EQ(estimate.sources_used, 200);
  EXPECT_NEAR(estimate.value, exact.value, 0.1 * exact.value);
  EXPECT_EQ(geodesic_error(g, P, Q, options).value, estimate.value);
}

// The split the pipeline uses to compute G during the solve: the same value,
// standard error and sources as the one-pass function, bit for bit.
TEST(MetricGeodesic, PrecomputedRowsGiveTheOnePassResultExactly) {
  const EdgeGraph g = grid_tet_graph(12, 10, 8);
  const Eigen::MatrixX3d P = grid_points(12, 10, 8);
  const Eigen::MatrixX3d Q = P + 0.5 * (0.4 * P).array().sin().matrix();
  for (int exact_limit : {100, 5000}) {
    GeodesicErrorOptions options;
    options.exact_limit = exact_limit;
    options.sources = 50;
    const GeodesicError one_pass = geodesic_error(g, P, Q, options);
    const GeodesicRows rows = geodesic_error_precomputation(g, P, options);
    const GeodesicError split = geodesic_error_solve(rows, Q);
    EXPECT_EQ(split.value, one_pass.value);
    EXPECT_EQ(split.standard_error, one_pass.standard_error);
    EXPECT_EQ(split.sources_used, one_pass.sources_used);
    EXPECT_EQ(split.exact, one_pass.exact);
    EXPECT_EQ(rows.G.rows(), exact_limit == 100 ? 50 : P.rows());
  }
  EXPECT_THROW(geodesic_error_solve(geodesic_error_precomputation(g, P), Q.topRows(10)),
               UsageError);
}

// Over a surface alone: the graph function on the faces' edges, the same for a
// similarity of the deformed surface, NaN where the faces fall apart.
TEST(MetricGeodesic, OverASurfaceAlone) {
  const SurfaceMesh sphere = test::uv_sphere(8, 12);
  const Eigen::MatrixX3i F = triangulate_faces(sphere);
  Eigen::MatrixX3d bent = sphere.V;
  for (Eigen::Index i = 0; i < bent.rows(); ++i) bent(i, 2) += 0.5 * bent(i, 0) * bent(i, 0);
  const double value = surface_geodesic_error(sphere.V, F, bent).value;
  EXPECT_EQ(value, geodesic_error(build_edge_graph(int(sphere.V.rows()), Eigen::MatrixXi(F)),
                                  sphere.V, bent)
                       .value);
  EXPECT_GT(value, surface_geodesic_error(sphere.V, F, sphere.V).value);
  std::mt19937 rng(5);
  EXPECT_NEAR(surface_geodesic_error(sphere.V, F, 2.5 * rigidly_moved(bent, rng)).value, value,
              1e-12);
  // Its rows made first (as beside a solve): the same value, bit for bit.
  EXPECT_EQ(
      surface_geodesic_error_solve(surface_geodesic_error_precomputation(sphere.V, F), bent).value,
      value);
  // Two spheres side by side: their faces' edges join no vertex of one to the other.
  Eigen::MatrixX3d two(2 * sphere.V.rows(), 3);
  two << sphere.V, sphere.V.rowwise() + Eigen::RowVector3d(3, 0, 0);
  Eigen::MatrixXi both(2 * F.rows(), 3);
  both << F, F.array() + int(sphere.V.rows());
  EXPECT_TRUE(std::isnan(surface_geodesic_error(two, both, two).value));
  EXPECT_TRUE(surface_geodesic_error_precomputation(two, both).sources.empty());
  EXPECT_TRUE(std::isnan(
      surface_geodesic_error_solve(surface_geodesic_error_precomputation(two, both), two).value));
  EXPECT_THROW(surface_geodesic_error(sphere.V, F, bent.topRows(3)), UsageError);
}

TEST(MetricGeodesic, RejectsDisconnectedGraph) {
  Eigen::MatrixXi edges(1, 2);
  edges << 0, 1;
  const EdgeGraph g = build_edge_graph(3, edges);
  const Eigen::MatrixX3d P = grid_points(3, 1, 1);
  EXPECT_THROW(geodesic_error(g, P, P), InputError);
  EXPECT_THROW(geodesic_error(g, P, P.topRows(2)), UsageError);
  EXPECT_THROW(geodesic_error_precomputation(g, P), InputError);
}

TEST(MetricEdgeRatio, EqualsUniformScale) {
  std::mt19937 rng(5);
  const EdgeGraph g = grid_tet_graph(3, 4, 5);
  const Eigen::MatrixX3d P = grid_points(3, 4, 5);
  EXPECT_NEAR(edge_ratio(g, P, 1.25 * rigidly_moved(P, rng)), 1.25, 1e-12);
  EXPECT_NEAR(edge_ratio(g, P, P), 1.0, 1e-15);
  // With the rest lengths computed once, as the solver does.
  Eigen::MatrixX3d bent = P;
  bent.col(2) += 0.1 * P.col(0).cwiseProduct(P.col(0));
  EXPECT_NEAR(edge_ratio(g, edge_lengths(g, P), bent), edge_ratio(g, P, bent), 1e-14);
  Eigen::MatrixX3d collapsed = P;
  collapsed.row(1) = collapsed.row(0);  // an edge of zero rest length
  EXPECT_THROW(edge_lengths(g, collapsed), InputError);
}

TEST(MetricRigidAlignment, ZeroForRigidCopy) {
  std::mt19937 rng(9);
  const Eigen::MatrixX3d A = random_points(100, 6);
  const Eigen::MatrixX3d B = rigidly_moved(A, rng);
  EXPECT_LT(aligned_distance(A, B), 1e-10);
  const RigidAlignment fit = align_rigidly(A, B);
  EXPECT_LT((fit.aligned - A).cwiseAbs().maxCoeff(), 1e-10);
  EXPECT_NEAR(fit.R.determinant(), 1.0, 1e-12);
}

TEST(MetricRigidAlignment, KnownValueForScaleAndReflection) {
  std::mt19937 rng(10);
  const Eigen::MatrixX3d A = random_points(80, 8);
  // A uniform scale about the centroid is best aligned by the identity: each
  // point stays off by |s - 1| times its distance to the centroid.
  const Eigen::RowVector3d c = A.colwise().mean();
  const Eigen::MatrixX3d scaled = ((1.5 * (A.rowwise() - c)).rowwise() + c);
  const double expected = 0.5 * (A.rowwise() - c).rowwise().norm().mean();
  EXPECT_NEAR(aligned_distance(A, rigidly_moved(scaled, rng)), expected, 1e-10);
  // A mirror image cannot be undone by a rotation.
  const Eigen::MatrixX3d mirrored = A * Eigen::Vector3d(-1, 1, 1).asDiagonal();
  const RigidAlignment fit = align_rigidly(A, mirrored);
  EXPECT_NEAR(fit.R.determinant(), 1.0, 1e-12);
  EXPECT_GT(fit.mean_distance, 0.05);
  EXPECT_THROW(aligned_distance(A, A.topRows(3)), UsageError);
}

}  // namespace
}  // namespace unfold
