// Turns a closed surface into a tetrahedral mesh whose first vertices are the
// surface vertices in input order. Routes are interchangeable behind this
// one function; the route used is reported.
#pragma once

#include <string>

#include "mesh/surface_mesh.h"
#include "mesh/tet_mesh.h"

namespace unfold {

struct TetOptions {
  std::string route = "conforming";  ///< "conforming": TetGen's boundary-conforming mode (-pY)
  double quality = 2.0;              ///< TetGen -q radius-edge bound; 0 turns refinement off
  double max_volume = 0;             ///< TetGen -a bound on tet volume (mesh units^3); 0: no bound
};

struct TetReport {
  std::string route;  ///< the route that produced the mesh
  int num_tets = 0;
  int num_interior_points = 0;  ///< Steiner points added inside (all after the surface ones)
  double seconds = 0;
};

/// Tetrahedralizes a closed surface.
/// @param surface a checked surface (see check_surface_mesh): closed, one component
/// @returns a TetMesh with V.topRows(surface.V.rows()) == surface.V, every
///          surface vertex used by some tetrahedron
/// @throws UsageError for an unknown route, NumericalError when the route fails
///         (TetGen's error kind is named), InputError for an open surface
TetMesh tetrahedralize(const SurfaceMesh& surface, const TetOptions& options,
                       TetReport* report = nullptr);

/// TetGen in boundary-conforming mode with no Steiner points on the surface
/// (switches -pYq, and -a when max_volume > 0: more interior points, for scale
/// tests). Needs a clean piecewise-linear complex: no self-intersections.
TetMesh tetrahedralize_conforming(const SurfaceMesh& surface, double quality,
                                  double max_volume = 0);

}  // namespace unfold
