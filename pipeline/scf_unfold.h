// method: scf inside unfold_prepared: the SCF baseline (solvers/scf.h) on a
// prepared mesh, its record in the shape every method's result has.
#pragma once

#include "mesh/edge_graph.h"
#include "pipeline/unfold_surface.h"

namespace unfold {

/// Runs scf() on result->tets (the surface alone when it has no tets) and
/// fills result->cascade (one stage: iterations = the skeleton's Guttman
/// transforms, energy = its MDS stress), result->skeleton and
/// result->skeleton_canonical (zero-mean frame, like cascade.positions); a
/// warning when the skeleton's repair left surface vertices out.
/// @pre result->surface and result->tets are set; graph is the tets' edge graph
/// @throws as scf()
void unfold_scf(const EdgeGraph& graph, const ScfOptions& options, UnfoldResult* result);

}  // namespace unfold
