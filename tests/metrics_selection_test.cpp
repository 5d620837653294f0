// metrics.compute (--metrics): only the metrics asked for are computed, the
// others are reported as not computed (null in JSON, empty in results.csv),
// never as a number; the ones computed are the same as in a full run.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "config/options.h"
#include "core/errors.h"
#include "core/json.h"
#include "core/parallel.h"
#include "mesh/edge_graph.h"
#include "mesh/write_surface_mesh.h"
#include "metrics/geodesic_error.h"
#include "pipeline/batch_run.h"
#include "pipeline/metrics_json.h"
#include "pipeline/unfold_surface.h"
#include "run_app.h"
#include "stages/solve_edge_graph.h"
#include "test_files.h"
#include "test_meshes.h"

namespace unfold {
namespace {

using Names = std::vector<std::string>;

TEST(MetricsSelection, FlagAndYamlForms) {
  const Options defaults;
  EXPECT_EQ(defaults.metrics, (Names{"E_rig", "E_str", "E_geo"}));
  EXPECT_EQ(load_options("", {{"metrics.compute", "E_rig,E_str"}}).metrics,
            (Names{"E_rig", "E_str"}));
  EXPECT_EQ(load_options("", {{"metrics.compute", "E_geo"}}).metrics, (Names{"E_geo"}));
  EXPECT_EQ(load_options("", {{"metrics.compute", "none"}}).metrics, Names{});
  EXPECT_EQ(load_options("", {{"metrics.compute", "all"}}).metrics, defaults.metrics);
  EXPECT_EQ(load_options("", {{"metrics.compute", "[]"}}).metrics, Names{});
  // The effective YAML reads back as the same selection, the empty one included.
  for (const Names& selection : {Names{}, Names{"E_str"}, Names{"E_geo", "E_rig"}}) {
    Options o;
    o.metrics = selection;
    const test::TempDir dir;
    const std::string path = dir.file("metrics.yaml");
    std::ofstream(path) << options_to_yaml(o);
    EXPECT_EQ(load_options(path).metrics, selection);
  }
  for (const char* bad : {"E_rig,E_foo", "E_rig,E_rig", "{a: 1}"}) {
    try {
      load_options("", {{"metrics.compute", bad}});
      ADD_FAILURE() << bad << " accepted";
    } catch (const UsageError& e) {
      EXPECT_NE(std::string(e.what()).find("metrics.compute"), std::string::npos) << e.what();
    }
  }
  EXPECT_TRUE(computes_metric(defaults, "E_geo"));
  EXPECT_FALSE(computes_metric(load_options("", {{"metrics.compute", "E_rig"}}), "E_geo"));
}

TEST(MetricsSelection, OnlyTheAskedMetricsAreComputedAndTheyEqualAFullRun) {
  const SurfaceMesh sphere = test::uv_sphere(10, 16);
  const Options defaults;
  const UnfoldResult all = unfold_surface(sphere, defaults);
  ASSERT_TRUE(std::isfinite(all.metrics.E_rig) && std::isfinite(all.metrics.E_str) &&
              std::isfinite(all.metrics.E_geo));
  // A mesh this small has E_geo's rows computed during the solve: the value is
  // the one-pass function's, on the solve's edges (the tets' and the surface's
  // edges that no tet has).
  ASSERT_LT(all.tets.V.rows(), kMinParallelRows);
  EXPECT_EQ(all.metrics.E_geo,
            geodesic_error(
                solve_edge_graph(all.tets, all.surface, defaults.integrate.surface_edges).graph,
                all.tets.V, all.tet_canonical, defaults.geodesic_metric)
                .value);
  // Computed with it: the same over the surface's own edges and vertices alone.
  EXPECT_EQ(all.metrics.E_geo_surface,
            surface_geodesic_error(sphere.V, triangulate_faces(sphere), all.canonical.V,
                                   defaults.geodesic_metric)
                .value);
  Options some;
  some.metrics = {"E_rig", "E_str"};
  const UnfoldResult r = unfold_surface(sphere, some);
  EXPECT_EQ(r.metrics.E_rig, all.metrics.E_rig);
  EXPECT_EQ(r.metrics.E_str, all.metrics.E_str);
  EXPECT_TRUE(std::isnan(r.metrics.E_geo) && std::isnan(r.metrics.E_geo_surface));
  EXPECT_EQ(r.metrics.rigidity_per_vertex, all.metrics.rigidity_per_vertex);
  const std::string json = to_json_text(metrics_document(r, some));
  EXPECT_NE(json.find("\"E_geo\": null"), std::string::npos) << json.substr(0, 300);
  EXPECT_NE(json.find("\"E_geo_surface\": null"), std::string::npos) << json.substr(0, 300);
  EXPECT_NE(json.find("\"metrics_computed\": [\"E_rig\", \"E_str\"]"), std::string::npos);

  Options none;
  none.metrics = {};
  const UnfoldResult n = unfold_surface(sphere, none);
  EXPECT_TRUE(std::isnan(n.metrics.E_rig) && std::isnan(n.metrics.E_str) &&
              std::isnan(n.metrics.E_geo));
  EXPECT_EQ(n.metrics.inverted_tets, all.metrics.inverted_tets);  // always counted
  // So is the damage measure (issue 44), over the surface's unique edges.
  EXPECT_EQ(n.metrics.damage.ratio_p999, all.metrics.damage.ratio_p999);
  EXPECT_EQ(n.metrics.damage.per_vertex, all.metrics.damage.per_vertex);
  EXPECT_EQ(n.metrics.damage.edges, int(sphere.V.rows() + sphere.faces.size()) - 2);
  EXPECT_EQ(n.cascade.positions, all.cascade.positions);  // the unfolding is the same
}

TEST(MetricsSelection, ResultsCsvLeavesAMetricNotComputedEmpty) {
  const test::TempDir dir;
  const std::string path = dir.file("results.csv");
  const double nan = std::nan("");
  BatchRow damaged{"cat1", "cat", "default", 0.5, 0.25, 0.125, 2.5, "ok"};
  damaged.damaged_edges_percent = 1.25, damaged.surface_edge_ratio_p999 = 4.5;
  damaged.surface_edge_ratio_max = 213, damaged.inverted_tets = 3000;
  damaged.folded_edges_percent = 0.375, damaged.dihedral_change_p999 = 150;
  damaged.E_geo_surface = 0.0625;
  write_results_csv(path, {{"cat0", "cat", "default", 0.5, 0.25, nan, 1.5, "ok"}, damaged});
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_EQ(text.str().rfind("shape,class,method,E_rig,E_str,E_geo,damaged_edges_percent,"
                             "surface_edge_ratio_p999,surface_edge_ratio_max,inverted_tets,"
                             "folded_edges_percent,dihedral_change_p999_degrees,E_geo_surface,"
                             "seconds,status\n",
                             0),
            0u)
      << text.str();
  EXPECT_NE(text.str().find("cat0,cat,default,0.5,0.25,,,,,,,,,1.5,ok"), std::string::npos)
      << text.str();
  EXPECT_NE(
      text.str().find("cat1,cat,default,0.5,0.25,0.125,1.25,4.5,213,3000,0.375,150,0.0625,2.5,ok"),
      std::string::npos)
      << text.str();
  const std::vector<BatchRow> rows = read_results_csv(path);
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0].E_rig, 0.5);
  EXPECT_TRUE(std::isnan(rows[0].E_geo));
  EXPECT_TRUE(std::isnan(rows[0].damaged_edges_percent));
  EXPECT_EQ(rows[1].damaged_edges_percent, 1.25);
  EXPECT_EQ(rows[1].surface_edge_ratio_p999, 4.5);
  EXPECT_EQ(rows[1].surface_edge_ratio_max, 213);
  EXPECT_EQ(rows[1].inverted_tets, 3000);
  EXPECT_TRUE(std::isnan(rows[0].folded_edges_percent));
  EXPECT_EQ(rows[1].folded_edges_percent, 0.375);
  EXPECT_EQ(rows[1].dihedral_change_p999, 150);
  EXPECT_TRUE(std::isnan(rows[0].E_geo_surface));
  EXPECT_EQ(rows[1].E_geo_surface, 0.0625);
  EXPECT_EQ(rows[1].seconds, 2.5);
  EXPECT_EQ(rows[1].status, "ok");
}

