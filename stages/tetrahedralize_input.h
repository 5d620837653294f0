// Stage: the input surface's tet mesh, or, when none can be made and the
// options allow it, the surface alone (unfolded on its own edge graph).
#pragma once

#include <string>
#include <vector>

#include "mesh/surface_mesh.h"
#include "mesh/tet_mesh.h"
#include "tetra/tetrahedralize.h"

namespace unfold {

struct InputTets {
  TetMesh tets;  ///< interior vertices sorted (mesh/sort_interior_vertices.h)
  TetReport report;
  std::vector<std::string> warnings;  ///< the fallback's
};

/// A TetMesh without tets: the surface's vertices alone (T is 0 x 4).
TetMesh surface_alone(const SurfaceMesh& surface);

/// Tetrahedralizes a closed surface (tetrahedralize.*). With
/// fallback_surface_graph, an open surface or one that cannot be
/// tetrahedralized yields surface_alone (route "surface_graph", a warning).
/// @param open                 the surface has holes no route closes
/// @param known_intersections  intersecting face pairs counted already, or -1
/// @throws NumericalError when tetrahedralization fails and there is no fallback
InputTets tetrahedralize_input(const SurfaceMesh& surface, bool open, const TetOptions& options,
                               bool fallback_surface_graph, int known_intersections = -1);

}  // namespace unfold
