#include "mesh/refine_faces.h"

#include <array>
#include <map>
#include <string>
#include <utility>

#include "core/errors.h"

namespace unfold {
namespace {

using Edge = std::pair<int, int>;

Edge edge_key(int a, int b) { return a < b ? Edge{a, b} : Edge{b, a}; }

}  // namespace

SurfaceMesh refine_faces(const SurfaceMesh& mesh, const std::vector<int>& selected) {
  const int num_faces = int(mesh.faces.size());
  const int num_vertices = int(mesh.V.rows());
  for (int f = 0; f < num_faces; ++f) {
    const auto& face = mesh.faces[size_t(f)];
    if (face.size() != 3)
      throw UsageError("refine_faces: face " + std::to_string(f) + " has " +
                       std::to_string(face.size()) + " vertices (triangles only)");
    for (int v : face)
      if (v < 0 || v >= num_vertices)
        throw UsageError("refine_faces: face " + std::to_string(f) + " names vertex " +
                         std::to_string(v) + " of " + std::to_string(num_vertices));
  }
  std::vector<char> red(size_t(num_faces), 0);
  for (int f : selected) {
    if (f < 0 || f >= num_faces)
      throw UsageError("refine_faces: selected face " + std::to_string(f) + " of " +
                       std::to_string(num_faces));
    red[size_t(f)] = 1;
  }

  // Split edges get their midpoint's index in the order they are first met,
  // which makes the output deterministic.
  std::map<Edge, int> midpoint;
  int next_vertex = num_vertices;
  const auto split_edges_of = [&](int f) {
    const auto& face = mesh.faces[size_t(f)];
    for (int k = 0; k < 3; ++k) {
      const auto inserted = midpoint.emplace(edge_key(face[size_t(k)], face[size_t(k + 1) % 3]), 0);
      if (inserted.second) inserted.first->second = next_vertex++;
    }
  };
  for (int f = 0; f < num_faces; ++f)
    if (red[size_t(f)]) split_edges_of(f);
  // Closure: a face with two split edges would need a split into three with
  // a poorer angle; promoting it to red keeps the children similar to it.
  for (bool changed = true; changed;) {
    changed = false;
    for (int f = 0; f < num_faces; ++f) {
      if (red[size_t(f)]) continue;
      const auto& face = mesh.faces[size_t(f)];
      int split = 0;
      for (int k = 0; k < 3; ++k)
        split += int(midpoint.count(edge_key(face[size_t(k)], face[size_t(k + 1) % 3])));
      if (split >= 2) {
        red[size_t(f)] = 1;
        split_edges_of(f);
        changed = true;
      }
    }
  }

  SurfaceMesh out;
  out.V.resize(next_vertex, 3);
  out.V.topRows(num_vertices) = mesh.V;
  for (const auto& [edge, m] : midpoint)
    out.V.row(m) = 0.5 * (mesh.V.row(edge.first) + mesh.V.row(edge.second));
  out.faces.reserve(mesh.faces.size() + 3 * midpoint.size());
  for (int f = 0; f < num_faces; ++f) {
    const auto& face = mesh.faces[size_t(f)];
    std::array<int, 3> mid;  // mid[k]: midpoint of edge (face[k], face[k+1]), or -1
    for (int k = 0; k < 3; ++k) {
      const auto it = midpoint.find(edge_key(face[size_t(k)], face[size_t(k + 1) % 3]));
      mid[size_t(k)] = it == midpoint.end() ? -1 : it->second;
    }
    if (red[size_t(f)]) {
      for (int k = 0; k < 3; ++k)
        out.faces.push_back({face[size_t(k)], mid[size_t(k)], mid[size_t(k + 2) % 3]});
      out.faces.push_back({mid[0], mid[1], mid[2]});
      continue;
    }
    int k = 0;
    while (k < 3 && mid[size_t(k)] < 0) ++k;
    if (k == 3) {
      out.faces.push_back(face);
      continue;
    }
    const int a = face[size_t(k)], b = face[size_t(k + 1) % 3], c = face[size_t(k + 2) % 3];
    out.faces.push_back({a, mid[size_t(k)], c});
    out.faces.push_back({mid[size_t(k)], b, c});
  }
  return out;
}

}  // namespace unfold