// A results.csv written before the damage or the fold columns, or before
// E_geo_surface, still reads: those are NaN.
TEST(MetricsSelection, ResultsCsvWithoutTheDamageColumnsStillReads) {
  const test::TempDir dir;
  const std::string path = dir.file("results.csv");
  // The one row of a results.csv of that header.
  const auto read_one = [&](const std::string& header, const std::string& row) {
    test::write_bytes(path, header + "\n" + row + "\n");
    const std::vector<BatchRow> rows = read_results_csv(path);
    EXPECT_EQ(rows.size(), 1u);
    return rows.empty() ? BatchRow{} : rows[0];
  };
  const BatchRow before_damage = read_one("shape,class,method,E_rig,E_str,E_geo,seconds,status",
                                          "cat0,cat,default,0.5,0.25,,1.5,ok");
  EXPECT_EQ(before_damage.E_str, 0.25);
  EXPECT_EQ(before_damage.seconds, 1.5);
  EXPECT_EQ(before_damage.status, "ok");
  EXPECT_TRUE(std::isnan(before_damage.damaged_edges_percent) &&
              std::isnan(before_damage.inverted_tets));
  // And one written before the fold columns: those alone are NaN.
  const std::string damage_header =
      "shape,class,method,E_rig,E_str,E_geo,damaged_edges_percent,surface_edge_ratio_p999,"
      "surface_edge_ratio_max,inverted_tets,";
  const BatchRow before_folds = read_one(damage_header + "seconds,status",
                                         "cat1,cat,paper,0.5,0.25,0.125,1.25,4.5,213,3000,2.5,ok");
  EXPECT_EQ(before_folds.inverted_tets, 3000);
  EXPECT_EQ(before_folds.seconds, 2.5);
  EXPECT_TRUE(std::isnan(before_folds.folded_edges_percent) &&
              std::isnan(before_folds.dihedral_change_p999));
  // And one written before E_geo_surface.
  const BatchRow before_surface =
      read_one(damage_header + "folded_edges_percent,dihedral_change_p999_degrees,seconds,status",
               "cat1,cat,paper,0.5,0.25,0.125,1.25,4.5,213,3000,0.375,150,2.5,ok");
  EXPECT_EQ(before_surface.dihedral_change_p999, 150);
  EXPECT_EQ(before_surface.seconds, 2.5);
  EXPECT_TRUE(std::isnan(before_surface.E_geo_surface));
}

TEST(MetricsSelection, UnfoldFlagWritesNullAndSaysNotComputed) {
  const test::TempDir dir;
  const std::string input = dir.file("sphere.off"), json = dir.file("m.json");
  write_surface_mesh(input, test::uv_sphere(8, 12));
  const test::AppRun r =
      test::run_unfold("--input " + input + " --metrics E_rig,E_str --metrics_json " + json);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::ifstream in(json);
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_NE(text.str().find("\"E_geo\": null"), std::string::npos);
  EXPECT_EQ(text.str().find("\"E_rig\": null"), std::string::npos);
  // A rigidity picture needs E_rig: refused before any work.
  const test::AppRun refused = test::run_unfold("--input " + input +
                                                " --metrics E_str --render_color rigidity "
                                                "--render " +
                                                dir.file("r.png"));
  EXPECT_EQ(refused.exit_code, 2) << refused.err;
  EXPECT_NE(refused.err.find("E_rig"), std::string::npos) << refused.err;
}

}  // namespace
}  // namespace unfold
