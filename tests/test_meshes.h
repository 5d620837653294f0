// Small meshes built in code for the unit tests, and the shared-data lookup.
#pragma once

#include <Eigen/Geometry>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <utility>

#include "mesh/surface_mesh.h"
#include "mesh/tet_mesh.h"

namespace unfold::test {

/// Signed volume enclosed by a closed surface (divergence theorem, polygons
/// fanned): positive when its faces are oriented outwards.
inline double signed_volume(const SurfaceMesh& m) {
  const Eigen::MatrixX3i F = triangulate_faces(m);
  double v = 0;
  for (Eigen::Index t = 0; t < F.rows(); ++t)
    v += m.V.row(F(t, 0)).dot(m.V.row(F(t, 1)).cross(m.V.row(F(t, 2)))) / 6;
  return v;
}

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

/// Two octahedra overlapping each other in one surface mesh (self-intersecting).
inline SurfaceMesh two_interpenetrating_octahedra() {
  SurfaceMesh folded = octahedron();
  const SurfaceMesh other = octahedron();
  folded.V.conservativeResize(12, 3);
  folded.V.bottomRows(6) = other.V.rowwise() + Eigen::RowVector3d(0.5, 0.3, 0.2);
  for (auto f : other.faces) {
    for (int& v : f) v += 6;
    folded.faces.push_back(f);
  }
  return folded;
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

/// A box of nx x ny x nz cubes, each split into 6 tetrahedra around its main diagonal.
inline TetMesh grid_tet_mesh(int nx, int ny, int nz, double spacing = 1.0) {
  auto id = [&](int i, int j, int k) { return (k * (ny + 1) + j) * (nx + 1) + i; };
  TetMesh mesh;
  mesh.V.resize((nx + 1) * (ny + 1) * (nz + 1), 3);
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i)
        mesh.V.row(id(i, j, k)) << i * spacing, j * spacing, k * spacing;
  mesh.T.resize(6 * nx * ny * nz, 4);
  int t = 0;
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        const int c[8] = {id(i, j, k),         id(i + 1, j, k),        id(i, j + 1, k),
                          id(i + 1, j + 1, k), id(i, j, k + 1),        id(i + 1, j, k + 1),
                          id(i, j + 1, k + 1), id(i + 1, j + 1, k + 1)};
        const int paths[6][2] = {{1, 3}, {3, 2}, {2, 6}, {6, 4}, {4, 5}, {5, 1}};
        for (const auto& p : paths) mesh.T.row(t++) << c[0], c[p[0]], c[p[1]], c[7];
      }
  mesh.num_surface_vertices = int(mesh.V.rows());
  return mesh;
}

/// A random rotation from a fixed seed.
inline Eigen::Matrix3d random_rotation(unsigned seed) {
  std::srand(seed);
  Eigen::Quaterniond q(Eigen::Vector4d::Random().normalized());
  return q.toRotationMatrix();
}

// A small generated shape without any mirror symmetry: a sphere stretched
// into an ellipsoid with three bumps of different sizes at places that no
// mirror maps onto each other. The same surface at any resolution (rings,
// segments of the underlying sphere), so two resolutions are two meshings.
inline SurfaceMesh chiral_blob(int rings, int segments) {
  SurfaceMesh mesh = uv_sphere(rings, segments);
  const Eigen::Vector3d bumps[3] = {Eigen::Vector3d(0.8, 0.5, 0.3).normalized(),
                                    Eigen::Vector3d(-0.6, 0.1, 0.8).normalized(),
                                    Eigen::Vector3d(0.1, -0.9, -0.4).normalized()};
  const double heights[3] = {0.6, 0.4, 0.25};
  for (int i = 0; i < mesh.V.rows(); ++i) {
    const Eigen::Vector3d u = mesh.V.row(i).normalized();
    double r = 1;
    for (int k = 0; k < 3; ++k) r += heights[k] * std::exp(-(u - bumps[k]).squaredNorm() / 0.08);
    mesh.V.row(i) = (r * u).cwiseProduct(Eigen::Vector3d(1.8, 1.0, 0.8)).transpose();
  }
  return mesh;
}

/// Path of a file in the shared test data, or "" if the data is absent.
inline std::string shared_data(const std::string& relative) {
  const char* env = std::getenv("UNFOLD_SHARED_DATA");
  const std::string root = env ? env : UNFOLD_SOURCE_DIR "/../shared/data";
  const std::string path = root + "/" + relative;
  std::FILE* f = std::fopen(path.c_str(), "r");
  if (!f) return "";
  std::fclose(f);
  return path;
}

}  // namespace unfold::test
