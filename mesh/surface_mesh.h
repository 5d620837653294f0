// A surface mesh exactly as read from a file: vertex positions and the faces
// as given (polygons allowed, non-manifold configurations kept).
#pragma once

#include <Eigen/Core>
#include <vector>

namespace unfold {

struct SurfaceMesh {
  Eigen::MatrixX3d V;                   ///< one row per vertex
  std::vector<std::vector<int>> faces;  ///< vertex indices per face, as in the file
};

/// A mesh from x y z per vertex (coords.size() / 3 rows) and the faces.
SurfaceMesh surface_mesh_from_rows(const std::vector<double>& coords,
                                   std::vector<std::vector<int>> faces);

/// Fan-triangulates every face (triangles stay as they are), in face order.
Eigen::MatrixX3i triangulate_faces(const SurfaceMesh& mesh);

/// The mean length of the triangles' edges (each counted once per triangle); 0 without triangles.
double mean_edge_length(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F);

}  // namespace unfold
