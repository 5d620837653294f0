// The coarse surface solve (simplify.surface_solve_vertices): the clusters of
// mesh/coarsen_surface.h and their solution carried back to every vertex
// (solvers/prolong_surface_solve.h).
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "core/errors.h"
#include "mesh/coarsen_surface.h"
#include "mesh/lumped_masses.h"
#include "solvers/prolong_surface_solve.h"
#include "tests/test_meshes.h"

namespace unfold {
namespace {

TEST(CoarsenSurface, ConnectedClustersOfTheWholeArea) {
  const SurfaceMesh sphere = test::uv_sphere(60, 60);
  const int n = int(sphere.V.rows());
  const SurfaceCoarsening c = coarsen_surface(sphere, 2);
  const int count = int(c.V.rows());
  // Two hops on a mesh of degree six: clusters of up to 19 vertices, fewer
  // where the greedy order leaves fragments.
  EXPECT_LT(count, n / 5);
  EXPECT_GT(count, n / 19);
  EXPECT_LT(coarsen_surface(sphere, 3).V.rows(), count);
  ASSERT_EQ(int(c.cluster_of.size()), n);
  EXPECT_EQ(c.graph.num_vertices, count);
  EXPECT_EQ(connected_components(c.graph), 1);
  EXPECT_NEAR(c.masses.sum(), lumped_masses(sphere.V, triangulate_faces(sphere)).sum(), 1e-9);
  // Each cluster is connected along the surface's own edges.
  const EdgeGraph fine = build_edge_graph(n, Eigen::MatrixXi(triangulate_faces(sphere)));
  std::vector<Eigen::Vector2i> inside;
  for (int e = 0; e < fine.num_edges(); ++e)
    if (c.cluster_of[size_t(fine.edges(e, 0))] == c.cluster_of[size_t(fine.edges(e, 1))])
      inside.emplace_back(fine.edges(e, 0), fine.edges(e, 1));
  Eigen::MatrixXi elements(Eigen::Index(inside.size()), 2);
  for (size_t k = 0; k < inside.size(); ++k) elements.row(Eigen::Index(k)) = inside[k].transpose();
  EXPECT_EQ(connected_components(build_edge_graph(n, elements)), count);
  // Centroids of clusters on a unit sphere lie just inside it.
  for (int k = 0; k < count; ++k) {
    EXPECT_LE(c.V.row(k).norm(), 1.0 + 1e-12);
    EXPECT_GT(c.V.row(k).norm(), 0.9);
  }
}

// The clusters follow the connectivity alone: a pose (here a bend and a
// squash) gets the same coarse graph.
TEST(CoarsenSurface, ADeformationGivesTheSameClusters) {
  const SurfaceMesh sphere = test::uv_sphere(30, 40);
  SurfaceMesh bent = sphere;
  for (Eigen::Index i = 0; i < bent.V.rows(); ++i) {
    const double y = sphere.V(i, 1);
    bent.V.row(i) = Eigen::RowVector3d(sphere.V(i, 0) + 0.4 * std::sin(3 * y), 0.5 * y,
                                       sphere.V(i, 2) + 0.2 * y * y);
  }
  const SurfaceCoarsening a = coarsen_surface(sphere, 2), b = coarsen_surface(bent, 2);
  EXPECT_EQ(a.cluster_of, b.cluster_of);
  EXPECT_EQ(a.graph.edges, b.graph.edges);
}

TEST(CoarsenSurface, ClustersStayWithinAComponentAndHopsMustBePositive) {
  SurfaceMesh two = test::octahedron();
  const SurfaceMesh other = test::octahedron();
  const int offset = int(two.V.rows());
  two.V.conservativeResize(2 * offset, 3);
  two.V.bottomRows(offset) = other.V.rowwise() + Eigen::RowVector3d(5, 0, 0);
  for (std::vector<int> face : other.faces) {
    for (int& v : face) v += offset;
    two.faces.push_back(face);
  }
  const SurfaceCoarsening c = coarsen_surface(two, 5);
  EXPECT_EQ(c.V.rows(), 2);
  EXPECT_EQ(c.graph.num_edges(), 0);
  for (int i = 0; i < offset; ++i) {
    EXPECT_EQ(c.cluster_of[size_t(i)], 0);
    EXPECT_EQ(c.cluster_of[size_t(offset + i)], 1);
  }
  EXPECT_THROW(coarsen_surface(two, 0), UsageError);
}

// A coarse solution that is one similarity of the clusters' rest positions
// (turned, scaled by 2.5, moved) is carried to the same similarity of every vertex.
TEST(ProlongSurfaceSolve, RecoversASimilarityOfTheWholeSurface) {
  const SurfaceMesh sphere = test::uv_sphere(40, 40);
  const int n = int(sphere.V.rows());
  const SurfaceCoarsening c = coarsen_surface(sphere, 2);
  const Eigen::Matrix3d R = test::random_rotation(11);
  const Eigen::MatrixX3d Sc = (2.5 * c.V * R.transpose()).rowwise() + Eigen::RowVector3d(1, 2, 3);
  const EdgeGraph graph = build_edge_graph(n, Eigen::MatrixXi(triangulate_faces(sphere)));
  const Eigen::MatrixX3d S = prolong_surface_solve(graph, sphere.V, c, Sc);
  const Eigen::MatrixX3d centred = sphere.V.rowwise() - sphere.V.colwise().mean();
  const Eigen::MatrixX3d expected = 2.5 * centred * R.transpose();
  EXPECT_LT((S - expected).cwiseAbs().maxCoeff(), 1e-8);
}

// The CG route (large surfaces) solves the factor route's systems: from a
// coarse solution that bends the surface (each cluster turned by its own
// angle), the two agree to CG's tolerance, and the CG route too recovers a
// whole-surface similarity.
TEST(ProlongSurfaceSolve, TheCgRouteAgreesWithTheFactor) {
  const SurfaceMesh sphere = test::uv_sphere(40, 40);
  const int n = int(sphere.V.rows());
  const SurfaceCoarsening c = coarsen_surface(sphere, 2);
  const EdgeGraph graph = build_edge_graph(n, Eigen::MatrixXi(triangulate_faces(sphere)));
  Eigen::MatrixX3d bent = c.V;
  for (Eigen::Index k = 0; k < bent.rows(); ++k)
    bent.row(k) =
        c.V.row(k) *
        Eigen::AngleAxisd(0.8 * c.V(k, 2), Eigen::Vector3d::UnitZ()).toRotationMatrix().transpose();
  const Eigen::MatrixX3d by_factor = prolong_surface_solve(graph, sphere.V, c, bent, n + 1);
  const Eigen::MatrixX3d by_cg = prolong_surface_solve(graph, sphere.V, c, bent, 0);
  const double radius = std::sqrt(by_factor.rowwise().squaredNorm().mean());
  const double apart = (by_cg - by_factor).rowwise().norm().maxCoeff() / radius;
  EXPECT_GT((by_factor - sphere.V).cwiseAbs().maxCoeff(), 0.1 * radius);  // it did bend
  EXPECT_LT(apart, 1e-4);
  EXPECT_GT(apart, 0);  // two routes, not one

  const Eigen::Matrix3d R = test::random_rotation(5);
  const Eigen::MatrixX3d Sc = (2.5 * c.V * R.transpose()).rowwise() + Eigen::RowVector3d(1, 2, 3);
  const Eigen::MatrixX3d S = prolong_surface_solve(graph, sphere.V, c, Sc, 0);
  const Eigen::MatrixX3d centred = sphere.V.rowwise() - sphere.V.colwise().mean();
  EXPECT_LT((S - 2.5 * centred * R.transpose()).cwiseAbs().maxCoeff(), 1e-6);
}

TEST(ProlongSurfaceSolve, MismatchedSizesAreUsageErrors) {
  const SurfaceMesh sphere = test::uv_sphere(10, 10);
  const SurfaceCoarsening c = coarsen_surface(sphere, 1);
  const EdgeGraph graph =
      build_edge_graph(int(sphere.V.rows()), Eigen::MatrixXi(triangulate_faces(sphere)));
  EXPECT_THROW(prolong_surface_solve(graph, sphere.V, c, Eigen::MatrixX3d::Zero(3, 3)), UsageError);
}

}  // namespace
}  // namespace unfold
