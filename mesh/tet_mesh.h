// A tetrahedral mesh whose first vertices are the surface vertices, in the
// surface mesh's order, followed by interior (Steiner) vertices.
#pragma once

#include <Eigen/Core>
#include <string>

namespace unfold {

struct TetMesh {
  Eigen::MatrixX3d V;            ///< one row per vertex; rows [0, num_surface_vertices) = surface
  Eigen::MatrixX4i T;            ///< vertex indices per tetrahedron
  int num_surface_vertices = 0;  ///< count of leading rows of V that are surface vertices
};

}  // namespace unfold
