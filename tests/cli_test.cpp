// The unfold command line: outputs on success; on failure a one-line error,
// the exit code of its class and no output file.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "mesh/read_surface_mesh.h"
#include "mesh/write_surface_mesh.h"
#include "output_checks.h"
#include "run_app.h"
#include "test_files.h"
#include "test_meshes.h"

namespace unfold {
namespace {

using test::AppRun;
using test::file_exists;
using test::run_unfold;

std::string temp(const std::string& name) {
  // The process id keeps parallel test runs (two checkouts on one machine) apart.
  const std::string path = ::testing::TempDir() + "cli_" + std::to_string(getpid()) + "_" + name;
  std::remove(path.c_str());
  return path;
}

TEST(Cli, DemoRunWritesEveryOutput) {
  const std::string out = temp("demo_canonical.ply"), in = temp("demo_input.off"),
                    json = temp("demo_metrics.json"), tets = temp("demo_tets.vtu");
  const AppRun r = run_unfold("--demo_pose 1 --output " + out + " --input_copy " + in +
                              " --metrics_json " + json + " --tet_output " + tets);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const SurfaceMesh input = read_surface_mesh(in), canonical = read_surface_mesh(out);
  EXPECT_EQ(canonical.V.rows(), input.V.rows());
  EXPECT_EQ(canonical.faces, input.faces);
  std::ifstream metrics(json);
  std::stringstream text;
  text << metrics.rdbuf();
  for (const char* key :
       {"\"E_rig\"", "\"E_str\"", "\"E_geo\"", "\"edge_ratio\"", "\"iterations\"", "\"cascades\"",
        "\"beta\"", "\"tet_vertices\"", "\"seconds_tetrahedralize\"", "\"seconds_unfold\"",
        "\"tetrahedralization\": {\"route\": \"robust\"", "\"shape\": \"unfolded\"",
        "\"E_geo_skipped\": null"})
    EXPECT_NE(text.str().find(key), std::string::npos) << key;
  EXPECT_EQ(text.str().find("\"E_geo\": null"), std::string::npos);  // below 20,000: computed
  EXPECT_TRUE(file_exists(tets));
  // The damage measure (issue 44) beside inverted_tets: present and finite, in
  // the JSON and in the summary line.
  const auto number = [&](const std::string& key) {
    const size_t at = text.str().find("\"" + key + "\": ");
    return at == std::string::npos ? NAN
                                   : std::strtod(text.str().c_str() + at + key.size() + 4, nullptr);
  };
  for (const char* key :
       {"inverted_tets", "damaged_edges_percent", "surface_edge_ratio_p999",
        "surface_edge_ratio_max", "surface_edge_ratio_min", "damaged_surface_edges",
        "surface_edges_measured", "zero_length_surface_edges"})
    EXPECT_TRUE(std::isfinite(number(key))) << key;
  EXPECT_GE(number("damaged_edges_percent"), 0);
  EXPECT_LE(number("damaged_edges_percent"), 100);
  EXPECT_GE(number("surface_edge_ratio_max"), number("surface_edge_ratio_p999"));
  EXPECT_GE(number("surface_edge_ratio_p999"), 1);
  EXPECT_LE(number("surface_edge_ratio_min"), 1);
  // A closed surface: V + F - 2 unique edges, all measured.
  EXPECT_EQ(number("surface_edges_measured"), double(input.V.rows() + input.faces.size()) - 2);
  // The fold measure beside it: in range, the largest change at least the p99.9.
  for (const char* key : {"folded_edges_percent", "folded_surface_edges",
                          "dihedral_change_p999_degrees", "dihedral_change_max_degrees"})
    EXPECT_TRUE(std::isfinite(number(key))) << key;
  EXPECT_GE(number("folded_edges_percent"), 0);
  EXPECT_LE(number("folded_edges_percent"), 100);
  EXPECT_GE(number("dihedral_change_max_degrees"), number("dihedral_change_p999_degrees"));
  EXPECT_LE(number("dihedral_change_max_degrees"), 180);
  EXPECT_GT(number("dihedral_change_max_degrees"), 0);  // the pose changed: some edge bends
  EXPECT_NE(r.out.find("; damaged surface edges "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("% (ratio outside [1/3, 3]; ratio p99.9 "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find(" inverted tets; folded surface edges "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("% (bend sharpened by more than 90 degrees; p99.9 "), std::string::npos)
      << r.out;
  // The edge damage is a point field of the canonical tet mesh.
  std::ifstream vtu(tets);
  std::stringstream vtu_text;
  vtu_text << vtu.rdbuf();
  EXPECT_NE(vtu_text.str().find("Name=\"edge_damage\""), std::string::npos);
}

std::string file_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}

// Not on a terminal, a run says nothing on stderr but its warnings and errors
// (the demo has none): its summary line goes to stdout; -v brings back the
// stages' lines, -vv the iterations' too.
TEST(Cli, TheDemoPrintsItsSummaryAloneUnlessVerbose) {
  const std::string out = temp("quiet.off");
  const AppRun quiet = run_unfold("--output " + out);
  ASSERT_EQ(quiet.exit_code, 0) << quiet.err;
  EXPECT_EQ(quiet.err, "");
  EXPECT_EQ(quiet.out.rfind("unfolded ", 0), 0u) << quiet.out;
  EXPECT_EQ(std::count(quiet.out.begin(), quiet.out.end(), '\n'), 1) << quiet.out;
  const AppRun verbose = run_unfold("-v --output " + out);
  ASSERT_EQ(verbose.exit_code, 0) << verbose.err;
  for (const char* line : {"unfold: no --input: unfolding the built-in demo shape",
                           "\nunfold: stage surface: cascade: ", "\nunfold: cascade 1/"})
    EXPECT_NE(verbose.err.find(line), std::string::npos) << line << " not in:\n" << verbose.err;
  EXPECT_EQ(verbose.err.find("unfold: iteration "), std::string::npos) << verbose.err;
  EXPECT_EQ(verbose.out.rfind("unfolded ", 0), 0u) << verbose.out;
}

// Above metrics.geodesic_max_vertices (unfold's default 20,000, lowered here so
// that a small mesh is above it) E_geo is left out, and the summary line and
// the JSON say so and how to ask for it; the other metrics are computed.
TEST(Cli, EGeoIsLeftOutAboveTheVertexLimitAndSaysHowToAsk) {
  const std::string out = temp("geo_limit.off"), json = temp("geo_limit.json");
  const AppRun r = run_unfold("--demo_pose 1 --output " + out + " --metrics_json " + json +
                              " --geodesic_max_vertices 1000");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("E_geo left out above 1000 tet vertices"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("--metrics E_rig,E_str,E_geo"), std::string::npos) << r.out;
  const std::string text = file_bytes(json);
  EXPECT_NE(text.find("\"E_geo\": null"), std::string::npos);
  EXPECT_NE(text.find("\"E_geo_skipped\": \"E_geo left out above 1000 tet vertices"),
            std::string::npos);
  EXPECT_EQ(text.find("\"E_rig\": null"), std::string::npos);
  EXPECT_EQ(text.find("\"E_str\": null"), std::string::npos);
}

TEST(Cli, SameInputConfigAndThreadsGiveBitIdenticalOutputs) {
  // docs/reliability.md: determinism holds for a fixed thread count.
  std::string outputs[2][3];
  for (int run = 0; run < 2; ++run) {
    const std::string tag = "determinism" + std::to_string(run);
    outputs[run][0] = temp(tag + ".off");
    outputs[run][1] = temp(tag + ".vtu");
    outputs[run][2] = temp(tag + ".json");
    const AppRun r =
        run_unfold("--threads 2 --demo_pose 2 --target_vertices 1000 --output " + outputs[run][0] +
                   " --tet_output " + outputs[run][1] + " --metrics_json " + outputs[run][2]);
    ASSERT_EQ(r.exit_code, 0) << r.err;
  }
  for (int k = 0; k < 2; ++k) {  // surface and tet mesh; the JSON holds timings
    EXPECT_FALSE(file_bytes(outputs[0][k]).empty());
    EXPECT_EQ(file_bytes(outputs[0][k]), file_bytes(outputs[1][k])) << outputs[0][k];
  }
  // The JSON equals once the "seconds" figures and the stages' (one line) are taken out.
  const auto without_timings = [](std::string text) {
    std::string out;
    std::istringstream lines(text);
    for (std::string line; std::getline(lines, line);) {
      if (line.find("\"stages\": {") != std::string::npos) continue;
      for (size_t at; (at = line.find("\"seconds")) != std::string::npos;)
        line.erase(at, line.find_first_of(",}", at) - at);
      out += line + "\n";
    }
    return out;
  };
  EXPECT_EQ(without_timings(file_bytes(outputs[0][2])), without_timings(file_bytes(outputs[1][2])));
}

// Issue 13: per-vertex fields of separately unfolded components were empty
// (a segmentation fault in the rigidity picture, exit 2 writing the tet mesh).
TEST(Cli, SeparateComponentsRenderByRigidityAndWriteTheTetFields) {
  const test::TempDir dir;
  const std::string two = UNFOLD_SOURCE_DIR "/tests/bad_inputs/two_components.off";
  const AppRun r = run_unfold("--input " + two + " --components separately --output " +
                              dir.file("x.off") + " --render " + dir.file("x.png") +
                              " --render_color rigidity --tet_output " + dir.file("x.vtu"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(test::IsSurface(dir.file("x.off"), 8));
  EXPECT_TRUE(test::IsPng(dir.file("x.png")));
  EXPECT_TRUE(test::IsVtu(dir.file("x.vtu")));
}

// Every output of a run is committed together: an error raised after some
// were written (here the sweep, which comes last) leaves none of them.
TEST(Cli, AFailureAfterSomeOutputsWereWrittenLeavesNone) {
  const test::TempDir dir;
  const std::string two = UNFOLD_SOURCE_DIR "/tests/bad_inputs/two_components.off";
  const AppRun r = run_unfold(
      "--input " + two + " --components separately --output " + dir.file("x.off") +
      " --tet_output " + dir.file("x.node") + " --metrics_json " + dir.file("x.json") +
      " --convergence " + dir.file("x.csv") + " --beta_sweep 1,2 --render " + dir.file("x.png"));
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("unfold: error: beta sweep: the surface has 2 connected components"),
            std::string::npos)
      << r.err;
  EXPECT_EQ(dir.count(), 0);
}

}  // namespace
}  // namespace unfold
