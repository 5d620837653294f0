// The per-vertex and per-tet fields written with the canonical tet mesh, so a
// viewer (ParaView) can colour where the unfolding stretched or bent.
#pragma once

#include "mesh/write_tet_mesh.h"
#include "pipeline/unfold_surface.h"

namespace unfold {

/// Fields of a finished run: per vertex "rigidity_error" (E_rig's term,
/// metrics.rigidity_per_vertex; only when E_rig was computed), "stretch_ratio"
/// (vertex_edge_ratio) and "edge_damage" (metrics.damage.per_vertex on the
/// surface vertices: the largest |ln r| of their surface edges; 0 on interior
/// vertices); per tet "volume_ratio" and "rigidity" (tet_deformation).
/// @param result a result of unfold_surface / unfold_prepared
/// @throws InputError if a rest tet or edge is degenerate
TetMeshFields canonical_tet_fields(const UnfoldResult& result);

/// Fields of the rest tet mesh (--rest_tet_output): per vertex "unfolded",
/// where the tets were made when that is not the rest (the unfolded shape's
/// tets, result.unfolded_tet_positions), so that given back (--tet_input,
/// read_tet_mesh) they unfold as they did; none otherwise.
TetMeshFields rest_tet_fields(const UnfoldResult& result);

}  // namespace unfold
