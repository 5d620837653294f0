// The LSMDS baseline: SMACOF recovers a shape from its own distances (exact
// and landmark variants), the stress never increases across Guttman
// transforms, and method: lsmds runs through the pipeline.
#include "solvers/lsmds.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "config/options.h"
#include "core/errors.h"
#include "metrics/rigid_alignment.h"
#include "pipeline/unfold_surface.h"
#include "shapes/articulated_shape.h"
#include "test_meshes.h"

namespace unfold {
namespace {

// Rows of Euclidean distances from the given sources: the geodesics of a convex shape.
LandmarkDistances euclidean_rows(const Eigen::MatrixX3d& P, const std::vector<int>& sources) {
  LandmarkDistances d;
  d.landmarks = sources;
  d.rows.resize(Eigen::Index(sources.size()), P.rows());
  for (size_t a = 0; a < sources.size(); ++a)
    for (Eigen::Index j = 0; j < P.rows(); ++j)
      d.rows(Eigen::Index(a), j) = (P.row(sources[a]) - P.row(j)).norm();
  return d;
}

// A flat-ish convex slab, and the same slab bent (the "pose" to unfold).
struct Slab {
  TetMesh mesh = test::grid_tet_mesh(6, 4, 1, 1.0);
  Eigen::MatrixX3d bent;
  Slab() {
    bent = mesh.V;
    for (Eigen::Index i = 0; i < bent.rows(); ++i) bent(i, 2) += 0.08 * bent(i, 0) * bent(i, 0);
  }
};

void expect_recovers(const LandmarkDistances& d, const Slab& s) {
  LsmdsOptions options;
  options.max_iterations = 3000;
  options.tolerance = 1e-10;
  const LsmdsResult r = smacof(d, s.bent, options);
  const double scale = d.rows.squaredNorm();
  EXPECT_LT(r.stress.back(), 1e-8 * scale)
      << "stress " << r.stress.front() << " -> " << r.stress.back();
  EXPECT_LT(aligned_distance(s.mesh.V, r.positions), 1e-3);
  EXPECT_NEAR(r.positions.colwise().mean().norm(), 0, 1e-9);
}

TEST(Lsmds, ExactRecoversAConvexShapeUpToRigidMotion) {
  Slab s;
  std::vector<int> all(size_t(s.mesh.V.rows()));
  for (size_t i = 0; i < all.size(); ++i) all[i] = int(i);
  const LandmarkDistances d = euclidean_rows(s.mesh.V, all);
  expect_recovers(d, s);
  EXPECT_TRUE(smacof(d, s.bent, LsmdsOptions{}).exact);
}

TEST(Lsmds, LandmarkVariantRecoversAConvexShapeUpToRigidMotion) {
  Slab s;
  const LandmarkDistances d = euclidean_rows(s.mesh.V, {0, 6, 28, 34, 40, 69, 17});
  expect_recovers(d, s);
  EXPECT_FALSE(smacof(d, s.bent, LsmdsOptions{}).exact);
}

TEST(Lsmds, StressNeverIncreasesAcrossGuttmanTransforms) {
  const TetMesh mesh = test::grid_tet_mesh(5, 3, 2, 0.5);
  const EdgeGraph graph = build_edge_graph(int(mesh.V.rows()), mesh.T);
  for (const int exact_limit : {1000, 0}) {
    LsmdsOptions options;
    options.exact_limit = exact_limit;
    options.landmarks = 12;
    options.tolerance = 0;  // every transform, up to max_iterations
    options.max_iterations = 200;
    const LandmarkDistances d = lsmds_distances(graph, mesh.V, options);
    EXPECT_EQ(d.landmarks.size(), exact_limit > 0 ? size_t(mesh.V.rows()) : size_t(12));
    std::srand(11);
    const Eigen::MatrixX3d start = mesh.V + 0.4 * Eigen::MatrixX3d::Random(mesh.V.rows(), 3);
    const LsmdsResult r = smacof(d, start, options);
    ASSERT_GE(r.stress.size(), size_t(2));
    for (size_t k = 1; k < r.stress.size(); ++k)
      ASSERT_LE(r.stress[k], r.stress[k - 1] * (1 + 1e-12)) << "iteration " << k;
    EXPECT_LT(r.stress.back(), 0.5 * r.stress.front());
  }
}

TEST(Lsmds, FarthestPointLandmarksAreDistinct) {
  const TetMesh mesh = test::grid_tet_mesh(4, 4, 2);
  const EdgeGraph graph = build_edge_graph(int(mesh.V.rows()), mesh.T);
  LsmdsOptions options;
  options.exact_limit = 0;
  options.landmarks = 20;
  std::vector<int> l = lsmds_distances(graph, mesh.V, options).landmarks;
  std::sort(l.begin(), l.end());
  EXPECT_EQ(std::unique(l.begin(), l.end()), l.end());
}

TEST(Baselines, LsmdsAndDpmuRunThroughThePipeline) {
  const SurfaceMesh pose = make_articulated_shape(ShapePose::preset(1), 32);
  const Options defaults;
  const PreparedMesh prepared = prepare_mesh(pose, defaults);
  Options lsmds_options;
  lsmds_options.method = "lsmds";
  const UnfoldResult l = unfold_prepared(prepared, lsmds_options);
  EXPECT_GT(l.cascade.iterations, 0);
  ASSERT_EQ(l.cascade.history.size(), size_t(l.cascade.iterations));
  EXPECT_DOUBLE_EQ(l.cascade.history.back().energy, l.cascade.final_energy);
  EXPECT_DOUBLE_EQ(l.cascade.history.back().edge_ratio, l.cascade.edge_ratio);
  EXPECT_TRUE(l.canonical.V.allFinite());
  EXPECT_GT(l.metrics.E_rig, 0);
  // LSMDS keeps geodesics as Euclidean distances: the geodesic error is small.
  EXPECT_LT(l.metrics.E_geo, 0.1);

  Options dpmu = paper_options();  // DPMU is a tet-mesh method
  dpmu.method = "dpmu";
  dpmu.energy.arap_weight = 0;
  dpmu.energy.edge_length_weight = 1;
  dpmu.energy.volume_weight = 1;
  const UnfoldResult d = unfold_prepared(prepared, dpmu);
  EXPECT_TRUE(d.cascade.bounded);  // the springs bound the stretch like ARAP
  EXPECT_TRUE(d.canonical.V.allFinite());
  EXPECT_EQ(d.metrics.inverted_tets, 0);
}

TEST(Baselines, DpmuNeedsItsTerms) {
  Options o;
  o.method = "dpmu";
  EXPECT_THROW(validate_options(o), UsageError);
}

}  // namespace
}  // namespace unfold
