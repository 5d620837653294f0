// Small meshes built in code for the unit tests.
#pragma once

#include <Eigen/Geometry>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "mesh/tet_mesh.h"

namespace unfold::testing {

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

}  // namespace unfold::testing
