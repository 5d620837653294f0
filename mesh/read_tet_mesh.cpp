#include "mesh/read_tet_mesh.h"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <map>
#include <sstream>
#include <string_view>
#include <vector>

#include "core/ends_with.h"
#include "core/errors.h"
#include "mesh/text_lines.h"

namespace unfold {
namespace {

std::string read_all(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) fail_reading(path, "no such file or not readable");
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// Whitespace-separated tokens of a text, read one at a time.
class Words {
 public:
  /// hash_comments: '#' to the end of the line is a comment (TetGen, MEDIT; not Gmsh).
  Words(std::string_view text, const std::string& path, bool hash_comments = true)
      : text_(text), path_(path), hash_comments_(hash_comments) {}

  bool at_end() {
    skip_space();
    return at_ >= text_.size();
  }
  std::string_view next() {
    if (at_end()) fail("unexpected end of file");
    const size_t start = at_;
    while (at_ < text_.size() && !std::isspace(static_cast<unsigned char>(text_[at_]))) ++at_;
    return text_.substr(start, at_ - start);
  }
  template <typename T>
  T number() {
    const std::string_view word = next();
    T value;
    if (!parse_number(word, &value)) fail("'" + std::string(word) + "' is not a number");
    return value;
  }
  /// A count of records of at least `min_bytes` each, checked against what is left.
  long count(size_t min_bytes) {
    const long n = number<long>();
    if (n < 0 || size_t(n) * min_bytes > text_.size() - std::min(at_, text_.size()))
      fail("a count of " + std::to_string(n) + " records does not fit in the file");
    return n;
  }
  [[noreturn]] void fail(const std::string& what) const { fail_reading(path_, what); }

