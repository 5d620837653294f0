// unfold_batch on every input class with every method: failing shapes are
// recorded with their error and the run goes on; every ok shape's files parse;
// a batch interrupted (Ctrl-C) and resumed with --skip_existing writes the
// same tables as one run straight through, and runs again only the configs
// whose results are missing; --threads is checked, and a shape
// below kMinParallelRows gives the same files on one thread as on two (what
// scripts/slurm/submit's one thread a shape relies on, docs/reliability.md);
// a shape's process runs parallel regions after the parent ran one.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "matrix_inputs.h"
#include "output_checks.h"
#include "pipeline/batch_run.h"
#include "run_app.h"
#include "test_files.h"

namespace unfold {
namespace {

// CMBOF's retrieval at a size that keeps these runs quick (its defaults: 1500
// words, 66 views of 256 pixels).
const std::string kCheapCmbof =
    "--cmbof_words 32 --cmbof_image_size 128 --cmbof_view_subdivisions 0";

namespace fs = std::filesystem;

// Every input class, plus a truncated file, as a batch input directory.
std::string input_dir(const test::TempDir& dir) {
  const std::string in = dir.file("in");
  fs::create_directories(in);
  for (int k = 0; k < test::kNumInputs; ++k)
    fs::copy_file(test::matrix_input(k), in + "/" + test::input_name(k) +
                                             fs::path(test::matrix_input(k)).extension().string());
  test::write_bytes(in + "/broken.off", "OFF\n4 4 0\n0 0 0\n");
  return in;
}

std::string configs(const std::vector<int>& which) {
  std::string list;
  for (int c : which)
    list += (list.empty() ? "" : ",") + test::quick_config(test::kMatrixConfigs[c]);
  return list;
}

// The error each failing shape is recorded with ("" = ok).
std::string expected_error(const std::string& shape) {
  if (shape == "two_components") return "2 connected components";
  if (shape == "open_surface") return "the surface is open";
  if (shape == "broken") return "broken.off";
  return "";
}

TEST(BatchMatrix, EveryShapeAndMethodIsRecordedAndFailuresDoNotStopTheRun) {
  const test::TempDir dir;
  const std::string in = input_dir(dir), out = dir.file("out");
  for (const char* jobs : {"2", "1 --target_vertices 50"}) {
    fs::remove_all(out);
    const test::AppRun r =
        test::run_app("unfold_batch", "--input_dir " + in + " --output_dir " + out + " --configs " +
                                          configs({0, 1, 2, 3}) + " --retrieval_points 100 " +
                                          kCheapCmbof + " --jobs " + jobs);
    SCOPED_TRACE(std::string("--jobs ") + jobs);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const std::vector<BatchRow> rows = read_results_csv(out + "/results.csv");
    ASSERT_EQ(rows.size(), size_t(6 * test::kNumMatrixConfigs));
    for (const BatchRow& row : rows) {
      const std::string error = expected_error(row.shape),
                        stem = out + "/" + row.method + "/" + row.shape;
      SCOPED_TRACE(row.shape + " " + row.method);
      if (!error.empty()) {
        EXPECT_NE(row.status.find(error), std::string::npos) << row.status;
        EXPECT_FALSE(fs::exists(stem + ".off"));
        EXPECT_FALSE(fs::exists(stem + ".json"));
        continue;
      }
      EXPECT_EQ(row.status, "ok");
      EXPECT_TRUE(test::IsSurface(stem + ".off", -100000));
      EXPECT_TRUE(test::IsMetricsJson(stem + ".json"));
    }
    // Text columns first: the method and framework; the shape; the class and the method.
    for (const auto& [table, text_columns] : {std::pair{"retrieval.csv", 2},
                                              {"similarity_dpmu.csv", 1},
                                              {"similarity_dpmu_ort.csv", 1},
                                              {"pose_invariance.csv", 2}})
      EXPECT_TRUE(test::IsCsv(out + "/" + table, text_columns)) << table;
  }
}

// Everything but the timing column of results.csv, and the other tables.
std::string tables(const std::string& out) {
  std::ostringstream all;
  std::istringstream results(test::file_text(out + "/results.csv"));
  for (std::string line; std::getline(results, line);) {
    const size_t status = line.rfind(','), seconds = line.rfind(',', status - 1);
    all << line.substr(0, seconds) << line.substr(status) << '\n';
  }
  for (const auto& entry : fs::directory_iterator(out))
    if (entry.path().extension() == ".csv" && entry.path().filename() != "results.csv")
      all << entry.path().filename() << ":\n" << test::file_text(entry.path().string());
  return all.str();
}

TEST(BatchMatrix, InterruptedThenResumedWithSkipExistingGivesTheSameTables) {
  const test::TempDir dir;
  const std::string in = input_dir(dir), list = configs({0, 2});
  const std::string args =
      " --configs " + list + " --retrieval_points 100 " + kCheapCmbof + " --jobs 1";
  ASSERT_EQ(test::run_app("unfold_batch",
                          "--input_dir " + in + " --output_dir " + dir.file("straight") + args)
                .exit_code,
            0);

  // Ctrl-C to the whole process group once the second shape (clean) is done.
  const std::string out = dir.file("resumed");
  const pid_t pid = fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    setpgid(0, 0);
    const int null = open("/dev/null", O_WRONLY);
    dup2(null, STDOUT_FILENO);
    dup2(null, STDERR_FILENO);
    const std::string bin = std::string(UNFOLD_BIN_DIR) + "/unfold_batch";
    execl(bin.c_str(), bin.c_str(), "--input_dir", in.c_str(), "--output_dir", out.c_str(),
          "--configs", list.c_str(), "--retrieval_points", "100", "--cmbof_words", "32",
          "--cmbof_image_size", "128", "--cmbof_view_subdivisions", "0", "--jobs", "1", nullptr);
    _exit(127);
  }
  setpgid(pid, pid);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::minutes(5);
  while (!fs::exists(out + "/lsmds/clean.row") && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  kill(-pid, SIGINT);
  int status = 0;
  waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFSIGNALED(status)) << "the batch ended before it was interrupted";
  ASSERT_FALSE(fs::exists(out + "/results.csv"));

