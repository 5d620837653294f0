// Checks that an output file of the apps is complete and parses: surfaces
// (through the library's reader), VTU and TetGen tet meshes, JSON, CSV, PNG.
// Each returns an AssertionResult naming what is wrong.
#pragma once

#include <gtest/gtest.h>

#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "mesh/read_surface_mesh.h"

namespace unfold::test {

inline std::string file_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}

/// A surface the library reads back, finite, with `vertices` vertices (or at
/// most -vertices when negative: a simplified surface).
inline ::testing::AssertionResult IsSurface(const std::string& path, long vertices) {
  try {
    const SurfaceMesh mesh = read_surface_mesh(path);
    const long n = long(mesh.V.rows());
    if (!mesh.V.allFinite()) return ::testing::AssertionFailure() << path << ": non-finite vertex";
    if (vertices >= 0 ? n != vertices : n > -vertices || n < 4)
      return ::testing::AssertionFailure()
             << path << ": " << n << " vertices, expected " << (vertices >= 0 ? "" : "at most ")
             << std::labs(vertices);
  } catch (const std::exception& e) {
    return ::testing::AssertionFailure() << path << ": " << e.what();
  }
  return ::testing::AssertionSuccess();
}

/// A number (strtod consumes all of it and it is finite).
inline bool is_number(const std::string& token) {
  char* end = nullptr;
  const double x = std::strtod(token.c_str(), &end);
  return !token.empty() && *end == '\0' && std::isfinite(x);
}

/// Whitespace-separated tokens of `text`.
inline std::vector<std::string> tokens(const std::string& text) {
  std::istringstream in(text);
  std::vector<std::string> out;
  for (std::string t; in >> t;) out.push_back(t);
  return out;
}

/// The integer value of attribute `name="..."` after position `from`, or -1.
inline long xml_attribute(const std::string& text, const std::string& name, size_t from = 0) {
  const size_t at = text.find(name + "=\"", from);
  return at == std::string::npos ? -1 : std::atol(text.c_str() + at + name.size() + 2);
}

/// A VTK unstructured grid as write_tet_mesh writes it: every DataArray holds
/// as many numbers as its place asks (per point, per cell, 3 per point, 4 per
/// cell), and a "rigidity_error" point field is present.
inline ::testing::AssertionResult IsVtu(const std::string& path) {
  const std::string text = file_text(path);
  const long points = xml_attribute(text, "NumberOfPoints"),
             cells = xml_attribute(text, "NumberOfCells");
  if (text.rfind("<?xml", 0) != 0 || text.find("</VTKFile>") == std::string::npos || points <= 0 ||
      cells < 0)
    return ::testing::AssertionFailure() << path << ": not a complete VTU file";
  if (text.find("Name=\"rigidity_error\"") == std::string::npos)
    return ::testing::AssertionFailure() << path << ": no rigidity_error field";
  std::string section;
  for (size_t at = 0; (at = text.find('<', at)) != std::string::npos; ++at) {
    const size_t end = text.find('>', at);
    const std::string tag = text.substr(at + 1, end - at - 1);
    for (const char* s : {"PointData", "CellData", "Points", "Cells"})
      if (tag.rfind(s, 0) == 0 && (tag.size() == std::strlen(s) || tag[std::strlen(s)] == ' '))
        section = s;
    if (tag.rfind("DataArray ", 0) != 0) continue;
    const size_t close = text.find("</DataArray>", end);
    const std::vector<std::string> values = tokens(text.substr(end + 1, close - end - 1));
    const bool connectivity = tag.find("Name=\"connectivity\"") != std::string::npos;
    const long expected = section == "PointData" ? points
                          : section == "Points"  ? 3 * points
                          : connectivity         ? 4 * cells
                                                 : cells;
    if (long(values.size()) != expected)
      return ::testing::AssertionFailure() << path << ": <" << tag << "> in " << section << " has "
                                           << values.size() << " values, expected " << expected;
    for (const auto& v : values)
      if (!is_number(v)) return ::testing::AssertionFailure() << path << ": '" << v << "'";
  }
  return ::testing::AssertionSuccess();
}

/// TetGen's `x.node` and `x.ele`: counts in the first lines, then as many
/// rows, tet corners within the vertices.
inline ::testing::AssertionResult IsTetgenMesh(const std::string& node_path) {
  const std::string ele_path = node_path.substr(0, node_path.size() - 5) + ".ele";
  const std::vector<std::string> node = tokens(file_text(node_path)),
                                 ele = tokens(file_text(ele_path));
  if (node.size() < 4 || ele.size() < 3)
    return ::testing::AssertionFailure() << node_path << " or .ele: missing or empty";
  const long n = std::atol(node[0].c_str()), m = std::atol(ele[0].c_str());
  if (n <= 0 || long(node.size()) != 4 + 4 * n || long(ele.size()) != 3 + 5 * m)
    return ::testing::AssertionFailure() << node_path << ": counts do not match the rows";
  for (long t = 0; t < m; ++t)
    for (int k = 1; k <= 4; ++k)
      if (std::atol(ele[size_t(3 + 5 * t + k)].c_str()) >= n)
        return ::testing::AssertionFailure() << ele_path << ": tet " << t << " out of range";
  return ::testing::AssertionSuccess();
}

