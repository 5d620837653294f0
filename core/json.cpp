#include "core/json.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iomanip>
#include <sstream>

namespace unfold {
namespace {

std::string quoted(const std::string& s) {
  std::ostringstream out;
  out << '"';
  for (char c : s) {
    if (c == '"' || c == '\\')
      out << '\\' << c;
    else if (static_cast<unsigned char>(c) < 0x20)
      out << "\\u" << std::hex << std::setw(4) << std::setfill('0') << int(c) << std::dec;
    else
      out << c;
  }
  out << '"';
  return out.str();
}

std::string number(double x) {
  if (!std::isfinite(x)) return "null";
  char text[32];
  for (int digits = 15; digits <= 17; ++digits) {
    std::snprintf(text, sizeof text, "%.*g", digits, x);
    if (std::strtod(text, nullptr) == x) break;
  }
  return text;
}

bool is_object(const Json& j) { return std::holds_alternative<JsonObject>(j.value); }

// depth 0 is the document itself.
void write(std::ostringstream& out, const Json& j, int depth) {
  const std::string indent(2 * depth + 2, ' '), close_indent(2 * depth, ' ');
  if (const auto* b = std::get_if<bool>(&j.value)) {
    out << (*b ? "true" : "false");
  } else if (const auto* i = std::get_if<int64_t>(&j.value)) {
    out << *i;
  } else if (const auto* x = std::get_if<double>(&j.value)) {
    out << number(*x);
  } else if (const auto* s = std::get_if<std::string>(&j.value)) {
    out << quoted(*s);
  } else if (const auto* a = std::get_if<JsonArray>(&j.value)) {
    const bool one_per_line = !a->empty() && is_object(a->front());
    out << (one_per_line ? "[\n" : "[");
    for (size_t k = 0; k < a->size(); ++k) {
      if (one_per_line) out << indent;
      write(out, (*a)[k], depth + 1);
      if (k + 1 < a->size()) out << (one_per_line ? ",\n" : ", ");
    }
    out << (one_per_line ? "\n" + close_indent + "]" : "]");
  } else {
    const auto& o = std::get<JsonObject>(j.value);
    const bool one_per_line = depth == 0;
    out << (one_per_line ? "{\n" : "{");
    for (size_t k = 0; k < o.size(); ++k) {
      if (one_per_line) out << indent;
      out << quoted(o[k].first) << ": ";
      write(out, o[k].second, depth + 1);
      if (k + 1 < o.size()) out << (one_per_line ? ",\n" : ", ");
    }
    out << (one_per_line ? "\n}" : "}");
  }
}

}  // namespace

std::string to_json_text(const Json& document) {
  std::ostringstream out;
  write(out, document, 0);
  out << '\n';
  return out.str();
}

}  // namespace unfold
