#include "mesh/read_obj.h"

#include <climits>
#include <string_view>
#include <vector>

#include "mesh/text_lines.h"

namespace unfold {

SurfaceMesh read_obj(std::istream& in, const std::string& path) {
  TextLines lines(in, path);
  Tokens t;
  std::vector<double> coords;
  std::vector<std::vector<int>> faces;
  while (lines.next(&t)) {
    if (t[0] == "v") {
      double p[3];
      if (t.size() < 4 || !parse_number(t[1], &p[0]) || !parse_number(t[2], &p[1]) ||
          !parse_number(t[3], &p[2]))
        lines.fail("bad vertex " + std::to_string(coords.size() / 3 + 1));
      coords.insert(coords.end(), p, p + 3);
    } else if (t[0] == "f") {
      std::vector<int> face;
      for (size_t j = 1; j < t.size(); ++j) {
        long long i;
        if (!parse_number(t[j].substr(0, t[j].find('/')), &i) || i == 0)
          lines.fail("bad vertex reference '" + std::string(t[j]) + "'");
        i = i > 0 ? i - 1 : (long long)(coords.size() / 3) + i;
        if (i < INT_MIN || i > INT_MAX) lines.fail("vertex reference out of range");
        face.push_back(int(i));
      }
      faces.push_back(std::move(face));
    }
  }
  return surface_mesh_from_rows(coords, std::move(faces));
}

}  // namespace unfold
