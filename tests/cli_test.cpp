// The unfold command line: outputs on success; on failure a one-line error,
// the exit code of its class and no output file.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdio>
#include <fstream>
#include <sstream>

#include "mesh/read_surface_mesh.h"
#include "mesh/write_surface_mesh.h"
#include "test_meshes.h"

namespace unfold {
namespace {

struct AppRun {
  int exit_code;
  std::string err;
};

AppRun run_unfold(const std::string& args) {
  // One file per test: ctest runs the tests as parallel processes.
  const std::string err_path = ::testing::TempDir() + "cli_stderr_" +
                               ::testing::UnitTest::GetInstance()->current_test_info()->name();
  const int status = std::system(
      (std::string(UNFOLD_BIN_DIR) + "/unfold " + args + " 2>" + err_path + " >/dev/null").c_str());
  std::ifstream in(err_path);
  std::stringstream err;
  err << in.rdbuf();
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, err.str()};
}

bool exists(const std::string& path) { return std::ifstream(path).good(); }

std::string temp(const std::string& name) {
  const std::string path = ::testing::TempDir() + name;
  std::remove(path.c_str());
  return path;
}

void expect_failure(const std::string& args, int code, const std::string& words,
                    const std::string& output) {
  const AppRun r = run_unfold(args + " --output " + output);
  EXPECT_EQ(r.exit_code, code) << r.err;
  EXPECT_NE(r.err.find("unfold: error: "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(words), std::string::npos) << r.err;
  EXPECT_FALSE(exists(output)) << "a failed run left " << output;
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
        "\"tetrahedralization\": {\"route\": \"conforming\""})
    EXPECT_NE(text.str().find(key), std::string::npos) << key;
  EXPECT_TRUE(exists(tets));
}

TEST(Cli, BadInputsFailCleanly) {
  const std::string out = temp("bad_out.off");
  expect_failure("--input /nonexistent/shape.off", 3, "/nonexistent/shape.off", out);
  const std::string nan_mesh = temp("nan.off");
  std::ofstream(nan_mesh) << "OFF\n4 4 0\n0 0 0\n1 0 0\n0 nan 0\n0 0 1\n"
                          << "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
  expect_failure("--input " + nan_mesh, 3, "vertex 2", out);
  SurfaceMesh open = test::octahedron();
  open.faces.pop_back();
  const std::string open_mesh = temp("open.off");
  write_surface_mesh(open_mesh, open);
  expect_failure("--input " + open_mesh, 3, "open", out);
  SurfaceMesh two = test::octahedron();
  const SurfaceMesh other = test::tetrahedron();
  two.V.conservativeResize(10, 3);
  two.V.bottomRows(4) = other.V.array() + 5.0;
  for (auto f : other.faces) {
    for (int& v : f) v += 6;
    two.faces.push_back(f);
  }
  const std::string two_mesh = temp("two.off");
  write_surface_mesh(two_mesh, two);
  expect_failure("--input " + two_mesh, 3, "2 connected components", out);
}

TEST(Cli, BadParametersAreUsageErrors) {
  const std::string out = temp("usage_out.off");
  expect_failure("--k_iter 0", 2, "cascade.k_iter", out);
  expect_failure("--beta -3", 2, "beta.value", out);
  expect_failure("--beta nan", 2, "beta.value", out);
  expect_failure("--no_such_flag 1", 2, "no_such_flag", out);
  expect_failure("--config /nonexistent/c.yaml", 2, "/nonexistent/c.yaml", out);
  const std::string config = temp("typo.yaml");
  std::ofstream(config) << "cascade:\n  kiter: 3\n";
  expect_failure("--config " + config, 2, "cascade.kiter", out);
}

TEST(Cli, UnwritableOutputsFailBeforeWork) {
  const AppRun r = run_unfold("--output " + temp("x.xyz"));
  EXPECT_EQ(r.exit_code, 5) << r.err;
  EXPECT_NE(r.err.find(".xyz"), std::string::npos) << r.err;
  const AppRun dir = run_unfold("--output /nonexistent_dir/out.off");
  EXPECT_EQ(dir.exit_code, 5) << dir.err;
  EXPECT_NE(dir.err.find("/nonexistent_dir/out.off"), std::string::npos) << dir.err;
}

}  // namespace
}  // namespace unfold
