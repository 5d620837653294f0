// Every config key as a command-line flag (config/config_keys.h), for the apps
// that take the whole config: included once, at namespace scope, by an app's
// single translation unit (it defines the flags); config_flag_overrides() then
// collects the keys set on the command line, by YAML path.
#pragma once

#include <gflags/gflags.h>

#include <map>
#include <string>

#include "config/config_keys.h"

// The key and its default are shown by --help (apps/app_help.h).
#define UNFOLD_DEFINE_KEY_FLAG(flag, path, member, help) DEFINE_string(flag, "", help);
UNFOLD_CONFIG_KEYS(UNFOLD_DEFINE_KEY_FLAG)
#undef UNFOLD_DEFINE_KEY_FLAG

/// The config keys given as flags: YAML path -> value as typed.
inline std::map<std::string, std::string> config_flag_overrides() {
  std::map<std::string, std::string> overrides;
#define UNFOLD_COLLECT_KEY_FLAG(flag, path, member, help) \
  if (!FLAGS_##flag.empty()) overrides[path] = FLAGS_##flag;
  UNFOLD_CONFIG_KEYS(UNFOLD_COLLECT_KEY_FLAG)
#undef UNFOLD_COLLECT_KEY_FLAG
  return overrides;
}
