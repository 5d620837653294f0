// Splits a surface mesh into its connected components (vertices linked by
// shared faces), each a mesh of its own that remembers where it came from.
#pragma once

#include <vector>

#include "mesh/surface_mesh.h"

namespace unfold {

struct SurfaceComponent {
  SurfaceMesh mesh;           ///< the component's vertices (input order) and faces (input order)
  std::vector<int> vertices;  ///< input vertex index of each mesh vertex, ascending
};

/// The connected components of `mesh`, ordered by their lowest input vertex.
/// @param mesh a mesh with valid face indices and no unused vertex (e.g. one
///             that passed check_surface_mesh(mesh, false))
std::vector<SurfaceComponent> split_surface_components(const SurfaceMesh& mesh);

}  // namespace unfold