 private:
  void skip_space() {
    while (at_ < text_.size()) {
      if (text_[at_] == '#' && hash_comments_) {
        while (at_ < text_.size() && text_[at_] != '\n') ++at_;
      } else if (std::isspace(static_cast<unsigned char>(text_[at_]))) {
        ++at_;
      } else {
        break;
      }
    }
  }
  std::string_view text_;
  const std::string& path_;
  bool hash_comments_;
  size_t at_ = 0;
};

// Points and tets from a list of positions and 4-tuples of indices into it
// (`base`: the first index's number).
TetMeshData assemble(const std::vector<double>& xyz, const std::vector<long>& tets, long base,
                     const std::string& path) {
  TetMeshData mesh;
  const long n = long(xyz.size() / 3);
  mesh.V =
      Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>>(xyz.data(), n, 3);
  mesh.T.resize(Eigen::Index(tets.size() / 4), 4);
  for (size_t k = 0; k < tets.size(); ++k) {
    const long i = tets[k] - base;
    if (i < 0 || i >= n)
      fail_reading(path, "tetrahedron " + std::to_string(k / 4) + " has vertex " +
                             std::to_string(tets[k]) + ", not one of the " + std::to_string(n) +
                             " vertices");
    mesh.T(Eigen::Index(k / 4), Eigen::Index(k % 4)) = int(i);
  }
  if (mesh.T.rows() == 0) fail_reading(path, "no tetrahedra");
  return mesh;
}

// --- VTK XML (.vtu), ASCII DataArrays as write_tet_mesh (and meshio with binary=False) writes.

// The text of the DataArray whose opening tag contains `attribute`, within `scope`.
std::string_view data_array(std::string_view scope, const std::string& attribute,
                            const std::string& path) {
  for (size_t at = scope.find("<DataArray"); at != std::string_view::npos;
       at = scope.find("<DataArray", at + 1)) {
    const size_t close = scope.find('>', at);
    if (close == std::string_view::npos) break;
    const std::string_view tag = scope.substr(at, close - at);
    if (!attribute.empty() && tag.find(attribute) == std::string_view::npos) continue;
    if (tag.find("format=\"ascii\"") == std::string_view::npos)
      fail_reading(path,
                   "binary or appended VTU data is not supported (write it as ASCII, e.g. "
                   "meshio.write(..., binary=False))");
    const size_t end = scope.find("</DataArray>", close);
    if (end == std::string_view::npos) break;
    return scope.substr(close + 1, end - close - 1);
  }
  fail_reading(path, "no DataArray " + attribute);
}

// The first <name> element of text, its opening tag (which may carry
// attributes) to its closing tag; empty if there is none.
std::string_view find_element(std::string_view text, const std::string& name) {
  const std::string open = "<" + name;
  for (size_t start = text.find(open); start != std::string_view::npos;
       start = text.find(open, start + 1)) {
    const size_t after = start + open.size();
    // <Points> or <Points ...>, not <PointsOther>
    if (after < text.size() && text[after] != '>' &&
        !std::isspace(static_cast<unsigned char>(text[after])))
      continue;
    const size_t end = text.find("</" + name + ">", after);
    return end == std::string_view::npos ? std::string_view() : text.substr(start, end - start);
  }
  return {};
}

std::string_view element(std::string_view text, const std::string& name, const std::string& path) {
  const std::string_view found = find_element(text, name);
  if (found.empty()) fail_reading(path, "no <" + name + "> element");
  return found;
}

TetMeshData read_vtu(const std::string& path) {
  const std::string text = read_all(path);
  if (text.find("<VTKFile") == std::string::npos ||
      text.find("UnstructuredGrid") == std::string::npos)
    fail_reading(path, "not a VTK XML unstructured grid");
  if (text.find("<Piece") != text.rfind("<Piece"))
    fail_reading(path, "several pieces; one is supported");
  const auto numbers = [&path](std::string_view data, auto zero) {
    std::vector<decltype(zero)> values;
    Words words(data, path);
    while (!words.at_end()) values.push_back(words.template number<decltype(zero)>());
    return values;
  };
  const std::string_view cells = element(text, "Cells", path);
  const std::vector<double> xyz = numbers(data_array(element(text, "Points", path), "", path), 0.0);
  const std::vector<long> connectivity =
      numbers(data_array(cells, "Name=\"connectivity\"", path), 0L);
  const std::vector<long> offsets = numbers(data_array(cells, "Name=\"offsets\"", path), 0L);
  const std::vector<long> types = numbers(data_array(cells, "Name=\"types\"", path), 0L);
  if (xyz.size() % 3 != 0) fail_reading(path, "the point coordinates are not triples");
  if (types.size() != offsets.size())
    fail_reading(path, "the cells' offsets and types differ in count");
  constexpr long kVtkTetra = 10;
  for (size_t c = 0; c < types.size(); ++c)
    if (types[c] != kVtkTetra || offsets[c] != long(4 * (c + 1)))
      fail_reading(path, "cell " + std::to_string(c) + " is not a tetrahedron (VTK type " +
                             std::to_string(types[c]) + ")");
  if (connectivity.size() != 4 * types.size())
    fail_reading(path, "the connectivity does not match the cells");
  TetMeshData mesh = assemble(xyz, connectivity, 0, path);
  const std::string_view point_arrays = find_element(text, "PointData");
  if (point_arrays.find("Name=\"unfolded\"") != std::string_view::npos) {
    const std::vector<double> unfolded =
        numbers(data_array(point_arrays, "Name=\"unfolded\"", path), 0.0);
    if (unfolded.size() != xyz.size())
      fail_reading(path, "the point array 'unfolded' has " + std::to_string(unfolded.size()) +
                             " values for " + std::to_string(xyz.size() / 3) + " points x 3");
    mesh.unfolded = Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>>(
        unfolded.data(), mesh.V.rows(), 3);
  }
  return mesh;
}

// --- TetGen .node/.ele: "n 3 attributes markers" then "index x y z ...", and
// "m 4|10 attributes" then "index a b c d ...". Indices start at the .node's first.

TetMeshData read_tetgen(const std::string& path) {
  const std::string node_text = read_all(path);
  const std::string ele_path = path.substr(0, path.size() - 5) + ".ele";
  const std::string ele_text = read_all(ele_path);
  Words node(node_text, path), ele(ele_text, ele_path);
  const long n = node.count(8);
  if (node.number<int>() != 3) node.fail("not 3-dimensional");
  const int attributes = node.number<int>(), markers = node.number<int>();
  std::vector<double> xyz;
  long base = 0;
  for (long i = 0; i < n; ++i) {
    const long index = node.number<long>();
    if (i == 0) base = index;
    for (int a = 0; a < 3; ++a) xyz.push_back(node.number<double>());
    for (int a = 0; a < attributes + (markers != 0); ++a) node.number<double>();
  }
  const long m = ele.count(10);
  const int corners = ele.number<int>(), tet_attributes = ele.number<int>();
  if (corners != 4 && corners != 10)
    ele.fail("tetrahedra of " + std::to_string(corners) + " nodes");
  std::vector<long> tets;
  for (long t = 0; t < m; ++t) {
    ele.number<long>();
    for (int c = 0; c < corners; ++c) {
      const long v = ele.number<long>();
      if (c < 4) tets.push_back(v);  // a quadratic tet's corners come first
    }
    for (int a = 0; a < tet_attributes; ++a) ele.number<double>();
  }
  return assemble(xyz, tets, base, ele_path);
}

// --- Gmsh .msh, ASCII, versions 2.x and 4.x: the nodes, and the elements of
// type 4 (4-node tetrahedron); nodes are referred to by tag.

TetMeshData read_msh(const std::string& path) {
  const std::string text = read_all(path);
  Words words(text, path, false);
  if (words.next() != "$MeshFormat") words.fail("not a Gmsh file (no $MeshFormat)");
  const double version = words.number<double>();
  if (words.number<int>() != 0) words.fail("binary .msh is not supported (save it as ASCII)");
  if (version < 2 || version >= 5)
    words.fail("Gmsh format version " + std::to_string(version) + " (2.x and 4.x are supported)");
  const bool v4 = version >= 4;
  std::vector<double> xyz;
  std::map<long, long> index_of_tag;
  std::vector<long> tets;
  const auto node = [&](long tag) {
    index_of_tag[tag] = long(xyz.size() / 3);
    for (int a = 0; a < 3; ++a) xyz.push_back(words.number<double>());
  };
  // Nodes per element type (the types a tet mesh file may carry besides tets).
  const auto nodes_of = [&words](int type) {
    static const std::map<int, int> counts = {{1, 2}, {2, 3}, {3, 4}, {4, 4},   {5, 8}, {6, 6},
                                              {7, 5}, {8, 3}, {9, 6}, {11, 10}, {15, 1}};
    const auto it = counts.find(type);
    if (it == counts.end()) words.fail("unsupported element type " + std::to_string(type));
    return it->second;
  };
  while (!words.at_end()) {
    const std::string_view section = words.next();
    if (section == "$Nodes") {
      if (!v4) {
        for (long n = words.count(8), i = 0; i < n; ++i) node(words.number<long>());
      } else {
        const long blocks = words.count(8);
        words.count(2);
        words.number<long>(), words.number<long>();
        for (long b = 0; b < blocks; ++b) {
          words.number<int>(), words.number<int>();
          if (words.number<int>() != 0) words.fail("parametric nodes are not supported");
          const long n = words.count(8);
          std::vector<long> tags(static_cast<size_t>(n));
          for (long& tag : tags) tag = words.number<long>();
          for (const long tag : tags) node(tag);
        }
      }
    } else if (section == "$Elements") {
      const long blocks = words.count(4);
      if (v4) words.count(2), words.number<long>(), words.number<long>();
      for (long b = 0; b < blocks; ++b) {
        int type;
        long n = 1;
        if (v4) {
          words.number<int>(), words.number<int>();
          type = words.number<int>();
          n = words.count(4);
        } else {
          words.number<long>();
          type = words.number<int>();
          for (int t = words.number<int>(); t > 0; --t) words.number<long>();
        }
        for (long e = 0; e < n; ++e) {
          if (v4) words.number<long>();
          for (int c = 0; c < nodes_of(type); ++c) {
            const long tag = words.number<long>();
            if (type != 4) continue;
            const auto it = index_of_tag.find(tag);
            if (it == index_of_tag.end())
              words.fail("an element refers to node " + std::to_string(tag) + ", not in $Nodes");
            tets.push_back(it->second);
          }
        }
      }
    } else if (section.size() > 1 && section[0] == '$' && section.substr(0, 4) != "$End") {
      // Another section ($PhysicalNames, $Entities, $NodeData ...): skipped.
      const std::string end = "$End" + std::string(section.substr(1));
      while (words.next() != end) {
      }
    }
  }
  return assemble(xyz, tets, 0, path);
}

// --- MEDIT .mesh, ASCII: "Vertices n" (x y z ref) and "Tetrahedra n"
// (a b c d ref, 1-based); other element sections skipped.

TetMeshData read_medit(const std::string& path) {
  const std::string text = read_all(path);
  Words words(text, path);
  static const std::map<std::string, int> skipped = {{"Edges", 3},
                                                     {"Triangles", 4},
                                                     {"Quadrilaterals", 5},
                                                     {"Hexahedra", 9},
                                                     {"Corners", 1},
                                                     {"Ridges", 1},
                                                     {"RequiredVertices", 1},
                                                     {"RequiredEdges", 1},
                                                     {"Normals", 3},
                                                     {"Tangents", 3},
                                                     {"Prisms", 7}};
  std::vector<double> xyz;
  std::vector<long> tets;
  while (!words.at_end()) {
    const std::string keyword(words.next());
    if (keyword == "MeshVersionFormatted") {
      words.number<int>();
    } else if (keyword == "Dimension") {
      if (words.number<int>() != 3) words.fail("not 3-dimensional");
    } else if (keyword == "Vertices") {
      for (long n = words.count(8), i = 0; i < n; ++i) {
        for (int a = 0; a < 3; ++a) xyz.push_back(words.number<double>());
        words.number<long>();
      }
    } else if (keyword == "Tetrahedra") {
      for (long n = words.count(10), t = 0; t < n; ++t) {
        for (int c = 0; c < 4; ++c) tets.push_back(words.number<long>());
        words.number<long>();
      }
    } else if (keyword == "End") {
      break;
    } else if (const auto it = skipped.find(keyword); it != skipped.end()) {
      for (long n = words.count(2) * it->second, k = 0; k < n; ++k) words.next();
    } else {
      words.fail("unsupported MEDIT keyword '" + keyword + "'");
    }
  }
  return assemble(xyz, tets, 1, path);
}

}  // namespace

void check_tet_input_format(const std::string& path) {
  if (!ends_with(path, ".vtu") && !ends_with(path, ".node") && !ends_with(path, ".msh") &&
      !ends_with(path, ".mesh"))
    throw InputError("unsupported tet mesh format '" + path +
                     "' (use .vtu, .node with its .ele, .msh or .mesh)");
}

TetMeshData read_tet_mesh(const std::string& path) {
  check_tet_input_format(path);
  if (ends_with(path, ".vtu")) return read_vtu(path);
  if (ends_with(path, ".node")) return read_tetgen(path);
  if (ends_with(path, ".msh")) return read_msh(path);
  return read_medit(path);
}

}  // namespace unfold
