#include "mesh/read_off.h"

#include <algorithm>
#include <cctype>
#include <climits>
#include <cstring>
#include <string_view>
#include <vector>

#include "mesh/read_with_openmesh.h"
#include "mesh/text_lines.h"

namespace unfold {
namespace {

// Walks the face records of a binary OFF ("k i1..ik", int32 each) after the
// vertices, so that a corrupt k is refused here: OpenMesh would allocate
// whatever it says (gigabytes, found by fuzzing). `body` starts at the counts.
void check_binary_off_faces(std::string_view body, const std::string& path, int32_t vertices,
                            int32_t faces) {
  const size_t skip = 12 + 12 * size_t(vertices);
  const std::string_view rest = body.substr(std::min(skip, body.size()));
  size_t at = 0;
  for (int32_t f = 0; f < faces; ++f) {
    int32_t k;
    if (skip > body.size() || at + 4 > rest.size())
      fail_reading(path,
                   "truncated: " + std::to_string(f) + " of " + std::to_string(faces) + " faces");
    std::memcpy(&k, rest.data() + at, 4);
    if (k < 1 || size_t(k) > (rest.size() - at - 4) / 4)
      fail_reading(path, "bad vertex count " + std::to_string(k) + " for face " +
                             std::to_string(f) + " (truncated or corrupt file)");
    at += 4 + 4 * size_t(k);
  }
}

}  // namespace

SurfaceMesh read_off(std::istream& in, const std::string& path, std::uintmax_t file_size) {
  TextLines lines(in, path);
  Tokens t;
  if (!lines.next(&t)) fail_reading(path, "the file is empty");
  std::string key(t[0]);
  if (key.find_first_of("4n") != std::string::npos)
    lines.fail("OFF variant '" + key + "' is not supported (only 3D positions)");
  // Letters only: OpenMesh, which reads binary OFF, parses the header again
  // and reads other counts after stray bytes (found by fuzzing).
  if (key.size() < 3 || key.compare(key.size() - 3, 3, "OFF") != 0 ||
      key.find_first_not_of("STCNOF") != std::string::npos) {
    for (char& c : key)
      if (!std::isprint(static_cast<unsigned char>(c))) c = '?';
    lines.fail("no OFF header (found '" + key + "')");
  }
  if (t.size() > 1 && t[1] == "BINARY") {
    int32_t counts[3];  // host byte order, as OpenMesh reads and writes it
    // Exactly as OpenMesh expects it, or it reads the body as text (fuzzing).
    const std::string_view header = lines.text(), body = lines.rest();
    if ((header != key + " BINARY" && header != key + " BINARY\r") || body.size() < sizeof counts ||
        (std::memcpy(counts, body.data(), sizeof counts), counts[0] < 1 || counts[1] < 1))
      fail_reading(path, "bad header or vertex and face counts in the binary OFF header");
    check_declared_size(
        path, std::to_string(counts[0]) + " vertices and " + std::to_string(counts[1]) + " faces",
        12.0 * counts[0] + 16.0 * counts[1], file_size);
    check_binary_off_faces(body, path, counts[0], counts[1]);
    return read_with_openmesh(path, counts[0], counts[1]);
  }
  t.erase(t.begin());
  if (t.empty() && !lines.next(&t)) fail_reading(path, "missing vertex and face counts");
  long long nv, nf;
  if (t.size() < 2 || !parse_number(t[0], &nv) || !parse_number(t[1], &nf) || nv < 0 || nf < 0 ||
      nv > INT_MAX || nf > INT_MAX)
    lines.fail("bad vertex and face counts");
  // Smallest possible text: "0 0 0\n" per vertex, "3 0 0 0\n" per face.
  check_declared_size(path, std::to_string(nv) + " vertices and " + std::to_string(nf) + " faces",
                      6.0 * nv + 8.0 * nf, file_size);

  std::vector<double> coords(3 * static_cast<size_t>(nv));
  for (long long i = 0; i < nv; ++i) {
    if (!lines.next(&t))
      fail_reading(path,
                   "truncated: " + std::to_string(i) + " of " + std::to_string(nv) + " vertices");
    if (t.size() < 3 || !parse_number(t[0], &coords[3 * i]) ||
        !parse_number(t[1], &coords[3 * i + 1]) || !parse_number(t[2], &coords[3 * i + 2]))
      lines.fail("bad coordinates for vertex " + std::to_string(i));
  }
  std::vector<std::vector<int>> faces(static_cast<size_t>(nf));
  for (long long f = 0; f < nf; ++f) {
    if (!lines.next(&t))
      fail_reading(path,
                   "truncated: " + std::to_string(f) + " of " + std::to_string(nf) + " faces");
    long long k;
    if (!parse_number(t[0], &k) || k < 0 || k >= (long long)t.size())
      lines.fail("bad vertex list for face " + std::to_string(f));
    faces[f].resize(size_t(k));
    for (long long j = 0; j < k; ++j)
      if (!parse_index(t[j + 1], &faces[f][j]))
        lines.fail("bad vertex index '" + std::string(t[j + 1]) + "' in face " + std::to_string(f));
  }
  return surface_mesh_from_rows(coords, std::move(faces));
}

}  // namespace unfold
