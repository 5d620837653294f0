// Config loading: defaults, the shipped default.yaml, overrides, and errors
// that name the key.
#include <gtest/gtest.h>

#include <fstream>

#include "config/options.h"
#include "core/errors.h"

namespace unfold {
namespace {

// Named after the running test as well: ctest runs the tests of this file in
// parallel processes, which would otherwise write one another's file.
std::string write_temp(const std::string& name, const std::string& text) {
  const std::string path = ::testing::TempDir() + "/" +
                           ::testing::UnitTest::GetInstance()->current_test_info()->name() + "_" +
                           name;
  std::ofstream(path) << text;
  return path;
}

void expect_usage_error(const std::string& yaml, const std::string& words) {
  const std::string path = write_temp("config.yaml", yaml);
  try {
    load_options(path);
    FAIL() << "no error for: " << yaml;
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
  }
}

TEST(Config, ShippedDefaultEqualsBuiltInDefaults) {
  const Options shipped = load_options(UNFOLD_SOURCE_DIR "/configs/default.yaml");
  const Options defaults;
  EXPECT_EQ(options_to_yaml(shipped), options_to_yaml(defaults));
  EXPECT_NE(options_to_yaml(shipped).find("k_iter: 300"), std::string::npos);
  EXPECT_NE(options_to_yaml(shipped).find("shape: auto"), std::string::npos);
  EXPECT_NE(options_to_yaml(shipped).find("edge_ratio_band: [0.95, 1.05]"), std::string::npos);
}

// configs/fast.yaml is the default with the squared spread (as it was until
// 2026-12-04), the coarse surface solve and the pose pull.
TEST(Config, FastIsTheDefaultWithACoarseSolveAndAPosePull) {
  const Options fast = load_options(UNFOLD_SOURCE_DIR "/configs/fast.yaml");
  Options expected;
  expected.energy.stretch_weight = 1;
  expected.energy.stretch_distance = 0;
  expected.energy.stretch_mass_power = 1;
  expected.surface_solve_hops = 1;
  expected.integrate.anchor = 40;
  expected.integrate.pose_pull = 0.2;
  EXPECT_EQ(options_to_yaml(fast), options_to_yaml(expected));
}

// configs/splayed.yaml is the default with the squared spread (as it was until
// 2026-12-04), the local spread and a mass power; configs/squared_spread.yaml
// the default with the squared spread alone.
TEST(Config, SplayedIsTheDefaultWithALocalSpread) {
  const Options squared = load_options(UNFOLD_SOURCE_DIR "/configs/squared_spread.yaml");
  Options expected;
  expected.energy.stretch_weight = 1;
  expected.energy.stretch_distance = 0;
  expected.energy.stretch_mass_power = 1;
  EXPECT_EQ(options_to_yaml(squared), options_to_yaml(expected));
  const Options splayed = load_options(UNFOLD_SOURCE_DIR "/configs/splayed.yaml");
  expected.energy.stretch_mass_power = 0.35;
  expected.energy.stretch_local = 0.8;
  expected.energy.stretch_local_radius = 0.3;
  expected.energy.stretch_local_regions = 32;
  EXPECT_EQ(options_to_yaml(splayed), options_to_yaml(expected));
}

// base: paper starts a config from the paper's parameters: paper.yaml lists
// them all and equals paper_options(); a config of one key over base: paper
// differs from it in that key alone.
TEST(Config, BasePaperStartsFromThePapersParameters) {
  const Options paper = load_options(UNFOLD_SOURCE_DIR "/configs/paper.yaml");
  EXPECT_EQ(options_to_yaml(paper), options_to_yaml(paper_options()));
  EXPECT_NE(options_to_yaml(paper), options_to_yaml(Options{}));
  const Options surface = load_options(UNFOLD_SOURCE_DIR "/configs/surface.yaml");
  Options expected = paper_options();
  expected.domain = "surface";
  EXPECT_EQ(options_to_yaml(surface), options_to_yaml(expected));
  expect_usage_error("base: sketch\n", "base");
}

TEST(Config, PaperConfigIsThePapersMethod) {
  const Options paper = load_options(UNFOLD_SOURCE_DIR "/configs/paper.yaml");
  EXPECT_EQ(paper.method, "local_global");
  EXPECT_EQ(paper.domain, "volume");
  EXPECT_EQ(paper.energy.arap_weights, "uniform");
  EXPECT_TRUE(paper.cascade.break_in_band);
  EXPECT_EQ(paper.cascade.anderson, 0);
  EXPECT_EQ(paper.cascade.k_iter, 15);
  EXPECT_EQ(paper.cascade.num_cascades, 4);
  EXPECT_EQ(paper.cascade.growth, 2.0);
  EXPECT_EQ(paper.energy.stretch_weight, 1.0);
  EXPECT_EQ(paper.energy.arap_weight, 1.0);
  EXPECT_EQ(paper.soften.scale, 0.0);             // one solve, the joints as stiff as the limbs
  EXPECT_EQ(paper.integrate.surface_edges, 0.0);  // no integration, the tets' edges alone
  EXPECT_EQ(load_options(UNFOLD_SOURCE_DIR "/configs/surface.yaml").domain, "surface");
}

TEST(Config, EffectiveYamlRoundTrips) {
  Options o;
  o.cascade.k_iter = 7;
  o.cascade.edge_ratio_band = {0.9, 1.1};
  o.beta_mode = "absolute";
  o.beta_value = 5e5;
  const std::string path = write_temp("roundtrip.yaml", options_to_yaml(o));
  EXPECT_EQ(options_to_yaml(load_options(path)), options_to_yaml(o));
}

TEST(Config, OverridesWinOverTheFile) {
  const std::string path = write_temp("k.yaml", "cascade:\n  k_iter: 9\n");
  const Options o = load_options(
      path,
      {{"cascade.k_iter", "20"}, {"cascade.edge_ratio_band", "0.9,1.2"}, {"beta.value", "2.5"}});
  EXPECT_EQ(o.cascade.k_iter, 20);
  EXPECT_EQ(o.cascade.edge_ratio_band[0], 0.9);
  EXPECT_EQ(o.cascade.edge_ratio_band[1], 1.2);
  EXPECT_EQ(o.beta_value, 2.5);
}

TEST(Config, ErrorsNameTheKey) {
  expect_usage_error("cascade:\n  kiter: 3\n", "unknown config key 'cascade.kiter'");
  expect_usage_error("cascade:\n  k_iter: abc\n", "'cascade.k_iter' must be an integer");
  expect_usage_error("cascade:\n  k_iter: 2.5\n", "'cascade.k_iter' must be an integer");
  expect_usage_error("cascade:\n  k_iter: 0\n", "'cascade.k_iter' must be at least 1");
  expect_usage_error("beta:\n  value: -1\n", "'beta.value' must be a positive");
  expect_usage_error("beta:\n  value: .nan\n", "'beta.value' must be a positive");
  expect_usage_error("beta:\n  mode: sideways\n", "'beta.mode' must be relative or absolute");
  expect_usage_error("cascade:\n  edge_ratio_band: [1.1, 0.9]\n", "'cascade.edge_ratio_band'");
  expect_usage_error("soften:\n  scale: -1\n", "'soften.scale' must be >= 0");
  expect_usage_error("soften:\n  floor: 0\n", "'soften.floor' must be in (0, 1]");
  expect_usage_error("soften:\n  floor: 1.5\n", "'soften.floor' must be in (0, 1]");
  expect_usage_error("soften:\n  filter: -0.1\n", "'soften.filter' must be a finite number >= 0");
  expect_usage_error("soften:\n  filter_stretch: .inf\n",
                     "'soften.filter_stretch' must be a finite number >= 0");
  expect_usage_error("soften:\n  epsilon: -1e-6\n",
                     "'soften.epsilon' must be a finite number >= 0");
  expect_usage_error("integrate:\n  surface_edges: -0.5\n",
                     "'integrate.surface_edges' must be a finite number >= 0");
  expect_usage_error("integrate:\n  surface_edges: .nan\n",
                     "'integrate.surface_edges' must be a finite number >= 0");
  expect_usage_error("integrate:\n  pose_pull: 1.5\n", "'integrate.pose_pull' must be in [0, 1]");
  expect_usage_error("stretch:\n  mass_power: 1.5\n",
                     "'stretch.mass_power' must be a number in [0, 1]");
  expect_usage_error("stretch:\n  mass_power: .nan\n", "'stretch.mass_power' must be a number in");
  expect_usage_error("stretch:\n  masses: uniform\n  mass_power: 0.5\n",
                     "'stretch.mass_power' is not 1, but stretch.masses is uniform");
  expect_usage_error("stretch:\n  local: 1\n", "'stretch.local' must be a number in [0, 1)");
  expect_usage_error("stretch:\n  local: .nan\n", "'stretch.local' must be a number in");
  expect_usage_error("stretch:\n  local_radius: 0\n", "'stretch.local_radius' must be a finite");
  expect_usage_error("stretch:\n  local_regions: 0\n",
                     "'stretch.local_regions' must be at least 1");
  expect_usage_error("cascade: [1, 2\n", "invalid YAML");
  expect_usage_error("- 1\n- 2\n", "not a mapping");
  // The surface domain has no tets: no cotangent weights, no volumes.
  expect_usage_error("domain: surface\narap:\n  weights: cotangent\n",
                     "'arap.weights' is cotangent, but domain: surface");
  expect_usage_error("domain: surface\nmethod: ceres\nvolume:\n  weight: 1.0\n",
                     "'volume.weight' must be 0 with domain: surface");
}

TEST(Config, MissingFileAndBadOverride) {
  EXPECT_THROW(load_options("/nonexistent/unfold.yaml"), UsageError);
  EXPECT_THROW(load_options("", {{"cascade.nmu", "3"}}), UsageError);
  EXPECT_THROW(load_options("", {{"cascade.num", "[1"}}), UsageError);
}

}  // namespace
}  // namespace unfold
