// Runs the command-line apps as subprocesses for the CLI, bad-input and
// option-matrix tests: exit code, stderr, and the check that a failed run wrote nothing.
#pragma once

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

namespace unfold::test {

struct AppRun {
  int exit_code;    ///< the process's exit status, -1 if it died from a signal
  std::string err;  ///< everything it wrote to stderr
  std::string out;  ///< everything it wrote to stdout (the summary line)
};

/// Runs `build/bin/<app> <args>` (args are passed through the shell); a
/// death by a signal, even reported by the shell as 128 + signal, gives -1.
inline AppRun run_app(const std::string& app, const std::string& args) {
  // One stderr file per process: ctest runs tests in parallel processes.
  const std::string stem = ::testing::TempDir() + app + "_std" + std::to_string(getpid());
  const std::string err_path = stem + "err.txt", out_path = stem + "out.txt";
  const int status = std::system(
      (std::string(UNFOLD_BIN_DIR) + "/" + app + " " + args + " 2>" + err_path + " >" + out_path)
          .c_str());
  const auto take = [](const std::string& path) {
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    std::remove(path.c_str());
    return text.str();
  };
  const bool exited = WIFEXITED(status) && WEXITSTATUS(status) < 128;
  return {exited ? WEXITSTATUS(status) : -1, take(err_path), take(out_path)};
}

/// Runs `build/bin/unfold <args>`.
inline AppRun run_unfold(const std::string& args) { return run_app("unfold", args); }

inline bool file_exists(const std::string& path) { return std::ifstream(path).good(); }

/// Runs unfold with `args --output output` and expects exit `code`, the one-line
/// error format with `words` in it, and no file at `output` afterwards.
inline void expect_failure(const std::string& args, int code, const std::string& words,
                           const std::string& output) {
  const AppRun r = run_unfold(args + " --output " + output);
  EXPECT_EQ(r.exit_code, code) << r.err;
  EXPECT_NE(r.err.find("unfold: error: "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(words), std::string::npos) << "'" << words << "' not in: " << r.err;
  EXPECT_FALSE(file_exists(output)) << "a failed run left " << output;
}

}  // namespace unfold::test
