// A shape from a rotation field (docs/method.md, pose invariance). The most
// pose-invariant states found are converged solves on the surface at low beta:
// their limbs point the same way whatever the input pose, but they are inflated
// (E_rig 5-8). Their per-vertex best rotations (from the rest tet mesh) keep
// the orientation and drop the inflation; integrating them gives a shape with
// the input's local detail in that common orientation.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "mesh/edge_graph.h"

namespace unfold {

struct IntegrateOptions {
  int iterations = 0;  ///< ARAP steps in all, the integration included; 0: off
  /// anchor of the steps after the first, in units of `lambda2`: deformation modes
  /// stiffer than about this are restored to the rest shape's, softer ones (the pose)
  /// stay where the integration put them
  double anchor = 20;
  double tolerance = 1e-4;  ///< the steps stop when they move less (relative to the radius)
  /// edge weights of every step: "uniform" or "inverse_length" (ArapSolveOptions::
  /// inverse_length_weights: long chords of a tet mesh do not stiffen its bending)
  std::string weights = "uniform";
  /// the surface's edges that no tet has join the steps' edges, their weights times
  /// this (the pipeline builds that graph: mesh/tet_and_surface_edge_graph.h); 0: the
  /// tets' edges alone
  double surface_edges = 0;
};

/// Where integrate_rotation_field spent its time (wall seconds).
struct IntegrateTimes {
  double integration = 0;  ///< the first step: the rotation field integrated
  double anchored = 0;     ///< the anchored steps after it
};

/// Integrates the rotation field of `Q` (best rotations from P, per vertex):
/// one ARAP step from Q with one vertex held, then up to iterations - 1 ARAP
/// steps anchored to that step's result with weight anchor * lambda2.
/// @param graph   edge graph of the tet mesh, connected
/// @param P       rest positions (n x 3)
/// @param Q       positions whose rotation field is integrated (n x 3)
/// @param lambda2 the anchor's unit, > 0: a lambda_2 (fiedler_value) of the shape, e.g.
///        of its surface's graph Laplacian, the same for every pose
/// @return zero-mean positions (n x 3); Q itself (centred) when iterations is 0
/// @param times   optional: the two parts' seconds
/// @param edge_factors optional: per edge of `graph` (its order), a factor of the
///        steps' weights (ArapSolveOptions::edge_factors); empty: none
/// @throws UsageError for mismatched sizes, negative options or unknown weights
Eigen::MatrixX3d integrate_rotation_field(const EdgeGraph& graph, const Eigen::MatrixX3d& P,
                                          const Eigen::MatrixX3d& Q, double lambda2,
                                          const IntegrateOptions& options,
                                          IntegrateTimes* times = nullptr,
                                          const std::vector<double>& edge_factors = {});

}  // namespace unfold
