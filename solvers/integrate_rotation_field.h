// A shape from a rotation field (docs/method.md, pose invariance). The most
// pose-invariant states found are converged solves on the surface at low beta:
// their limbs point the same way whatever the input pose, but they are inflated
// (E_rig 5-8). Their per-vertex best rotations (from the rest tet mesh) keep
// the orientation and drop the inflation; integrating them gives a shape with
// the input's local detail in that common orientation.
#pragma once

#include <Eigen/Core>
#include <future>
#include <memory>
#include <string>
#include <vector>

#include "mesh/edge_graph.h"
#include "solvers/arap_multigrid.h"
#include "solvers/arap_solve.h"

namespace unfold {

struct IntegrateOptions {
  int iterations = 0;  ///< ARAP steps in all, the integration included; 0: off
  /// anchor of the steps after the first, in units of `lambda2`: deformation modes
  /// stiffer than about this are restored to the rest shape's, softer ones (the pose)
  /// stay where the integration put them
  double anchor = 20;
  /// how the anchor is shared among the vertices: "uniform" (alike) or "stiffness"
  /// (in proportion to each vertex's own stiffness, ArapSolveOptions::
  /// anchor_by_stiffness: finely meshed parts keep their own detail as coarse ones do)
  std::string anchor_weights = "uniform";
  double tolerance = 1e-4;  ///< the steps stop when they move less (relative to the radius)
  /// L-BFGS window of the anchored steps (ArapSolveOptions::lbfgs); 0: local-global
  /// steps, Anderson-accelerated
  int lbfgs = 0;
  /// edge weights of every step: "uniform" or "inverse_length" (ArapSolveOptions::
  /// inverse_length_weights: long chords of a tet mesh do not stiffen its bending)
  std::string weights = "uniform";
  /// the surface's edges that no tet has join the steps' edges, their weights times
  /// this (the pipeline builds that graph: mesh/tet_and_surface_edge_graph.h); 0: the
  /// tets' edges alone
  double surface_edges = 0;
  /// how far the anchored steps start (and are anchored) toward Q's own shape, in [0, 1]:
  /// Q fitted to the integrated field by a similarity, the difference low-pass filtered
  /// by the steps' own factor, anchor (L + anchor)^-1, so that Q's pose (its softest
  /// modes) is kept and its inflation and local distortion are not. The integration
  /// alone drifts from Q's pose along the limbs, by as much as the input's local
  /// shapes differ between poses (docs/method.md, pose pull); 0: off. Without
  /// anchored steps (iterations < 2 or anchor 0) nothing filters it: no pull.
  double pose_pull = 0;
  /// from this many vertices the steps run on the graph renumbered in locality_order
  /// (mesh/locality_order.h), their result put back in the caller's order: a cell's
  /// neighbours are then near in memory, where a refined scan's are far apart. At
  /// 197k tet vertices that took the anchored steps from about 11 to 8.4 s; below
  /// about this the steps' data fit the caches (docs/performance.md, large scans)
  int locality_order_vertices = 100000;
  /// from this many vertices, with L-BFGS steps (lbfgs > 0), the anchored steps'
  /// initial inverse Hessian is one AMG V-cycle of their matrix instead of its
  /// factor, and the pose pull is filtered by CG (solvers/arap_multigrid.h); the
  /// integration's one solve is by CG as well, so no tet factorization is made. At 197k
  /// tet vertices that took the integration and the steps from 9.9-11.7 to 7.6-8.4 s
  /// and the run's peak memory from 0.95 to 0.71 GB (docs/performance.md, large scans)
  int multigrid_vertices = 100000;
};

/// The graph and positions the steps run on, renumbered.
struct LocalityOrdered {
  std::vector<int> order;  ///< locality_order: the new vertex i is the caller's order[i]
  EdgeGraph graph;
  Eigen::MatrixX3d P;  ///< the rest positions
};

/// The first step done (integrate_rotations) and what the anchored steps after
/// it need: their factorization or multigrid, being made on another thread meanwhile.
struct IntegratedRotations {
  /// the integrated field (n x 3; in `reordered`'s order if any); Q when iterations is 0
  Eigen::MatrixX3d positions;
  ArapSolveOptions anchored;                                 ///< the anchored steps' options
  std::future<std::unique_ptr<SparseLdlt>> anchored_factor;  ///< invalid: none made
  /// from options.multigrid_vertices, instead of the factor; invalid: none made
  std::future<std::unique_ptr<ArapMultigrid>> anchored_multigrid;
  /// pose_pull times (Q fitted to positions) - positions, filtered by the anchored
  /// steps before they start; empty: none
  Eigen::MatrixX3d pull;
  /// from options.locality_order_vertices: what the steps run on (the factor or multigrid
  /// refers to it, so it is held here); null: the caller's graph and P
  std::unique_ptr<const LocalityOrdered> reordered;
};

/// Integrates the rotation field of `Q` (best rotations from P, per vertex):
/// one ARAP step from Q with one vertex held; with options.pose_pull, also the
/// pull toward Q that the anchored steps filter. The anchored steps' factor (or
/// multigrid) depends on neither the integration nor its result: it is made on
/// another thread meanwhile (CHOLMOD factorizes on one thread, and so does the
/// integration's own factor).
/// @param graph   edge graph of the tet mesh, connected; it and P must outlive
///        the result's anchored_factor and anchored_multigrid
/// @param P       rest positions (n x 3)
/// @param Q       positions whose rotation field is integrated (n x 3)
/// @param lambda2 the anchor's unit, > 0: a lambda_2 (fiedler_value) of the shape, e.g.
///        of its surface's graph Laplacian, the same for every pose
/// @param edge_factors optional: per edge of `graph` (its order), a factor of the
///        steps' weights (ArapSolveOptions::edge_factors); empty: none
/// @throws UsageError for mismatched sizes, negative options, unknown weights or
///         anchor_weights, or a pose_pull outside [0, 1]
IntegratedRotations integrate_rotations(const EdgeGraph& graph, const Eigen::MatrixX3d& P,
                                        const Eigen::MatrixX3d& Q, double lambda2,
                                        const IntegrateOptions& options,
                                        const std::vector<double>& edge_factors = {});

/// Up to iterations - 1 ARAP steps anchored to the integrated field with weight
/// anchor * lambda2 (integrate_rotations' options), the field first moved by
/// its pull, filtered: (L + A)^-1 A pull, A the anchor weights (a = anchor *
/// lambda2 per vertex, or shared by stiffness).
/// @param report optional: the anchored steps taken and whether they converged
///        (ArapSolveReport; none taken: 0 steps, converged)
/// @return zero-mean positions (n x 3)
/// @throws UsageError for mismatched sizes
Eigen::MatrixX3d anchored_steps(const EdgeGraph& graph, const Eigen::MatrixX3d& P,
                                IntegratedRotations integrated, ArapSolveReport* report = nullptr);

/// integrate_rotations, then anchored_steps.
/// @return zero-mean positions (n x 3); Q itself (centred) when iterations is 0
/// @throws as integrate_rotations
Eigen::MatrixX3d integrate_rotation_field(const EdgeGraph& graph, const Eigen::MatrixX3d& P,
                                          const Eigen::MatrixX3d& Q, double lambda2,
                                          const IntegrateOptions& options,
                                          const std::vector<double>& edge_factors = {});

}  // namespace unfold
