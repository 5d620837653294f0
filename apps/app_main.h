// What every unfold command-line app shares: gflags parsing that reports bad
// flags as usage errors (exit 2) instead of gflags' own exit 1, the app's own
// --help (app_help.h), log lines on stderr as "<app>: ..." (glog's full prefix
// with --v >= 1 or an explicit --log_prefix), and the mapping of library
// exceptions to one-line messages and exit codes (docs/errors.md).
#pragma once

#include <gflags/gflags.h>
#include <glog/logging.h>

#include <cstdio>
#include <cstring>
#include <functional>
#include <new>
#include <string>

#include "apps/app_help.h"
#include "core/errors.h"

namespace unfold::app {

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

// glog's line prefix replaced by the app's name: "unfold: cascade 2: ...",
// "unfold: warning: ...". `data` is the name.
inline void plain_log_prefix(std::ostream& s, const google::LogMessageInfo& info, void* data) {
  s << static_cast<const char*>(data) << ':';
  switch (info.severity[0]) {
    case 'W':
      s << " warning:";
      break;
    case 'E':
      s << " error:";
      break;
    case 'F':
      s << " fatal:";
      break;
    default:
      break;
  }
}

// Log lines go to stderr, prefixed by the app's name unless the user asked for
// glog's own prefix (time, thread id, source line) with --v >= 1 or --log_prefix.
inline void start_logging(const char* name) {
  FLAGS_logtostderr = true;
  gflags::CommandLineFlagInfo log_prefix;
  const bool full_prefix =
      FLAGS_v > 0 || (gflags::GetCommandLineFlagInfo("log_prefix", &log_prefix) &&
                      !log_prefix.is_default && FLAGS_log_prefix);
  if (full_prefix)
    google::InitGoogleLogging(name);
  else
    google::InitGoogleLogging(name, plain_log_prefix, const_cast<char*>(name));
}

/// Parses flags (or prints the app's help for --help, --helpfull), then runs
/// `body`, turning every exception into a one-line "<name>: error: ..." on
/// stderr and the exit code of its class.
inline int run_main(const char* name, const AppHelp& help, int argc, char** argv,
                    const std::function<int()>& body) {
  try {
    bool full = false;
    if (asks_for_help(argc, argv, &full)) {
      std::fputs(help_text(name, help, full).c_str(), stdout);
      return 0;
    }
    gflags::SetUsageMessage(help.usage);  // for gflags' --helpxml
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
