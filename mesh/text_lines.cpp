#include "mesh/text_lines.h"

#include <climits>
#include <cstring>

#include "core/errors.h"

namespace unfold {
namespace {

// isspace in the C locale, without the locale lookup per character.
bool is_space(char c) { return c == ' ' || (c >= '\t' && c <= '\r'); }

}  // namespace

void fail_reading(const std::string& path, const std::string& what) {
  throw InputError("cannot read '" + path + "': " + what);
}

bool parse_index(std::string_view s, int* value) {
  long long v;
  if (!parse_number(s, &v) || v < INT_MIN || v > INT_MAX) return false;
  *value = int(v);
  return true;
}

void check_declared_size(const std::string& path, const std::string& declared, double min_bytes,
                         std::uintmax_t file_size) {
  if (min_bytes > double(file_size))
    fail_reading(path, "the header declares " + declared + ", more than its " +
                           std::to_string(file_size) +
                           " bytes can hold (truncated or corrupt file)");
}

TextLines::TextLines(std::istream& in, const std::string& path) : path_(path) {
  char buffer[1 << 16];
  while (in.read(buffer, sizeof buffer) || in.gcount() > 0)
    data_.append(buffer, size_t(in.gcount()));
}

bool TextLines::next(Tokens* tokens) {
  while (at_ < data_.size()) {
    const char* start = data_.data() + at_;
    const char* newline = static_cast<const char*>(std::memchr(start, '\n', data_.size() - at_));
    const size_t length = newline ? size_t(newline - start) : data_.size() - at_;
    at_ += length + (newline ? 1 : 0);
    ++line_;
    text_ = std::string_view(start, length);
    const size_t end = std::min(text_.find('#'), text_.size());
    tokens->clear();
    size_t i = 0;
    while (i < end) {
      while (i < end && is_space(text_[i])) ++i;
      const size_t begin = i;
      while (i < end && !is_space(text_[i])) ++i;
      if (i > begin) tokens->emplace_back(text_.data() + begin, i - begin);
    }
    if (!tokens->empty()) return true;
  }
  return false;
}

void TextLines::fail(const std::string& what) const {
  fail_reading(path_, "line " + std::to_string(line_) + ": " + what);
}

}  // namespace unfold
