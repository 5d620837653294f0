// A method is a list of stages (pipeline/unfold_method.h): the config picks
// the list, and the one loop that runs it records every stage's seconds, in
// order, in the result and the metrics JSON.
#include <gtest/gtest.h>

#include <numeric>
#include <string>
#include <vector>

#include "pipeline/metrics_json.h"
#include "pipeline/unfold_method.h"
#include "pipeline/unfold_surface.h"
#include "shapes/articulated_shape.h"

namespace unfold {
namespace {

const std::string kStageConfigs = UNFOLD_SOURCE_DIR "/configs/";

std::vector<std::string> stage_names_run(const std::vector<StageTime>& times) {
  std::vector<std::string> names;
  for (const StageTime& t : times) names.push_back(t.name);
  return names;
}

double stage_seconds_sum(const std::vector<StageTime>& times,
                         const std::vector<std::string>& names) {
  double s = 0;
  for (const StageTime& t : times)
    if (std::find(names.begin(), names.end(), t.name) != names.end()) s += t.seconds;
  return s;
}

TEST(MethodStages, TheDefaultConfigListsTheDefaultsStages) {
  const Method m = choose_method(load_options(kStageConfigs + "default.yaml"));
  EXPECT_EQ(m.name, "default");
  EXPECT_EQ(
      stage_names(m.stages),
      (std::vector<std::string>{
          "check and simplify", "tetrahedralize the input", "metrics: the surface's geodesic rows",
          "integration: anchor lambda_2", "surface: lambda_2 and beta", "surface: cascade",
          "soft joints: lambda_2 and beta", "soft joints: cascade", "soft joints: filter",
          "surface: to full resolution", "tets of the unfolded shape", "given tets' unfolded shape",
          "edges", "interior placement", "integration", "anchored steps", "untangle", "metrics"}));
}

TEST(MethodStages, ThePaperConfigListsThePapersStages) {
  const Method m = choose_method(load_options(kStageConfigs + "paper.yaml"));
  EXPECT_EQ(m.name, "paper");
  EXPECT_EQ(stage_names(m.stages),
            (std::vector<std::string>{"check and simplify", "tetrahedralize the input",
                                      "metrics: the surface's geodesic rows",
                                      "tetrahedralize the input (deferred)", "edges",
                                      "lambda_2 and beta", "cascade", "metrics"}));
}

TEST(MethodStages, EveryConfigPicksItsList) {
  const auto method_of = [](const std::string& config) {
    return choose_method(load_options(kStageConfigs + config + ".yaml")).name;
  };
  EXPECT_EQ(method_of("dpmu"), "paper");
  EXPECT_EQ(method_of("volume"), "paper");
  EXPECT_EQ(method_of("invariant"), "surface");
  EXPECT_EQ(method_of("surface"), "surface");
  EXPECT_EQ(method_of("contact"), "default");
  EXPECT_EQ(method_of("lsmds"), "lsmds");
  EXPECT_EQ(method_of("scf"), "scf");
  Options contact = load_options(kStageConfigs + "default.yaml");
  contact.tet_shape = "contact";
  EXPECT_EQ(choose_method(contact).name, "contact");
}

// The stages that run on a small closed surface, each timed once, in list
// order; the seconds_* fields are their sums.
TEST(MethodStages, TheDriverTimesEveryStageOnceInOrder) {
  const SurfaceMesh shape = make_articulated_shape(ShapePose::preset(0));
  const Options default_options = load_options(kStageConfigs + "default.yaml");
  const UnfoldResult d = unfold_surface(shape, default_options);
  EXPECT_EQ(stage_names_run(d.stage_seconds),
            (std::vector<std::string>{"check and simplify", "metrics: the surface's geodesic rows",
                                      "integration: anchor lambda_2", "surface: lambda_2 and beta",
                                      "surface: cascade", "soft joints: lambda_2 and beta",
                                      "soft joints: cascade", "soft joints: filter",
                                      "tets of the unfolded shape", "edges", "integration",
                                      "anchored steps", "untangle", "metrics"}));
  for (const StageTime& t : d.stage_seconds) EXPECT_GE(t.seconds, 0) << t.name;
  EXPECT_DOUBLE_EQ(d.seconds_prepare, stage_seconds_sum(d.stage_seconds, {"check and simplify"}));
  EXPECT_DOUBLE_EQ(d.seconds_lambda2,
                   stage_seconds_sum(d.stage_seconds, {"surface: lambda_2 and beta",
                                                       "soft joints: lambda_2 and beta"}));
  EXPECT_DOUBLE_EQ(d.seconds_cascade,
                   stage_seconds_sum(d.stage_seconds, {"surface: cascade", "soft joints: cascade",
                                                       "soft joints: filter"}));
  EXPECT_DOUBLE_EQ(d.seconds_integration, stage_seconds_sum(d.stage_seconds, {"integration"}));
  EXPECT_DOUBLE_EQ(d.seconds_anchored, stage_seconds_sum(d.stage_seconds, {"anchored steps"}));
  // The anchored steps' count within their cap (the integration is the first step), in the JSON.
  EXPECT_GT(d.anchored_steps, 0);
  EXPECT_LT(d.anchored_steps, default_options.integrate.iterations);
  const std::string json = to_json_text(metrics_document(d, default_options));
  EXPECT_NE(json.find("\"anchored_steps\": " + std::to_string(d.anchored_steps)),
            std::string::npos);
  EXPECT_NE(json.find(std::string("\"anchored_converged\": ") +
                      (d.anchored_converged ? "true" : "false")),
            std::string::npos);
  EXPECT_DOUBLE_EQ(d.tet_report.seconds,
                   stage_seconds_sum(d.stage_seconds, {"tets of the unfolded shape"}));
  EXPECT_DOUBLE_EQ(d.metrics.seconds, stage_seconds_sum(d.stage_seconds, {"metrics"}));
  EXPECT_GE(d.seconds_unfold, d.seconds_cascade);

  const Options paper = load_options(kStageConfigs + "paper.yaml");
  const UnfoldResult p = unfold_surface(shape, paper);
  const std::vector<std::string> paper_stages{"check and simplify",
                                              "tetrahedralize the input",
                                              "metrics: the surface's geodesic rows",
                                              "edges",
                                              "lambda_2 and beta",
                                              "cascade",
                                              "metrics"};
  EXPECT_EQ(stage_names_run(p.stage_seconds), paper_stages);

  // prepare_mesh, then unfold_prepared: the same stages, the same record.
  const UnfoldResult q = unfold_prepared(prepare_mesh(shape, paper), paper);
  EXPECT_EQ(stage_names_run(q.stage_seconds), paper_stages);
  EXPECT_EQ(q.canonical.V, p.canonical.V);

  // The metrics JSON's "stages", in the same order.
  const Json doc = metrics_document(p, paper);
  const JsonObject& fields = std::get<JsonObject>(doc.value);
  const auto stages =
      std::find_if(fields.begin(), fields.end(), [](const auto& f) { return f.first == "stages"; });
  ASSERT_NE(stages, fields.end());
  std::vector<std::string> json_names;
  for (const auto& [name, seconds] : std::get<JsonObject>(stages->second.value))
    json_names.push_back(name);
  EXPECT_EQ(json_names, paper_stages);
}

}  // namespace
}  // namespace unfold
