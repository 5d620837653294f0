#include "core/json.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <limits>
#include <string>

namespace unfold {
namespace {

// The text of a one-member document's value.
std::string value_text(const Json& value) {
  const std::string text = to_json_text(JsonObject{{"x", value}});
  const std::string prefix = "{\n  \"x\": ";
  EXPECT_EQ(text.substr(0, prefix.size()), prefix);
  return text.substr(prefix.size(), text.size() - prefix.size() - 3);  // "\n}\n"
}

TEST(Json, NumbersReadBackAsTheSameDoubleWithTheFewestDigits) {
  EXPECT_EQ(value_text(0.1), "0.1");
  EXPECT_EQ(value_text(1.5), "1.5");
  EXPECT_EQ(value_text(1e-300), "1e-300");
  for (double x : {1.0 / 3.0, 0.1 + 0.2, 2890.878985069923, -1.41291e+08 / 7.0}) {
    const std::string text = value_text(x);
    EXPECT_EQ(std::strtod(text.c_str(), nullptr), x) << text;
    EXPECT_LE(text.size(), 24u) << text;
  }
  EXPECT_EQ(value_text(std::numeric_limits<double>::quiet_NaN()), "null");
  EXPECT_EQ(value_text(-std::numeric_limits<double>::infinity()), "null");
  EXPECT_EQ(value_text(int64_t(1) << 40), "1099511627776");
}

TEST(Json, StringsAreEscaped) { EXPECT_EQ(value_text("a\"b\\c\n"), "\"a\\\"b\\\\c\\u000a\""); }

TEST(Json, TopLevelMembersAndArraysOfObjectsGoOnePerLine) {
  const Json document = JsonObject{{"flag", true},
                                   {"nested", JsonObject{{"a", 1}, {"b", "x"}}},
                                   {"list", JsonArray{1, 2.5, false}},
                                   {"empty", JsonArray{}},
                                   {"rows", JsonArray{JsonObject{{"i", 1}}, JsonObject{{"i", 2}}}}};
  EXPECT_EQ(to_json_text(document),
            "{\n"
            "  \"flag\": true,\n"
            "  \"nested\": {\"a\": 1, \"b\": \"x\"},\n"
            "  \"list\": [1, 2.5, false],\n"
            "  \"empty\": [],\n"
            "  \"rows\": [\n"
            "    {\"i\": 1},\n"
            "    {\"i\": 2}\n"
            "  ]\n"
            "}\n");
}

}  // namespace
}  // namespace unfold
