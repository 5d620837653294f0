// What every unfold command-line app shares: gflags parsing that reports bad
// flags as usage errors (exit 2) instead of gflags' own exit 1, the app's own
// --help (app_help.h), how much it says (--verbosity, -v, -vv), log lines on
// stderr as "<app>: ..." (glog's full prefix with --v >= 1 or an explicit
// --log_prefix), the progress line on a terminal (ProgressScope), and the
// mapping of library exceptions to one-line messages and exit codes
// (docs/errors.md).
#pragma once

#include <gflags/gflags.h>
#include <glog/logging.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <new>
#include <string>
#include <vector>

#include "apps/app_help.h"
#include "core/errors.h"
#include "core/keep_freed_memory.h"
#include "core/progress.h"
#include "core/terminal_progress.h"

// Its own flag rather than glog's --v: that one also turns on the VLOG lines of
// the libraries below (Ceres) and glog's full prefix.
DEFINE_int32(verbosity, 0,
             "what goes to stderr besides warnings, errors and the results (and on a terminal "
             "the progress line): 1 (-v) also each stage's lines, 2 (-vv) each iteration's too");

namespace unfold::app {

// The verbosity shorthands as --verbosity: "-v" is 1, "-vv" 2 (one level per
// v), "-v N" (N digits) N. The apps take no other arguments, so a number after
// -v can only be its level.
inline std::vector<std::string> expand_verbosity_shorthands(int argc, char** argv) {
  std::vector<std::string> args;
  for (int i = 0; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--") {
      args.insert(args.end(), argv + i, argv + argc);
      break;
    }
    if (i == 0 || arg.size() < 2 || arg[0] != '-' ||
        arg.find_first_not_of('v', 1) != std::string::npos) {
      args.push_back(arg);
      continue;
    }
    std::string level = std::to_string(arg.size() - 1);
    if (arg == "-v" && i + 1 < argc && argv[i + 1][0] != '\0' &&
        std::strspn(argv[i + 1], "0123456789") == std::strlen(argv[i + 1]))
      level = argv[++i];
    args.push_back("--verbosity=" + level);
  }
  return args;
}

/// How much the app says on stderr: --verbosity, and at least 2 with glog's --v >= 1.
inline int verbosity() { return FLAGS_v > 0 ? std::max(FLAGS_verbosity, 2) : FLAGS_verbosity; }

// Validates each --flag against gflags' registry before gflags parses them.
inline void check_flags(int argc, char** argv) {
  for (int i = 1; i < argc; ++i) {
    std::string arg = argv[i];
    if (arg == "--") break;
    if (arg.size() < 2 || arg[0] != '-') continue;
    arg.erase(0, arg.find_first_not_of('-'));
    const size_t eq = arg.find('=');
    const std::string name = arg.substr(0, eq);
    if (name == "help" || name == "helpfull" || name == "version") continue;
    gflags::CommandLineFlagInfo info;
    if (!gflags::GetCommandLineFlagInfo(name.c_str(), &info)) {
      const bool negated_bool = name.rfind("no", 0) == 0 &&
                                gflags::GetCommandLineFlagInfo(name.c_str() + 2, &info) &&
                                info.type == "bool";
      if (!negated_bool) throw UsageError("unknown flag --" + name + " (see --help)");
      continue;
    }
    if (info.type == "bool" && eq == std::string::npos) continue;
    const std::string value = eq != std::string::npos ? arg.substr(eq + 1)
                              : i + 1 < argc          ? argv[++i]
                                                      : "";
    if (gflags::SetCommandLineOption(name.c_str(), value.c_str()).empty())
      throw UsageError("bad value '" + value + "' for --" + name);
  }
}

// "--help" and "--helpshort" ask for the app's help, "--helpfull" for all of it.
inline bool asks_for_help(int argc, char** argv, bool* full) {
  for (int i = 1; i < argc && std::strcmp(argv[i], "--") != 0; ++i) {
    std::string arg = argv[i];
    arg.erase(0, arg.find_first_not_of('-'));
    if (arg == "help" || arg == "helpshort" || arg == "helpfull") {
      *full = arg == "helpfull";
      return true;
    }
  }
  return false;
}

// What follows the app's name in a log line of this severity ('I', 'W', 'E', 'F').
inline const char* severity_tag(char severity) {
  switch (severity) {
    case 'W':
      return " warning:";
    case 'E':
      return " error:";
    case 'F':
      return " fatal:";
    default:
      return "";
  }
}

// glog's line prefix replaced by the app's name: "unfold: cascade 2: ...",
// "unfold: warning: ...". `data` is the name.
inline void plain_log_prefix(std::ostream& s, const google::LogMessageInfo& info, void* data) {
  s << static_cast<const char*>(data) << ':' << severity_tag(info.severity[0]);
}

// Whether log lines carry glog's full prefix (time, thread id, source line):
// with --v >= 1 or an explicit --log_prefix.
inline bool full_log_prefix() {
  gflags::CommandLineFlagInfo log_prefix;
  return FLAGS_v > 0 || (gflags::GetCommandLineFlagInfo("log_prefix", &log_prefix) &&
                         !log_prefix.is_default && FLAGS_log_prefix);
}

