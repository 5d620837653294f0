// A JSON document as a value: what the library writes as text (the metrics
// JSON) and what language bindings turn into their own dictionaries, so both
// come from one description of the document.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace unfold {

struct Json;
using JsonArray = std::vector<Json>;
/// Members in the order they are written (not sorted).
using JsonObject = std::vector<std::pair<std::string, Json>>;

struct Json {
  /// A double that is not finite is written as null (JSON has no NaN or Inf).
  std::variant<bool, int64_t, double, std::string, JsonArray, JsonObject> value;

  Json(bool b) : value(b) {}
  Json(int i) : value(int64_t(i)) {}
  Json(int64_t i) : value(i) {}
  Json(double x) : value(x) {}
  Json(std::string s) : value(std::move(s)) {}
  Json(const char* s) : value(std::string(s)) {}
  Json(JsonArray a) : value(std::move(a)) {}
  Json(JsonObject o) : value(std::move(o)) {}
};

/// The document as text: the top-level object one member per line, arrays of
/// objects one element per line, everything else on one line. Numbers have
/// the fewest digits that read back as the same double.
std::string to_json_text(const Json& document);

}  // namespace unfold
