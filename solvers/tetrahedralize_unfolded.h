// The tet mesh of the unfolded surface, put back into the input (docs/method.md,
// contact). Where an input's parts touch or pass through each other (a hand on
// a thigh, crossed legs), any tet mesh of the input's volume joins them: its
// tets bridge the contact, and a canonical form computed on it keeps the
// contact. The surface solve S (domain: surface) is not fooled by contact, as
// it uses the surface's own edges, and has its limbs apart. Tetrahedralizing S
// gives tets that join only what the surface joins; their rest state is then
// made by placing the interior vertices into the input's surface (ARAP, with
// S's tets, scaled to the input's area, as the reference shape), so that parts
// that touch in the input overlap there instead of being glued together
// (the idea of Sacht et al., "Consistent volumetric discretizations inside
// self-intersecting surfaces", SGP 2013, with S in place of their flow).
#pragma once

#include <Eigen/Core>

#include "mesh/surface_mesh.h"
#include "mesh/tet_mesh.h"
#include "tetra/tetrahedralize.h"

namespace unfold {

struct UnfoldedTetMesh {
  TetMesh rest;               ///< S's tets, the input's surface, the interior placed into it
  Eigen::MatrixX3d unfolded;  ///< positions of rest's vertices in S (S's own tet mesh)
  /// S's tetrahedralization, shape "unfolded", dropped_inverted_tets, inverted_rest_tets
  TetReport report;
};

/// The robust route's interior grid spacing in S that is, in the input, what
/// the input's own tets get: three times the input's mean edge length, times
/// S's inflation (the square root of its area over the input's). The default
/// spaces S's grid by S's own mean edge length (TetOptions::interior_spacing 0),
/// which a coarse surface solve, whose S is smoother, makes finer (david0: 20k
/// interior points against 2.6k; docs/performance.md).
double input_interior_spacing(const SurfaceMesh& input, const Eigen::MatrixX3d& S);

/// Tetrahedralizes the unfolded surface S and places its interior vertices
/// into the input surface; the tets inverted there are dropped, but for those
/// that keep the mesh connected (drop_inverted_tets).
/// @param input   the input surface (rest positions of the surface vertices)
/// @param S       unfolded positions of the input's vertices (rows of input.V)
/// @param options how S is tetrahedralized (route, quality)
/// @param surface_edges_join the solve joins the surface's edges to the tets'
///        (tet_and_surface_edge_graph): inverted tets are then kept only to join
///        interior vertices, not surface ones
/// @param placement_iterations ARAP steps placing the interior into the input
/// @return the rest tet mesh (surface rows = input.V) and its unfolded positions
/// @throws UsageError if S's size is not input's, NumericalError if S cannot be
///         tetrahedralized or the placement fails
UnfoldedTetMesh tetrahedralize_unfolded(const SurfaceMesh& input, const Eigen::MatrixX3d& S,
                                        const TetOptions& options, bool surface_edges_join = false,
                                        int placement_iterations = 100);

}  // namespace unfold
