// What a new user sees first: every app's --help starts with its usage and its
// own flags (glog's and gflags' only under --helpfull, no source paths), and
// the lines of -v and -vv read "unfold: ..." without glog's "I20261124 20:38:54
// ..." prefix.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "config/options.h"
#include "mesh/write_surface_mesh.h"
#include "run_app.h"
#include "test_files.h"
#include "test_meshes.h"

namespace unfold {
namespace {

using test::AppRun;
using test::run_app;

std::vector<std::string> apps() {
  std::vector<std::string> names;
  for (const auto& source : std::filesystem::directory_iterator(UNFOLD_SOURCE_DIR "/apps"))
    if (source.path().extension() == ".cpp") names.push_back(source.path().stem());
  return names;
}

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> result;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) result.push_back(line);
  return result;
}

// The flags an app defines itself, from gflags' machine-readable --helpxml.
std::vector<std::string> own_flags(const std::string& app) {
  const std::string xml = run_app(app, "--helpxml").out;
  static const std::regex flag("<flag><file>([^<]*)</file><name>([^<]*)</name>");
  std::vector<std::string> names;
  for (auto it = std::sregex_iterator(xml.begin(), xml.end(), flag); it != std::sregex_iterator();
       ++it)
    if ((*it)[1].str().find("apps/") != std::string::npos) names.push_back((*it)[2]);
  return names;
}

// Flags of glog and gflags that a user should not have to read past.
const char* const kInternals[] = {"logtostderr",    "alsologtoemail", "log_dir",   "minloglevel",
                                  "tab_completion", "flagfile",       "Flags from"};

TEST(AppHelp, EveryAppStartsWithItsUsageAndItsOwnFlags) {
  const std::vector<std::string> names = apps();
  ASSERT_GE(names.size(), 5u);
  for (const std::string& app : names) {
    const AppRun r = run_app(app, "--help");
    ASSERT_EQ(r.exit_code, 0) << app << ": " << r.err;
    const std::vector<std::string> text = lines(r.out);
    ASSERT_GE(text.size(), 5u) << app;
    EXPECT_EQ(text[0].rfind("usage: " + app + " ", 0), 0u) << app << ": " << text[0];
    std::string head;
    for (size_t i = 0; i < std::min<size_t>(30, text.size()); ++i) head += text[i] + "\n";
    EXPECT_NE(head.find("\n  --"), std::string::npos) << app << ": no flag in the first 30 lines";
    for (const char* internal : kInternals)
      EXPECT_EQ(head.find(internal), std::string::npos) << app << " --help shows " << internal;
    // No build paths: neither the source tree nor a source file's name.
    EXPECT_EQ(r.out.find(UNFOLD_SOURCE_DIR), std::string::npos) << app;
    EXPECT_EQ(r.out.find(".cpp"), std::string::npos) << app;
    // Every flag the app defines is there, with its default.
    const std::vector<std::string> flags = own_flags(app);
    EXPECT_FALSE(flags.empty()) << app;
    for (const std::string& flag : flags) {
      const size_t at = r.out.find("\n  --" + flag + " ");
      const size_t at_long = r.out.find("\n  --" + flag + "\n");
      ASSERT_TRUE(at != std::string::npos || at_long != std::string::npos)
          << app << " --help does not list --" << flag;
      const size_t start = std::min(at, at_long);
      const std::string entry = r.out.substr(start, r.out.find("\n  --", start + 1) - start);
      EXPECT_NE(entry.find("default"), std::string::npos) << app << " --" << flag << entry;
    }
  }
}

TEST(AppHelp, UnfoldShowsConfigKeysWithTheBuiltInDefaultsAndGroupsByTopic) {
  const AppRun r = run_app("unfold", "--help");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Options defaults;
  EXPECT_NE(r.out.find("[config key cascade.k_iter, default " +
                       std::to_string(defaults.cascade.k_iter) + "]"),
            std::string::npos);
  EXPECT_NE(r.out.find("[config key cascade.num, default " +
                       std::to_string(defaults.cascade.num_cascades) + "]"),
            std::string::npos);
  // Topics in order: input and output first, the cascade's flags under theirs.
  const size_t io = r.out.find("\nInput and output:\n"), cascade = r.out.find("\nCascade:\n"),
               tets = r.out.find("\nTetrahedralization:\n");
  ASSERT_NE(io, std::string::npos);
  ASSERT_NE(cascade, std::string::npos);
  ASSERT_NE(tets, std::string::npos);
  EXPECT_LT(io, cascade);
  const size_t k_iter = r.out.find("\n  --k_iter ");
  EXPECT_GT(k_iter, cascade);
  EXPECT_LT(k_iter, r.out.find("\n\n", cascade + 1));
  EXPECT_GT(r.out.find("\n  --tet_route "), tets);
}