// Log lines go to stderr, prefixed by the app's name unless the user asked for
// glog's own prefix (time, thread id, source line) with --v >= 1 or --log_prefix.
// The library logs its stages' lines at INFO: shown from verbosity 1 only.
inline void start_logging(const char* name) {
  if (FLAGS_verbosity < 0) throw UsageError("--verbosity must be >= 0");
  FLAGS_logtostderr = true;
  if (verbosity() < 1) FLAGS_minloglevel = std::max(FLAGS_minloglevel, int(google::GLOG_WARNING));
  if (full_log_prefix())
    google::InitGoogleLogging(name);
  else
    google::InitGoogleLogging(name, plain_log_prefix, const_cast<char*>(name));
}

/// Whether stderr is a terminal that can rewrite a line in place (not TERM=dumb,
/// e.g. an editor's shell buffer).
inline bool stderr_is_terminal() {
  const char* term = std::getenv("TERM");
  return ::isatty(STDERR_FILENO) == 1 && !(term && std::strcmp(term, "dumb") == 0);
}

/// While alive, the app's listener of the library's reports (core/progress.h).
/// On a terminal, with `line`: the progress drawn as one line rewritten in
/// place on stderr, and the log lines printed above it (glog then writes
/// through this sink instead of to stderr); when stderr is a file or a pipe,
/// or without `line`: no line, the log lines plain as they come. From
/// verbosity 2 the solvers' lines of detail are logged too (at INFO).
class ProgressScope : public google::LogSink, public ProgressListener {
 public:
  ProgressScope(const char* name, bool line)
      : name_(name),
        display_(name, stderr, line && stderr_is_terminal(), 0.25),
        details_(verbosity() >= 2) {
    if (display_.active() || details_) set_progress_listener(this);
    if (!display_.active()) return;
    full_prefix_ = full_log_prefix();
    google::AddLogSink(this);
    for (int severity = 0; severity < google::NUM_SEVERITIES; ++severity)
      google::SetLogDestination(severity, "");  // no log files either
    saved_threshold_ = FLAGS_stderrthreshold;
    FLAGS_stderrthreshold = google::NUM_SEVERITIES;
    FLAGS_logtostderr = false;
  }
  ~ProgressScope() override { finish(); }
  ProgressScope(const ProgressScope&) = delete;
  ProgressScope& operator=(const ProgressScope&) = delete;

  /// Erases the progress line (before printing a result to stdout); glog
  /// writes to stderr again, and the library's reports go nowhere.
  void finish() {
    set_progress_listener(nullptr);
    if (!display_.active()) return;
    FLAGS_logtostderr = true;
    FLAGS_stderrthreshold = saved_threshold_;
    google::RemoveLogSink(this);
    display_.finish();
  }

  void stage(const std::string& name) override { display_.stage(name); }
  void step(int done, int total) override { display_.step(done, total); }
  bool wants_details() const override { return details_; }
  void detail(const std::string& line) override { LOG(INFO) << line; }

  void send(google::LogSeverity severity, const char* full_filename, const char* base_filename,
            int line, const google::LogMessageTime& time, const char* message,
            size_t length) override {
    (void)full_filename;
    display_.print_line(
        full_prefix_
            ? google::LogSink::ToString(severity, base_filename, line, time, message, length)
            : name_ + ":" + severity_tag(google::GetLogSeverityName(severity)[0]) + " " +
                  std::string(message, length),
        stderr);
  }

 private:
  std::string name_;
  TerminalProgress display_;
  const bool details_;
  bool full_prefix_ = false;
  int saved_threshold_ = 0;
};

/// Parses flags (or prints the app's help for --help, --helpfull), then runs
/// `body`, turning every exception into a one-line "<name>: error: ..." on
/// stderr and the exit code of its class.
inline int run_main(const char* name, const AppHelp& help, int argc, char** argv,
                    const std::function<int()>& body) {
  keep_freed_memory();
  try {
    bool full = false;
    if (asks_for_help(argc, argv, &full)) {
      std::fputs(help_text(name, help, full).c_str(), stdout);
      return 0;
    }
    gflags::SetUsageMessage(help.usage);  // for gflags' --helpxml
    std::vector<std::string> args = expand_verbosity_shorthands(argc, argv);
    std::vector<char*> pointers;
    for (std::string& arg : args) pointers.push_back(arg.data());
    argc = int(pointers.size());
    pointers.push_back(nullptr);
    argv = pointers.data();
    check_flags(argc, argv);
    gflags::ParseCommandLineFlags(&argc, &argv, true);
    start_logging(name);
    if (argc > 1)
      throw UsageError(std::string("unexpected argument '") + argv[1] + "' (flags start with --)");
    return body();
  } catch (const Error& e) {
    std::fprintf(stderr, "%s: error: %s\n", name, e.what());
    return e.exit_code();
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr, "%s: error: out of memory\n", name);
    return NumericalError("").exit_code();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s: error: internal error: %s\n", name, e.what());
    return 1;
  }
}

}  // namespace unfold::app
