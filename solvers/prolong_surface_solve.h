// The surface solve carried from a coarse graph of the surface
// (mesh/coarsen_surface.h) back to every surface vertex: each cluster's best
// similarity (rotation and scale, from its coarse 1-ring to the solution's)
// applied to the surface's own edges and integrated, so the surface keeps its
// detail at the coarse solve's orientation and inflation.
#pragma once

#include <Eigen/Core>

#include "mesh/coarsen_surface.h"
#include "mesh/edge_graph.h"

namespace unfold {

/// Surfaces from this many vertices are carried by CG (prolong_surface_solve).
inline constexpr int kIterativeCarryVertices = 100000;

/// The surface's positions for a coarse solution:
/// min_S sum_{edges ij} |s_i - s_j - (A_i + A_j)/2 (p_i - p_j)|^2
///       + mu sum_i |s_i - (Sc_c + A_c (p_i - Vc_c))|^2,
/// with c the cluster of i, A_i = A_c its similarity and mu = 0.01 (the
/// second term only keeps the integration from drifting along long limbs).
/// @param graph   the surface's edge graph (coarsening.cluster_of's vertices)
/// @param P       the surface's rest positions (n x 3)
/// @param coarsening  from coarsen_surface(surface of P)
/// @param Sc      the coarse solution (one row per cluster)
/// @param iterative_from from this many vertices the solves are by CG with an
///        AMG preconditioner, to a relative residual of 1e-6, in place of a
///        sparse factor, whose fill grows as n^1.5 on a surface (1.2M vertices:
///        its analysis and factorization 15 s, the CG route's whole stage 10 s;
///        docs/performance.md, large scans)
/// @return zero-mean positions (n x 3)
/// @throws UsageError for mismatched sizes
/// @throws NumericalError if CG does not converge
Eigen::MatrixX3d prolong_surface_solve(const EdgeGraph& graph, const Eigen::MatrixX3d& P,
                                       const SurfaceCoarsening& coarsening,
                                       const Eigen::MatrixX3d& Sc,
                                       int iterative_from = kIterativeCarryVertices);

}  // namespace unfold
