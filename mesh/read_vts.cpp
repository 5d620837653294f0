#include "mesh/read_vts.h"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <vector>

#include "mesh/text_lines.h"

namespace unfold {

std::string vts_path(const std::string& mesh_path) {
  return std::filesystem::path(mesh_path).replace_extension(".vts").string();
}

Eigen::VectorXi read_vts(const std::string& path, int vertex_count, int expected_rows) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) fail_reading(path, "it is a directory");
  std::ifstream in(path, std::ios::binary);
  if (!in) fail_reading(path, std::strerror(errno));
  TextLines lines(in, path);
  std::vector<int> ids;
  Tokens t;
  while (lines.next(&t)) {
    long long id;
    if (t.size() != 1 || !parse_number(t[0], &id))
      lines.fail("expected one vertex id, found '" + std::string(lines.text()) + "'");
    if (id < 1 || id > vertex_count)
      lines.fail("vertex id " + std::to_string(id) + " is outside 1.." +
                 std::to_string(vertex_count) + " (ids are one-based; the mesh has " +
                 std::to_string(vertex_count) + " vertices)");
    ids.push_back(int(id - 1));
  }
  if (ids.empty()) fail_reading(path, "no vertex id");
  if (expected_rows >= 0 && int(ids.size()) != expected_rows)
    fail_reading(path, "holds " + std::to_string(ids.size()) + " vertex ids, expected " +
                           std::to_string(expected_rows));
  return Eigen::Map<const Eigen::VectorXi>(ids.data(), Eigen::Index(ids.size()));
}

}  // namespace unfold
