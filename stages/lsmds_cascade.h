// Stage: method lsmds, the LSMDS baseline (solvers/lsmds.h) in the shape of a
// cascade's result.
#pragma once

#include <Eigen/Core>

#include "mesh/edge_graph.h"
#include "solvers/cascade.h"
#include "solvers/lsmds.h"

namespace unfold {

/// LSMDS has no cascade: one stage, iterations = Guttman transforms, energy =
/// the stress (beta 0 in the history); reached_band is true (no band applies).
/// @param P  rest positions of the graph's vertices
/// @throws as lsmds()
CascadeResult lsmds_cascade(const EdgeGraph& graph, const Eigen::MatrixX3d& P,
                            const LsmdsOptions& options);

}  // namespace unfold
