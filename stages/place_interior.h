// Stage: domain surface on the input's tets. The energy lived on the surface;
// the interior then follows by ARAP on the tet edges, the surface held
// (docs/method.md, pose invariance).
#pragma once

#include <Eigen/Core>

#include "mesh/edge_graph.h"
#include "mesh/tet_mesh.h"

namespace unfold {

/// The tet vertices placed: the surface's at `surface_positions`, the interior
/// by ARAP from the rest interior (both zero-mean frames).
/// @param graph              the tets' edge graph
/// @param surface_positions  the surface solve's positions (num_surface_vertices x 3)
/// @return every tet vertex's position (tets.V.rows() x 3)
/// @throws as arap_solve
Eigen::MatrixX3d place_interior(const EdgeGraph& graph, const TetMesh& tets,
                                const Eigen::MatrixX3d& surface_positions);

}  // namespace unfold
