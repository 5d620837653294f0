// Validates a surface mesh before unfold builds anything on it: fatal defects
// throw, tolerable ones are counted and described.
#pragma once

#include <string>
#include <vector>

#include "mesh/surface_mesh.h"

namespace unfold {

/// Tolerable defects found by check_surface_mesh.
struct SurfaceReport {
  int num_boundary_edges = 0;         ///< edges used by exactly one face (open surface)
  int num_nonmanifold_edges = 0;      ///< edges used by more than two faces
  int num_misoriented_edges = 0;      ///< two-face edges both faces traverse the same way
  int num_nonmanifold_vertices = 0;   ///< vertices where separate fans of faces meet
  int num_components = 1;             ///< connected components (via shared vertices)
  std::vector<std::string> warnings;  ///< one line per kind of defect, with an example
};

/// Checks a mesh, in this order, and throws InputError (one line, naming the
/// vertex or face) at the first fatal defect: empty mesh; non-finite
/// coordinate; bounding-box diagonal above 1e30 or below 1e-30 (coordinates
/// too large or too small to process); face with fewer than 3 vertices; face index out of range; face
/// repeating a vertex; zero-area face (below 1e-12 x squared bounding-box
/// diagonal); vertex used by no face; more than one connected component
/// (only when `require_one_component`; otherwise they are counted).
/// @param mesh any mesh, e.g. straight from read_surface_mesh.
/// @return counts and warnings for boundary, non-manifold and misoriented
///         edges and non-manifold vertices.
SurfaceReport check_surface_mesh(const SurfaceMesh& mesh, bool require_one_component = true);

}  // namespace unfold