  const auto finished_before = fs::last_write_time(out + "/default/clean.off");
  const test::AppRun r = test::run_app(
      "unfold_batch", "--input_dir " + in + " --output_dir " + out + args + " --skip_existing");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(fs::last_write_time(out + "/default/clean.off"), finished_before) << "not kept";
  EXPECT_EQ(tables(out), tables(dir.file("straight")));

  // One config's result gone: only that config runs again for the shape (and the
  // three failing shapes, whose rows are not ok).
  fs::remove(out + "/lsmds/clean.row");
  const test::AppRun again = test::run_app(
      "unfold_batch", "--input_dir " + in + " --output_dir " + out + args + " --skip_existing");
  ASSERT_EQ(again.exit_code, 0) << again.err;
  EXPECT_NE(again.out.find("4 shapes to run (2 kept; 1 of their 8 results kept)"),
            std::string::npos)
      << again.out;
  EXPECT_EQ(fs::last_write_time(out + "/default/clean.off"), finished_before) << "not kept";
  EXPECT_TRUE(fs::exists(out + "/lsmds/clean.row"));
  EXPECT_EQ(tables(out), tables(dir.file("straight")));
}

TEST(BatchMatrix, ThreadsIsCheckedAndASmallShapeDoesNotDependOnIt) {
  const test::TempDir dir;
  const std::string in = dir.file("in");
  fs::create_directories(in);
  fs::copy_file(test::matrix_input(test::kDemo), in + "/demo.ply");
  const std::string args =
      "--input_dir " + in + " --configs " + configs({0}) + " " + kCheapCmbof + " --output_dir ";
  const test::AppRun bad = test::run_app("unfold_batch", args + dir.file("bad") + " --threads -1");
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("--threads must be >= 0"), std::string::npos) << bad.err;
  EXPECT_FALSE(fs::exists(dir.file("bad")));
  for (const char* threads : {"1", "2"})
    ASSERT_EQ(
        test::run_app("unfold_batch", args + dir.file(threads) + " --threads " + threads).exit_code,
        0);
  EXPECT_EQ(test::file_text(dir.file("1") + "/default/demo.off"),
            test::file_text(dir.file("2") + "/default/demo.off"));
}

// The parent's config probe builds the local spread's regions, whose edge
// lengths are taken in a parallel region. A team left in the parent was copied
// into every forked child without its threads (libgomp is not fork-safe), and
// the child's first parallel region waited for them forever: the run must end.
TEST(BatchMatrix, AShapesProcessRunsParallelRegionsAfterTheParentRanOne) {
  const test::TempDir dir;
  const std::string in = dir.file("in"), config = dir.file("local_spread.yaml");
  fs::create_directories(in);
  fs::copy_file(test::matrix_input(test::kDemo), in + "/demo.ply");
  test::write_bytes(config, "base: default\nstretch:\n  local: 0.5\n");
  // Two threads in the parent and in the child whatever the machine; the
  // whole process group killed if it hangs.
  const std::string command = "OMP_NUM_THREADS=2 timeout -s KILL 120 " +
                              std::string(UNFOLD_BIN_DIR) + "/unfold_batch --input_dir " + in +
                              " --output_dir " + dir.file("out") + " --configs " + config +
                              " --metrics none --retrieval_points 100 " + kCheapCmbof +
                              " --jobs 1 --threads 2 >/dev/null 2>&1";
  const int status = std::system(command.c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0) << "137: killed after 120 s, the shape's process hung";
  const std::vector<BatchRow> rows = read_results_csv(dir.file("out") + "/results.csv");
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_EQ(rows[0].status, "ok");
}

}  // namespace
}  // namespace unfold
