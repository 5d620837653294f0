// docs/usage.md cannot drift from the code: every app flag (from the app's own
// --helpxml) and every config key (UNFOLD_CONFIG_KEYS) has a row with its default.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>

#include "config/config_keys.h"
#include "config/options.h"
#include "test_files.h"

namespace unfold {
namespace {

// The part of the page under "## title", up to the next "## ".
std::string section(const std::string& page, const std::string& title) {
  const size_t start = page.find("\n## " + title + "\n");
  if (start == std::string::npos) return "";
  return page.substr(start, page.find("\n## ", start + 1) - start);
}

// The table cells of the row whose first cell is `--flag`, without the first.
std::vector<std::string> row(const std::string& text, const std::string& flag) {
  const std::string start = "| `--" + flag + "` |";
  const size_t at = text.find(start);
  if (at == std::string::npos) return {};
  const std::string line = text.substr(at + 1, text.find('\n', at) - at - 1);
  std::vector<std::string> cells;
  std::stringstream in(line);
  for (std::string cell; std::getline(in, cell, '|');)
    cells.push_back(cell.substr(cell.find_first_not_of(' '),
                                cell.find_last_not_of(' ') - cell.find_first_not_of(' ') + 1));
  cells.erase(cells.begin());
  return cells;
}

std::string code(const std::string& value) { return value.empty() ? "(none)" : "`" + value + "`"; }

// Flag name -> default of the flags an app defines itself (not gflags' or glog's).
std::map<std::string, std::string> app_flags(const std::string& app, const test::TempDir& dir) {
  const std::string xml = dir.file(app + ".xml");
  (void)std::system(
      (std::string(UNFOLD_BIN_DIR) + "/" + app + " --helpxml >" + xml + " 2>/dev/null").c_str());
  const std::string text = test::read_text(xml);
  static const std::regex flag(
      "<flag><file>([^<]*)</file><name>([^<]*)</name><meaning>[^<]*</meaning>"
      "<default>([^<]*)</default>");
  std::map<std::string, std::string> flags;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), flag); it != std::sregex_iterator();
       ++it)
    if ((*it)[1].str().find("/apps/") != std::string::npos) flags[(*it)[2]] = (*it)[3];
  return flags;
}

TEST(Docs, UsageListsEveryFlagOfEveryAppWithItsDefault) {
  test::TempDir dir;
  const std::string page = test::read_text(UNFOLD_SOURCE_DIR "/docs/usage.md");
  ASSERT_FALSE(page.empty());
  std::set<std::string> key_flags;
#define UNFOLD_KEY_FLAG(flag, path, member, help) key_flags.insert(#flag);
  UNFOLD_CONFIG_KEYS(UNFOLD_KEY_FLAG)
#undef UNFOLD_KEY_FLAG
  int apps = 0;
  for (const auto& source : std::filesystem::directory_iterator(UNFOLD_SOURCE_DIR "/apps")) {
    if (source.path().extension() != ".cpp") continue;
    const std::string app = source.path().stem();
    ++apps;
    const std::string text = section(page, app);
    ASSERT_FALSE(text.empty()) << "docs/usage.md has no '## " << app << "' section";
    const auto flags = app_flags(app, dir);
    EXPECT_FALSE(flags.empty()) << app << " --helpxml listed no flags";
    for (const auto& [name, default_value] : flags) {
      if (key_flags.count(name)) continue;  // documented under "Config keys"
      const std::vector<std::string> cells = row(text, name);
      ASSERT_GE(cells.size(), 2u) << "docs/usage.md, " << app << ": no row for --" << name;
      EXPECT_EQ(cells[0], code(default_value)) << app << " --" << name;
    }
  }
  EXPECT_GE(apps, 2);
}

// YAML scalars compare as numbers when both are numbers ("1e-4" == "0.0001").
bool same_value(const YAML::Node& a, const YAML::Node& b) {
  if (a.IsSequence() || b.IsSequence()) {
    if (!a.IsSequence() || !b.IsSequence() || a.size() != b.size()) return false;
    for (size_t i = 0; i < a.size(); ++i)
      if (!same_value(a[i], b[i])) return false;
    return true;
  }
  try {
    return a.as<double>() == b.as<double>();
  } catch (const YAML::Exception&) {
    return a.as<std::string>() == b.as<std::string>();
  }
}

TEST(Docs, UsageListsEveryConfigKeyWithPathAndDefault) {
  const std::string text =
      section(test::read_text(UNFOLD_SOURCE_DIR "/docs/usage.md"), "Config keys");
  ASSERT_FALSE(text.empty()) << "docs/usage.md has no '## Config keys' section";
  const Options options;
  const YAML::Node defaults = YAML::Load(options_to_yaml(options));
  const auto check = [&](const std::string& flag, const std::string& path) {
    const std::vector<std::string> cells = row(text, flag);
    ASSERT_GE(cells.size(), 3u) << "docs/usage.md: no config key row for --" << flag;
    EXPECT_EQ(cells[0], "`" + path + "`") << flag;
    const size_t dot = path.find('.');
    const YAML::Node value = dot == std::string::npos
                                 ? defaults[path]
                                 : defaults[path.substr(0, dot)][path.substr(dot + 1)];
    ASSERT_TRUE(cells[1].size() > 2 && cells[1].front() == '`') << flag << ": " << cells[1];
    EXPECT_TRUE(same_value(YAML::Load(cells[1].substr(1, cells[1].size() - 2)), value))
        << flag << ": docs say " << cells[1] << ", the code " << YAML::Dump(value);
  };
#define UNFOLD_CHECK_KEY(flag, path, member, help) check(#flag, path);
  UNFOLD_CONFIG_KEYS(UNFOLD_CHECK_KEY)
#undef UNFOLD_CHECK_KEY
}

}  // namespace
}  // namespace unfold
