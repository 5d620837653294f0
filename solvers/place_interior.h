// The interior of a tet mesh following its surface: when the unfolding is
// solved on the surface alone, the interior (Steiner) vertices are placed
// afterwards by ARAP on the tet edges with the surface vertices held where
// the solve put them, so the tet mesh stays as rigid as the surface allows.
#pragma once

#include <Eigen/Core>

#include "mesh/edge_graph.h"

namespace unfold {

/// Local-global ARAP on the graph's edges with vertices [0, num_fixed) held at
/// Q's rows; returns Q with the other rows moved. Stops when an iteration moves
/// the free vertices by less than `tolerance` times Q's RMS radius, or after
/// max_iterations.
/// @param graph the tet mesh's edge graph (n vertices)
/// @param P     rest positions, n x 3
/// @param Q     n x 3: rows [0, num_fixed) are kept, the others are the start
/// @throws UsageError if the sizes disagree or num_fixed is not in [1, n]
/// @throws NumericalError if some free vertex has no path to a fixed one
Eigen::MatrixX3d place_interior(const EdgeGraph& graph, const Eigen::MatrixX3d& P,
                                Eigen::MatrixX3d Q, int num_fixed, int max_iterations = 200,
                                double tolerance = 1e-7);

}  // namespace unfold
