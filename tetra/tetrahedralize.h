// Turns a closed surface into a tetrahedral mesh whose first vertices are the
// surface vertices in input order. Routes are interchangeable behind this
// one function; the route used is reported.
#pragma once

#include <functional>
#include <string>

#include "mesh/surface_mesh.h"
#include "mesh/tet_mesh.h"
#include "tetra/fast_winding_number.h"

namespace unfold {

/// The robust route's interior grid spacing in mean surface edge lengths:
/// measured on the TOSCA/FAUST meshes (docs/tetrahedralization.md), lower E_rig
/// than twice it and a third of the interior points.
constexpr double kInteriorSpacingEdges = 3;

struct TetOptions {
  /// "conforming": TetGen's boundary-conforming mode (-pY), needs a clean surface;
  /// "robust": Delaunay of surface and interior points carved by the winding number;
  /// "auto": robust directly when the surface is known not to be a valid PLC
  /// (intersecting faces, vertices at one position), else conforming, and
  /// robust when conforming fails.
  std::string route = "auto";
  double quality = 2.0;   ///< TetGen -q radius-edge bound (conforming route); 0 turns it off
  double max_volume = 0;  ///< TetGen -a bound on tet volume (conforming route); 0: no bound
  /// robust route: the interior grid's spacing; 0: three times the surface's mean edge length
  double interior_spacing = 0;
  /// the unfolded shape's tets (solvers/tetrahedralize_unfolded.h): those whose
  /// quality (mesh/tet_quality.h) put back into the input is below this are
  /// dropped like inverted ones; 0: only inverted ones
  double unfolded_min_quality = 0;
};

struct TetReport {
  std::string route;  ///< the route that produced the mesh ("conforming" or "robust")
  int num_tets = 0;
  int num_interior_points = 0;  ///< Steiner points added inside (all after the surface ones)
  int num_removed_tets = 0;     ///< robust: Delaunay tets carved away as outside
  int num_rescued_tets = 0;     ///< robust: carved tets put back to connect every vertex
  /// pairs of surface triangles that intersect beyond what they share
  /// (intersecting_face_pairs), counted on every route
  int num_intersecting_faces = 0;
  /// auto: why the conforming route was not used: its error, or why it was not
  /// tried ("" when it produced the mesh)
  std::string fallback;
  double seconds = 0;
  /// what was tetrahedralized: "input", or "unfolded" (the surface solve's
  /// shape, solvers/tetrahedralize_unfolded.h, which also fills the next field)
  std::string shape = "input";
  /// unfolded: tets whose orientation at rest (put back into the input) is not
  /// the one they were made with, dropped (mesh/drop_inverted_tets.h)
  int dropped_inverted_tets = 0;
  /// unfolded: tets upright but flatter than unfolded_min_quality at rest, dropped
  int dropped_flat_tets = 0;
  /// unfolded: such tets kept, as the mesh needs them to stay connected
  int inverted_rest_tets = 0;
  /// shape contact: the surface's intersecting face pairs that are parts passing
  /// through each other (solvers/contact_bridges.h); when there are any, shape
  /// is "unfolded" and the input's tets are neither made nor checked
  int contact_face_pairs = 0;
  /// shape contact: some tet of the input bridges a contact
  /// (solvers/contact_bridges.h), so shape is "unfolded"; false also when
  /// the input's tets were not checked
  bool contact_bridge = false;
};

/// Tetrahedralizes a closed surface.
/// @param surface a checked surface (see check_surface_mesh): closed, one component
/// @param known_intersecting_faces the count of intersecting_face_pairs(surface) when
///        the caller has it (-1: counted here)
/// @returns a TetMesh with V.topRows(surface.V.rows()) == surface.V, every
///          surface vertex used by some tetrahedron
/// @throws UsageError for an unknown route, NumericalError when the route fails
///         (TetGen's error kind is named; auto fails only if robust fails too),
///         InputError for an open surface
TetMesh tetrahedralize(const SurfaceMesh& surface, const TetOptions& options,
                       TetReport* report = nullptr, int known_intersecting_faces = -1);

/// TetGen in boundary-conforming mode with no Steiner points on the surface
/// (switches -pYq, and -a when max_volume > 0: more interior points, for scale
/// tests). Needs a clean piecewise-linear complex: no self-intersections.
/// @param give_up see run_tetgen (tetra/run_tetgen.h)
/// @throws NumericalError when TetGen fails or is given up
TetMesh tetrahedralize_conforming(const SurfaceMesh& surface, double quality, double max_volume = 0,
                                  const std::function<bool()>& give_up = {});

/// The robust route's first steps, which need the surface alone: the
/// winding-number tree, the orientation and the interior grid points.
/// tetrahedralize() takes them while it counts intersecting faces (on the other
/// core), before it knows whether auto goes robust.
struct RobustStart {
  FastWindingNumberTree tree;  ///< over the surface's triangles (tree.F)
  double orientation = 1;      ///< -1 for an inward-oriented surface (negative volume)
  double mean_edge_length = 0;
  Eigen::MatrixX3d interior;  ///< the interior grid points (sheared)
  double seconds = 0;
};

/// @param spacing the interior grid's; 0: three times the surface's mean edge length
/// @throws InputError for fewer than 4 vertices or no faces
RobustStart robust_start(const SurfaceMesh& surface, double spacing = 0);

/// Delaunay tetrahedralization (delaunay_tets, CGAL) of the surface vertices and
/// interior grid points (spacing three times the mean edge length), keeping the tets
/// inside by the generalized winding number: at the centroid, and at the
/// midpoint of every edge joining two surface vertices that is not a surface
/// edge (so tets bridging two touching parts are carved). Works on
/// self-intersecting, non-manifold or slightly open surfaces; vertices and
/// faces are used as given, equal positions included.
/// @param start robust_start(surface)
/// @param report if not null, receives num_removed_tets and num_rescued_tets
/// @throws NumericalError if the Delaunay fails or a surface vertex is in no usable
///         tetrahedron (robust_start throws InputError for fewer than 4
///         vertices or no faces)
TetMesh tetrahedralize_robust(const SurfaceMesh& surface, const RobustStart& start,
                              TetReport* report = nullptr);

}  // namespace unfold
