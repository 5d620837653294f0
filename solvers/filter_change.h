// The soft joints' change kept at the scale of limbs (docs/method.md, soft
// joints): the second surface solve straightens the joints, but where a fine
// feature (a nose, lips) turns the rotation field as fast as a joint does, its
// softened edges let the stretch term squash it too. The change from the first
// solve to the second splits into its rotations and the rest (stretch); each
// is low-pass filtered at a physical length, so a limb's turn about its joint
// passes whole while a face's wrinkles do not.
#pragma once

#include <Eigen/Core>

#include "mesh/edge_graph.h"

namespace unfold {

struct FilterChangeOptions {
  /// the rotation change's filter length, in P's units; 0: kept whole
  double rotation_length = 0;
  /// the rest's (stretch's) filter length, in P's units; 0: kept whole
  double stretch_length = 0;
};

/// S2 with its change from S1 low-pass filtered. With D_i the best rotation
/// from S1 to S2 of vertex i's cell (uniform weights) and rebuild(D) the
/// positions whose edges best match S1's turned by D (uniform graph Laplacian,
/// S2's mean):
///   S = rebuild(F_r(D)) + F_s(S2 - rebuild(D)),
/// F_r filtering log D_i, F_s positions, each F = (I + l^2 / 1.5 L_P)^-1 with
/// L_P the graph Laplacian of weights 1 / |p_i - p_j|^2 (about -l^2 times the
/// Laplace-Beltrami operator on a regular triangulation: a filter of physical
/// length l, whatever the meshing). A rigid motion of S1 comes back unchanged,
/// and so does S2 with both lengths 0. A limb turned about a joint keeps its
/// turn beyond a length l of the joint; wrinkles finer than l are flattened.
/// @param graph   the solve's edge graph (n vertices, one component or more)
/// @param P       rest positions, n x 3: the lengths the filters measure
/// @param S1, S2  the first and the second solution, n x 3
/// @param options lengths >= 0, finite
/// @returns S, n x 3, with S2's mean
/// @throws UsageError if the sizes disagree or a length is negative or not finite
Eigen::MatrixX3d filter_change(const EdgeGraph& graph, const Eigen::MatrixX3d& P,
                               const Eigen::MatrixX3d& S1, const Eigen::MatrixX3d& S2,
                               const FilterChangeOptions& options);

}  // namespace unfold
