// A tet mesh given by the user (TetWild, Gmsh, a simulation, an earlier
// run's --rest_tet_output) instead of one tetrahedralize makes: prepare_mesh's
// counterpart, after which unfold_prepared runs as usual.
#pragma once

#include <Eigen/Core>

#include "config/options.h"
#include "mesh/surface_mesh.h"
#include "pipeline/unfold_surface.h"

namespace unfold {

/// Checks that `surface` is the boundary of the tets T over vertices V and
/// orders the tet mesh as the solver expects: the surface's vertices first, in
/// its order, then the interior ones (sort_interior_vertices). The tet report's
/// route is "given".
/// @param surface  the surface (e.g. tet_mesh_boundary(V, T)); checked as prepare_mesh does
/// @param unfolded optional: where the tets were made (rows as V's; the point
///        array "unfolded" of a default run's --rest_tet_output): the default's
///        route then unfolds them as it did (PreparedMesh::unfolded_tet_positions)
/// A surface whose triangles are not all the tets' boundary (a carved tet mesh)
/// gets a warning. Given tets are unfolded whatever tetrahedralize.shape says
/// (but unfolded, which makes a tet mesh of its own).
/// @throws InputError if the surface fails the checks, has a vertex the tets do
///         not (match_tet_mesh_boundary) or a vertex off the surface is in no tetrahedron;
///         UsageError for bad options or simplify.target_vertices > 0 (a given
///         tet mesh is not simplified) or tetrahedralize.shape: unfolded, or
///         `unfolded` has other than V's rows
PreparedMesh prepare_mesh_from_tets(const SurfaceMesh& surface, const Eigen::MatrixX3d& V,
                                    const Eigen::MatrixX4i& T, const Options& options,
                                    const Eigen::MatrixX3d& unfolded = Eigen::MatrixX3d());

}  // namespace unfold
