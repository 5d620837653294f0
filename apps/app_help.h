// The apps' --help: a usage line, then the app's own flags grouped by topic,
// each with its default (and config key), wrapped for a terminal. glog's and
// gflags' own flags only under --helpfull; no source paths either way (gflags'
// built-in help lists flags by the file that defines them).
#pragma once

#include <gflags/gflags.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cstdio>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "config/config_keys.h"
#include "config/options.h"

namespace unfold::app {

/// One topic of --help: its title and its flags, in the order shown.
struct FlagGroup {
  std::string title;
  std::vector<std::string> flags;
};

/// What an app's --help says.
struct AppHelp {
  std::string usage;    ///< after "usage: ", e.g. "unfold [--input shape.off] [flags]"
  std::string summary;  ///< one sentence: what the app does
  std::vector<FlagGroup> groups;
  /// The app defines a flag per config key (UNFOLD_CONFIG_KEYS): each is shown
  /// with its key and the built-in default, in the group its topic names.
  bool config_key_flags = false;
};

/// The --help topic of a config key, from its YAML section.
inline std::string config_key_topic(const std::string& path) {
  const std::string section = path.substr(0, path.find('.'));
  if (section == "simplify" || section == "tetrahedralize") return "Tetrahedralization";
  if (section == "beta" || section == "cascade") return "Cascade";
  if (section == "linear_solver") return "Linear solver (method local_global)";
  if (section == "stretch" || section == "arap" || section == "user_pairs" || section == "volume" ||
      section == "edge_length")
    return "Energy terms";
  if (section == "ceres" || section == "lsmds") return "Baselines (method ceres, lsmds)";
  if (section == "metrics") return "Metrics and pictures";
  if (section == "match") return "Matching (unfold_match)";
  return "Method and config";
}

namespace detail {

// `text` wrapped to `width` columns, every line after the first indented by `indent`.
inline std::string wrap(const std::string& text, size_t first_column, size_t indent,
                        size_t width = 100) {
  std::istringstream words(text);
  std::string out, word;
  size_t column = first_column;
  bool line_start = true;
  while (words >> word) {
    if (!line_start && column + 1 + word.size() > width) {
      out += "\n" + std::string(indent, ' ');
      column = indent;
      line_start = true;
    }
    if (!line_start) {
      out += ' ';
      ++column;
    }
    out += word;
    column += word.size();
    line_start = false;
  }
  return out;
}

// One flag's entry: name, then its help and default from column 26.
inline std::string flag_entry(const std::string& name, const std::string& help) {
  constexpr size_t kColumn = 26;
  std::string line = "  --" + name;
  if (line.size() + 2 > kColumn)
    line += "\n" + std::string(kColumn, ' ');
  else
    line += std::string(kColumn - line.size(), ' ');
  return line + wrap(help, kColumn, kColumn) + "\n";
}

inline std::string shown_default(const std::string& value) {
  return value.empty() ? "none" : value;
}

// A config key's built-in default as a command line writes it ("0.95,1.05").
inline std::string key_default(const YAML::Node& defaults, const std::string& path) {
  const size_t dot = path.find('.');
  const YAML::Node value = dot == std::string::npos
                               ? defaults[path]
                               : defaults[path.substr(0, dot)][path.substr(dot + 1)];
  if (!value.IsSequence()) return shown_default(value.as<std::string>());
  std::string items;
  for (const auto& item : value) items += (items.empty() ? "" : ",") + item.as<std::string>();
  return items.empty() ? "none" : items;
}

}  // namespace detail

/// The text of --help (full = false) or --helpfull (full = true: then also
/// every other flag the program knows, glog's and gflags' included).
/// Flags the app defines but no group lists still appear, under "Other".
inline std::string help_text(const std::string& name, const AppHelp& help, bool full) {
  std::vector<FlagGroup> groups = help.groups;
  const auto group = [&groups](const std::string& title) -> FlagGroup& {
    for (auto& g : groups)
      if (g.title == title) return g;
    groups.push_back({title, {}});
    return groups.back();
  };
  // flag -> (config key, default) of the key flags.
  std::vector<std::pair<std::string, std::pair<std::string, std::string>>> keys;
  if (help.config_key_flags) {
    const YAML::Node defaults = YAML::Load(options_to_yaml(Options()));
#define UNFOLD_HELP_KEY(flag, path, member, text) \
  keys.push_back({#flag, {path, detail::key_default(defaults, path)}});
    UNFOLD_CONFIG_KEYS(UNFOLD_HELP_KEY)
#undef UNFOLD_HELP_KEY
    for (const auto& [flag, key] : keys) group(config_key_topic(key.first)).flags.push_back(flag);
  }
  group("Messages").flags.push_back("verbosity");  // every app's (app_main.h)
  std::set<std::string> listed;
  for (const auto& g : groups) listed.insert(g.flags.begin(), g.flags.end());

  std::vector<gflags::CommandLineFlagInfo> all;
  gflags::GetAllFlags(&all);
  // The app's own flags: those defined in apps/ (gflags knows each one's file).
  for (const auto& info : all)
    if (!listed.count(info.name) && info.filename.find("apps/") != std::string::npos)
      group("Other").flags.push_back(info.name);

  std::string out = "usage: " + help.usage + "\n" + detail::wrap(help.summary, 0, 0) + "\n";
  for (const auto& g : groups) {
    if (g.flags.empty()) continue;
    out += "\n" + g.title + ":\n";
    for (const std::string& flag : g.flags) {
      gflags::CommandLineFlagInfo info;
      if (!gflags::GetCommandLineFlagInfo(flag.c_str(), &info)) continue;
      const auto key = std::find_if(keys.begin(), keys.end(),
                                    [&flag](const auto& k) { return k.first == flag; });
      const std::string tail =
          key != keys.end()
              ? " [config key " + key->second.first + ", default " + key->second.second + "]"
              : " [default " + detail::shown_default(info.default_value) + "]";
      out += detail::flag_entry(flag, info.description + tail);
    }
  }
  out += "\n" +
         detail::wrap("Messages go to stderr as '" + name +
                          ": ...' lines: warnings and errors always, each stage's lines with -v "
                          "(--verbosity 1), each iteration's too with -vv (--verbosity 2). glog's "
                          "--v=1 is -vv with glog's full prefix (time, thread, source line) on "
                          "every line, which --log_prefix alone also gives. --helpfull also lists "
                          "the flags of logging and flag parsing (glog, gflags).",
                      0, 0) +
         "\n";
  if (!full) return out;

  out += "\nLogging and flag parsing (glog, gflags):\n";
  std::vector<std::pair<std::string, std::string>> others;
  for (const auto& info : all)
    if (info.filename.find("apps/") == std::string::npos)
      others.push_back({info.name, info.description + " [default " +
                                       detail::shown_default(info.default_value) + "]"});
  std::sort(others.begin(), others.end());
  for (const auto& [flag, text] : others) out += detail::flag_entry(flag, text);
  return out;
}

}  // namespace unfold::app
