// What the text mesh readers (OFF, OBJ, ASCII PLY) share: the file's content
// lines split into tokens, whole-token number parsing, and their errors.
#pragma once

#include <charconv>
#include <cstdint>
#include <istream>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

namespace unfold {

using Tokens = std::vector<std::string_view>;

/// @throws InputError "cannot read '<path>': <what>"
[[noreturn]] void fail_reading(const std::string& path, const std::string& what);

/// A whole token as a number (a leading '+' allowed); from_chars also takes
/// "nan" and "inf". False for anything else, nothing thrown.
template <typename T>
bool parse_number(std::string_view s, T* value) {
  if (!s.empty() && s[0] == '+') s.remove_prefix(1);
  const auto result = std::from_chars(s.data(), s.data() + s.size(), *value);
  return result.ec == std::errc() && result.ptr == s.data() + s.size();
}

/// A whole token as a vertex index in the range of int.
bool parse_index(std::string_view s, int* value);

/// Refuses a header that declares more elements than the file can hold,
/// before anything is allocated or looped over (a corrupt count must not hang
/// a reader). @throws InputError if min_bytes > file_size
void check_declared_size(const std::string& path, const std::string& declared, double min_bytes,
                         std::uintmax_t file_size);

/// The content lines of a text file, split into whitespace-separated tokens;
/// blank lines and '#' comments are skipped. The rest of the stream is read
/// into memory at once (at disk speed) and split there.
class TextLines {
 public:
  TextLines(std::istream& in, const std::string& path);

  /// Tokens of the next content line (valid while this object lives); false at end of file.
  bool next(Tokens* tokens);

  /// The whole current line, comments included, without its line break.
  std::string_view text() const { return text_; }

  /// The bytes after the current line (a binary body after a text header).
  std::string_view rest() const { return std::string_view(data_).substr(at_); }

  /// @throws InputError naming the path and the current line
  [[noreturn]] void fail(const std::string& what) const;

 private:
  std::string data_;
  const std::string& path_;
  size_t at_ = 0;  // start of the next line
  std::string_view text_;
  int line_ = 0;
};

}  // namespace unfold
