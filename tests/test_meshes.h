// Small meshes built in code for the mesh tests.
#pragma once

#include <cmath>
#include <utility>

#include "mesh/surface_mesh.h"

namespace unfold::test {

/// Regular tetrahedron, faces oriented outwards.
inline SurfaceMesh tetrahedron() {
  SurfaceMesh m;
  m.V.resize(4, 3);
  m.V << 1, 1, 1, 1, -1, -1, -1, 1, -1, -1, -1, 1;
  m.faces = {{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}};
  return m;
}

/// Octahedron with vertices on the axes, faces oriented outwards.
inline SurfaceMesh octahedron() {
  SurfaceMesh m;
  m.V.resize(6, 3);
  m.V << 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1;
  m.faces = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
             {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  return m;
}

/// Unit cube made of 6 quads, oriented outwards.
inline SurfaceMesh cube() {
  SurfaceMesh m;
  m.V.resize(8, 3);
  m.V << 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1;
  m.faces = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {2, 3, 7, 6}, {1, 2, 6, 5}, {0, 4, 7, 3}};
  return m;
}

/// UV sphere of radius `radius` with `rings` latitude bands and `segments`
/// longitude steps: 2 + (rings - 1) * segments vertices, closed, one component.
inline SurfaceMesh uv_sphere(int rings, int segments, double radius = 1.0) {
  SurfaceMesh m;
  m.V.resize(2 + (rings - 1) * segments, 3);
  m.V.row(0) << 0, 0, radius;
  for (int r = 1; r < rings; ++r)
    for (int s = 0; s < segments; ++s) {
      const double theta = M_PI * r / rings, phi = 2 * M_PI * s / segments;
      m.V.row(1 + (r - 1) * segments + s) << radius * std::sin(theta) * std::cos(phi),
          radius * std::sin(theta) * std::sin(phi), radius * std::cos(theta);
    }
  const int south = int(m.V.rows()) - 1;
  m.V.row(south) << 0, 0, -radius;
  const auto at = [&](int r, int s) { return 1 + (r - 1) * segments + (s % segments); };
  for (int s = 0; s < segments; ++s) {
    m.faces.push_back({0, at(1, s), at(1, s + 1)});
    for (int r = 1; r + 1 < rings; ++r) {
      m.faces.push_back({at(r, s), at(r + 1, s), at(r + 1, s + 1)});
      m.faces.push_back({at(r, s), at(r + 1, s + 1), at(r, s + 1)});
    }
    m.faces.push_back({south, at(rings - 1, s + 1), at(rings - 1, s)});
  }
  return m;
}

/// Three triangles sharing the edge 0-1 (a non-manifold "book" of three pages).
inline SurfaceMesh three_pages() {
  SurfaceMesh m;
  m.V.resize(5, 3);
  m.V << 0, 0, 0, 0, 0, 1, 1, 0, 0, 0, 1, 0, -1, -1, 0;
  m.faces = {{0, 1, 2}, {0, 1, 3}, {0, 1, 4}};
  return m;
}

}  // namespace unfold::test
