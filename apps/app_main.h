// What every unfold command-line app shares: gflags parsing that reports bad
// flags as usage errors (exit 2) instead of gflags' own exit 1, logging to
// stderr, and the mapping of library exceptions to one-line messages and exit
// codes (docs/errors.md).
#pragma once

#include <gflags/gflags.h>
#include <glog/logging.h>

#include <cstdio>
#include <functional>
#include <new>
#include <string>

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

/// Parses flags, then runs `body`, turning every exception into a one-line
/// "<name>: error: ..." on stderr and the exit code of its class.
inline int run_main(const char* name, int argc, char** argv, const std::function<int()>& body) {
  FLAGS_logtostderr = true;
  try {
    check_flags(argc, argv);
    gflags::ParseCommandLineFlags(&argc, &argv, true);
    google::InitGoogleLogging(name);
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
