// The two backends minimise the same energy: at one fixed beta, run to
// convergence, they reach the same final energy; user pair constraints and the
// volume term do what they promise.
#include <gtest/gtest.h>

#include <fstream>
#include <map>

#include "config/options.h"
#include "core/errors.h"
#include "mesh/read_surface_mesh.h"
#include "pipeline/compare_configs.h"
#include "pipeline/unfold_surface.h"
#include "shapes/articulated_shape.h"
#include "solvers/make_backend.h"
#include "test_meshes.h"
#include "test_problem.h"

namespace unfold {
namespace {

const std::string kConfigs = UNFOLD_SOURCE_DIR "/configs/";

void expect_backends_agree(const SurfaceMesh& surface) {
  const auto rows =
      compare_configs(surface, {kConfigs + "paper.yaml", kConfigs + "ceres.yaml"}, 4.0);
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0].config, "paper");
  EXPECT_EQ(rows[1].config, "ceres");
  EXPECT_LT(std::abs(rows[0].final_energy - rows[1].final_energy),
            0.01 * std::abs(rows[0].final_energy))
      << format_comparison(rows);
  EXPECT_LT(rows[0].final_energy, 0);
}

TEST(BackendCompare, FixedBetaEnergiesAgreeOnTheDemoShape) {
  expect_backends_agree(make_articulated_shape(ShapePose::preset(1), 32));
}

TEST(BackendCompare, FixedBetaEnergiesAgreeOnWolf0) {
  const std::string path = test::shared_data("tosca/wolf0.off");
  if (path.empty()) GTEST_SKIP() << "shared data absent: tosca/wolf0.off";
  expect_backends_agree(read_surface_mesh(path));
}

TEST(BackendCascade, CeresUnfoldsWithEnergyPerCascade) {
  const Options options = load_options(kConfigs + "ceres.yaml");
  const UnfoldResult r = unfold_surface(make_articulated_shape(ShapePose::preset(0), 32), options);
  EXPECT_TRUE(r.cascade.reached_band);
  EXPECT_LT(r.metrics.E_rig, 1.0);
  EXPECT_GT(r.metrics.E_str, 0.05);
  ASSERT_FALSE(r.cascade.history.empty());
  EXPECT_EQ(r.cascade.history.back().cascade, r.cascade.cascades);
  for (size_t k = 1; k < r.cascade.history.size(); ++k) {
    EXPECT_GE(r.cascade.history[k].cascade, r.cascade.history[k - 1].cascade);
    if (r.cascade.history[k].cascade == r.cascade.history[k - 1].cascade) {  // L-BFGS descends
      EXPECT_LE(r.cascade.history[k].energy, r.cascade.history[k - 1].energy);
    }
  }
}

TEST(BackendUserControl, PairsReachTheirTargetsAndRigidityHolds) {
  // configs/demo_pairs.csv: front feet and hind feet side by side.
  const SurfaceMesh shape = make_articulated_shape(ShapePose::preset(0));
  const Options defaults;
  const UnfoldResult free = unfold_surface(shape, defaults);
  const Options options = load_options(kConfigs + "user_control.yaml");
  const UnfoldResult held = unfold_surface(shape, options);
  const struct {
    int i, j;
    Eigen::RowVector3d t;
  } pairs[] = {{538, 34, {0, 1.17, 0}}, {117, 290, {0, 1.04, 0}}};
  for (const auto& p : pairs) {
    const Eigen::RowVector3d before = free.canonical.V.row(p.i) - free.canonical.V.row(p.j);
    const Eigen::RowVector3d after = held.canonical.V.row(p.i) - held.canonical.V.row(p.j);
    EXPECT_GT((before - p.t).norm(), 0.05 * p.t.norm()) << "the pair was already in place";
    EXPECT_LT((after - p.t).norm(), 0.05 * p.t.norm()) << p.i << "-" << p.j << ": " << after;
  }
  EXPECT_LT(held.metrics.E_rig, 1.2 * free.metrics.E_rig);
}

TEST(BackendUserControl, BadPairsFileIsAnInputError) {
  const std::string path = ::testing::TempDir() + "pairs.csv";
  std::ofstream(path) << "0, 999999, 1, 0, 0\n";
  Options options;
  options.energy.user_pairs_file = path;
  try {
    unfold_surface(make_articulated_shape(ShapePose::rest(), 32), options);
    FAIL() << "an out-of-range pair index was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("999999"), std::string::npos) << e.what();
  }
}

TEST(BackendVolume, NoInvertedTetrahedraOnWolf0) {
  const std::string path = test::shared_data("tosca/wolf0.off");
  if (path.empty()) GTEST_SKIP() << "shared data absent: tosca/wolf0.off";
  const SurfaceMesh wolf = read_surface_mesh(path);
  // Untangling off in both: the solves' own inversions, which it would mend after them.
  const std::map<std::string, std::string> no_untangling = {{"untangle.sweeps", "0"}};
  const UnfoldResult plain = unfold_surface(wolf, load_options("", no_untangling));
  const UnfoldResult held =
      unfold_surface(wolf, load_options(kConfigs + "volume.yaml", no_untangling));
  EXPECT_GT(plain.metrics.inverted_tets, 0) << "nothing for the volume term to fix";
  EXPECT_EQ(held.metrics.inverted_tets, 0);
  EXPECT_TRUE(held.cascade.reached_band);
}

TEST(BackendVolume, RefusedByLocalGlobal) {
  EXPECT_THROW(load_options("", {{"volume.weight", "1"}, {"domain", "volume"}}), UsageError);
  EXPECT_NO_THROW(
      load_options("", {{"volume.weight", "1"}, {"method", "ceres"}, {"domain", "volume"}}));
}

TEST(BackendSupport, LocalGlobalRefusesANonQuadraticTermByName) {
  EnergyOptions energy;
  energy.volume_weight = 1;
  const test::ProblemFixture f(test::grid_tet_mesh(2, 1, 1), energy);
  BackendOptions options;
  try {
    make_backend(options, f.problem);
    FAIL() << "local_global accepted the volume term";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("volume"), std::string::npos) << e.what();
  }
  options.method = "ceres";
  EXPECT_NE(make_backend(options, f.problem), nullptr);
}

}  // namespace
}  // namespace unfold