TEST(AppHelp, HelpfullAddsLoggingFlagsWithoutPaths) {
  const AppRun help = run_app("unfold_shape", "--help"),
               full = run_app("unfold_shape", "--helpfull");
  ASSERT_EQ(full.exit_code, 0) << full.err;
  EXPECT_EQ(full.out.rfind(help.out, 0), 0u) << "--helpfull does not start with --help";
  EXPECT_NE(full.out.find("\n  --logtostderr "), std::string::npos);
  EXPECT_NE(full.out.find("\n  --v "), std::string::npos);
  EXPECT_EQ(full.out.find(UNFOLD_SOURCE_DIR), std::string::npos);
  EXPECT_EQ(full.out.find("Flags from"), std::string::npos);
}

// A line in glog's own format: severity letter, date, time, thread id, file:line].
const std::regex kGlogPrefix("^[IWEF][0-9]{8} [0-9:.]+ +[0-9]+ [^ ]+:[0-9]+\\] ");

// Each line of `err` starts with "unfold: " and has no glog prefix; how many
// start with "unfold: <start>".
int count_plain_lines(const std::string& err, const std::string& start) {
  int count = 0;
  for (const std::string& line : lines(err)) {
    EXPECT_FALSE(std::regex_search(line, kGlogPrefix)) << line;
    EXPECT_EQ(line.rfind("unfold: ", 0), 0u) << line;
    count += line.rfind("unfold: " + start, 0) == 0;
  }
  return count;
}

TEST(AppHelp, VerbosityAddsStageThenIterationLinesNamingTheTool) {
  test::TempDir dir;
  const std::string input = dir.file("sphere.off");
  write_surface_mesh(input, test::uv_sphere(8, 12));
  const auto run = [&](const std::string& flags) {
    const AppRun r =
        run_app("unfold", flags + " --input " + input + " --output " + dir.file("out.off"));
    EXPECT_EQ(r.exit_code, 0) << flags << ": " << r.err;
    return r;
  };
  EXPECT_EQ(run("").err, "");  // the summary line alone, on stdout
  const AppRun stages = run("-v");
  EXPECT_GE(count_plain_lines(stages.err, "cascade "), 1) << stages.err;
  EXPECT_GE(count_plain_lines(stages.err, "stage "), 3) << stages.err;
  EXPECT_EQ(count_plain_lines(stages.err, "iteration "), 0) << stages.err;
  for (const std::string flags : {"-vv", "-v 2", "--verbosity 2", "--verbosity=2"}) {
    const AppRun iterations = run(flags);
    EXPECT_GE(count_plain_lines(iterations.err, "iteration "), 1)
        << flags << ": " << iterations.err;
    EXPECT_GE(count_plain_lines(iterations.err, "stage "), 3) << flags << ": " << iterations.err;
  }

  // glog's --v=1: the iteration lines too, in glog's own format.
  const AppRun glog = run("--v=1");
  int glog_lines = 0;
  for (const std::string& line : lines(glog.err))
    glog_lines += std::regex_search(line, kGlogPrefix);
  EXPECT_GT(glog_lines, int(lines(stages.err).size())) << glog.err;

  const AppRun negative = run_app("unfold", "--verbosity -1 --input " + input);
  EXPECT_EQ(negative.exit_code, 2);
  EXPECT_EQ(negative.err, "unfold: error: --verbosity must be >= 0\n");
}

TEST(AppHelp, Wolf0PrintsNoGlogPrefix) {
  const std::string wolf = test::shared_data("tosca/wolf0.off");
  if (wolf.empty()) GTEST_SKIP() << "../shared/data/tosca/wolf0.off is absent";
  test::TempDir dir;
  const AppRun r = run_app(
      "unfold", "-v --input " + wolf + " --output " + dir.file("wolf.off") + " --metrics none");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const std::string& line : lines(r.err)) {
    EXPECT_FALSE(std::regex_search(line, kGlogPrefix)) << line;
    EXPECT_EQ(line.rfind("unfold: ", 0), 0u) << line;
  }
  EXPECT_NE(r.err.find("\nunfold: cascade 1/"), std::string::npos) << r.err;
}

TEST(AppHelp, WarningsAndErrorsAreOneLineNamingTheTool) {
  test::TempDir dir;
  const std::string input = dir.file("sphere.off");
  write_surface_mesh(input, test::uv_sphere(8, 12));
  // A starting beta below the bound (stretch.weight (n/lambda_2 - 1)) is raised, with a warning.
  const AppRun warned =
      run_app("unfold", "--input " + input + " --beta 0.01 --output " + dir.file("warned.off"));
  ASSERT_EQ(warned.exit_code, 0) << warned.err;
  const std::vector<std::string> warned_lines = lines(warned.err);
  EXPECT_TRUE(std::any_of(warned_lines.begin(), warned_lines.end(), [](const std::string& line) {
    return line.rfind("unfold: warning: beta ", 0) == 0;
  })) << warned.err;
  const AppRun failed = run_app(
      "unfold", "--input " + dir.file("missing.off") + " --output " + dir.file("failed.off"));
  EXPECT_NE(failed.exit_code, 0);
  ASSERT_EQ(lines(failed.err).size(), 1u) << failed.err;
  EXPECT_EQ(failed.err.rfind("unfold: error: ", 0), 0u) << failed.err;
}

}  // namespace
}  // namespace unfold