namespace json {

// Recursive descent over one JSON value; false at the first syntax error.
inline bool value(const std::string& s, size_t& i);

inline void space(const std::string& s, size_t& i) {
  while (i < s.size() && std::isspace(static_cast<unsigned char>(s[i]))) ++i;
}

inline bool string(const std::string& s, size_t& i) {
  if (s[i] != '"') return false;
  for (++i; i < s.size() && s[i] != '"'; ++i)
    if (s[i] == '\\') ++i;
  return i++ < s.size();
}

inline bool sequence(const std::string& s, size_t& i, char close, bool keys) {
  ++i;
  space(s, i);
  if (i < s.size() && s[i] == close) return ++i, true;
  while (i < s.size()) {
    space(s, i);
    if (keys) {
      if (!string(s, i)) return false;
      space(s, i);
      if (i >= s.size() || s[i++] != ':') return false;
    }
    if (!value(s, i)) return false;
    space(s, i);
    if (i < s.size() && s[i] == close) return ++i, true;
    if (i >= s.size() || s[i++] != ',') return false;
  }
  return false;
}

inline bool value(const std::string& s, size_t& i) {
  space(s, i);
  if (i >= s.size()) return false;
  if (s[i] == '{') return sequence(s, i, '}', true);
  if (s[i] == '[') return sequence(s, i, ']', false);
  if (s[i] == '"') return string(s, i);
  for (const char* word : {"true", "false", "null"})
    if (s.compare(i, std::strlen(word), word) == 0) return i += std::strlen(word), true;
  const size_t start = i;
  while (i < s.size() && std::strchr("+-.0123456789eE", s[i])) ++i;
  return is_number(s.substr(start, i - start));
}

}  // namespace json

/// One JSON object, nothing after it, with a finite "E_rig".
inline ::testing::AssertionResult IsMetricsJson(const std::string& path) {
  const std::string text = file_text(path);
  size_t i = 0;
  const bool parsed = !text.empty() && text[0] == '{' && json::value(text, i);
  json::space(text, i);
  if (!parsed || i != text.size())
    return ::testing::AssertionFailure()
           << path << ": not one JSON object (stopped at byte " << i << ")";
  const size_t at = text.find("\"E_rig\": ");
  char* end = nullptr;
  const double E_rig = at == std::string::npos ? NAN : std::strtod(text.c_str() + at + 9, &end);
  if (!std::isfinite(E_rig) || !std::strchr(",}\n", *end))
    return ::testing::AssertionFailure() << path << ": no finite E_rig";
  return ::testing::AssertionSuccess();
}

/// A header, then rows of as many fields as the header has names: numbers
/// after the first `text_columns` fields.
/// @param rows the number of rows expected; -1: any (none when a run needed
///             no iteration)
inline ::testing::AssertionResult IsCsv(const std::string& path, int text_columns = 0,
                                        int rows = -1) {
  std::istringstream lines(file_text(path));
  std::string header;
  std::getline(lines, header);
  const auto fields = [](const std::string& line) {
    std::vector<std::string> out(1);
    for (char c : line)
      if (c == ',')
        out.emplace_back();
      else
        out.back().push_back(c);
    return out;
  };
  if (header.empty() || is_number(fields(header).front()))
    return ::testing::AssertionFailure() << path << ": no header";
  const size_t columns = fields(header).size();
  int row = 0;
  for (std::string line; std::getline(lines, line); ++row) {
    const auto f = fields(line);
    if (f.size() != columns)
      return ::testing::AssertionFailure()
             << path << ": row " << row << " has " << f.size() << " fields, the header " << columns;
    for (size_t k = size_t(text_columns); k < f.size(); ++k)
      if (!is_number(f[k])) return ::testing::AssertionFailure() << path << ": '" << f[k] << "'";
  }
  if (rows >= 0 && row != rows)
    return ::testing::AssertionFailure() << path << ": " << row << " rows, expected " << rows;
  return ::testing::AssertionSuccess();
}

/// PNG signature, a non-empty IHDR and IEND as the last chunk.
inline ::testing::AssertionResult IsPng(const std::string& path) {
  const std::string b = file_text(path);
  const auto big_endian = [&](size_t at) {
    return (unsigned(uint8_t(b[at])) << 24) | (unsigned(uint8_t(b[at + 1])) << 16) |
           (unsigned(uint8_t(b[at + 2])) << 8) | unsigned(uint8_t(b[at + 3]));
  };
  if (b.size() < 45 || b.compare(0, 8, "\x89PNG\r\n\x1a\n") != 0 || b.compare(12, 4, "IHDR") != 0 ||
      big_endian(16) == 0 || big_endian(20) == 0 || b.compare(b.size() - 8, 4, "IEND") != 0)
    return ::testing::AssertionFailure() << path << ": not a complete PNG";
  return ::testing::AssertionSuccess();
}

}  // namespace unfold::test
