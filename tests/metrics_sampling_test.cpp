// The sampled estimators used above the exact limits: their reported
// standard errors bound the distance to the exact value (the documented bound,
// docs/performance.md), and they are positive.
#include <gtest/gtest.h>

#include <cmath>

#include "metrics/geodesic_error.h"
#include "metrics/stretch_error.h"
#include "test_meshes.h"

namespace unfold {
namespace {

struct Bent {
  TetMesh mesh = test::grid_tet_mesh(12, 4, 3, 0.5);
  EdgeGraph graph = build_edge_graph(int(mesh.V.rows()), mesh.T);
  Eigen::MatrixX3d Q = [this] {
    Eigen::MatrixX3d q = mesh.V;
    for (Eigen::Index i = 0; i < q.rows(); ++i) q(i, 1) += 0.2 * q(i, 0) * q(i, 0);
    return q;
  }();
};

TEST(MetricsSampling, GeodesicEstimateWithinFourStandardErrors) {
  Bent b;
  const GeodesicError exact = geodesic_error(b.graph, b.mesh.V, b.Q);
  ASSERT_TRUE(exact.exact);
  EXPECT_EQ(exact.standard_error, 0);
  GeodesicErrorOptions sampled;
  sampled.exact_limit = 0;
  sampled.sources = 40;
  const GeodesicError estimate = geodesic_error(b.graph, b.mesh.V, b.Q, sampled);
  EXPECT_FALSE(estimate.exact);
  EXPECT_GT(estimate.standard_error, 0);
  EXPECT_LT(std::abs(estimate.value - exact.value), 4 * estimate.standard_error);
}

TEST(MetricsSampling, StretchEstimateWithinFourStandardErrors) {
  Bent b;
  const StretchError exact = stretch_error(b.mesh.V, b.Q);
  ASSERT_TRUE(exact.exact);
  StretchErrorOptions sampled;
  sampled.exact_limit = 0;
  sampled.sample_pairs = 5000;
  const StretchError estimate = stretch_error(b.mesh.V, b.Q, sampled);
  EXPECT_GT(estimate.standard_error, 0);
  EXPECT_LT(std::abs(estimate.value - exact.value), 4 * estimate.standard_error);
}

}  // namespace
}  // namespace unfold
