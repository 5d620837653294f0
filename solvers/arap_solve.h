// ARAP (as-rigid-as-possible) by local-global or L-BFGS steps on an edge
// graph, with some vertices held and the others optionally pulled back to
// where they start. Two uses (docs/method.md):
// - domain: surface places the interior (Steiner) vertices after the surface
//   solve, the surface vertices held;
// - integrate: turns a rotation field into a shape (one step, one vertex
//   held), then restores local detail with the start anchored, so that the
//   steps do not drift back to ARAP's own minimum, the input pose.
#pragma once

#include <Eigen/Core>
#include <memory>
#include <string>
#include <vector>

#include "mesh/edge_graph.h"
#include "solvers/sparse_ldlt.h"

namespace unfold {

struct ArapMultigrid;  // solvers/arap_multigrid.h

struct ArapSolveOptions {
  int num_fixed = 1;         ///< vertices [0, num_fixed) are held at Q's rows
  int max_iterations = 200;  ///< local-global steps at most
  /// stop when a step moves every free vertex by less than this times Q's RMS radius
  /// (L-BFGS steps: a step taken whole, neither halved nor the plain step after a reset)
  double tolerance = 1e-7;
  /// weight a of a |q_i - q_i^start|^2 per free vertex, in units of the
  /// uniform graph Laplacian (whose diagonal is the degree; shared among the
  /// vertices as anchor_by_stiffness says); 0: none
  double anchor = 0;
  /// Anderson acceleration window of the steps (0: plain steps). An
  /// extrapolated step is kept only if it lowers the energy.
  int anderson = 5;
  /// Edge weights w_ij: false, uniform (1); true, inversely proportional to the
  /// edge's rest length |p_i - p_j| (a spring's stiffness), scaled to mean 1.
  /// A tet mesh's long chords then weigh no more than the short edges they
  /// span, instead of dominating the stiffness of bending (docs/method.md).
  bool inverse_length_weights = false;
  /// Optional factors of the edge weights, one per edge of the graph (its order),
  /// each finite and > 0; empty: none.
  std::vector<double> edge_factors;
  /// How the anchor is shared: false, `anchor` on every free vertex; true,
  /// `anchor` times the vertex's own stiffness as the mesh makes it, k_i =
  /// sum_j w_ij |p_i - p_j|^2 with w_ij the length weights alone (uniform or
  /// inverse length; the edge factors weigh edges, not the mesh's density),
  /// over the free vertices' mean k (arap_anchor_weights). Alike for every
  /// vertex, the anchor holds a finely meshed part (a face, a hand) harder
  /// against its own stiffness than a coarse one, so there modes of a given
  /// size follow the anchor's shape where elsewhere they get the rest shape's
  /// back (docs/method.md, the anchor).
  bool anchor_by_stiffness = false;
  /// L-BFGS window: > 0, quasi-Newton steps instead of local-global ones
  /// (LbfgsDirection, the global step's factor their initial inverse Hessian, scaled
  /// by its curvature along the last step over the energy's, in [1, 4];
  /// anderson unused), each halved until it lowers the energy enough, after
  /// three halvings a plain step; the steps' count to a tolerance drops
  /// several-fold where soft modes make local-global steps crawl
  /// (docs/performance.md, the anchored steps' convergence); 0: local-global
  int lbfgs = 0;
};

/// What arap_solve's steps did.
struct ArapSolveReport {
  int steps = 0;  ///< steps taken (local-global or L-BFGS)
  /// true: stopped by the tolerance or because a step no longer lowered the
  /// energy; false: by max_iterations (or there was no step to take)
  bool converged = false;
};

/// Per free vertex (rows num_fixed and up, in order), the weight a_i of its
/// anchor term a_i |q_i - q_i^start|^2: options.anchor, or with
/// options.anchor_by_stiffness options.anchor k_i / mean k (k as there; every k
/// zero: options.anchor).
/// @throws UsageError if P's rows are not the graph's vertices, num_fixed is not
///         in [1, n], or edge_factors are not one finite factor > 0 per edge
Eigen::VectorXd arap_anchor_weights(const EdgeGraph& graph, const Eigen::MatrixX3d& P,
                                    const ArapSolveOptions& options);

/// The matrix arap_solve's global steps solve with: the free rows' block of the
/// graph Laplacian (weighted as options.inverse_length_weights and the edge
/// factors) plus the anchor, L + A; symmetric positive definite when every
/// free vertex reaches a held one.
/// @param caller the name the errors start with
/// @throws UsageError as arap_factorization
Eigen::SparseMatrix<double> arap_global_matrix(const EdgeGraph& graph, const Eigen::MatrixX3d& P,
                                               const ArapSolveOptions& options,
                                               const std::string& caller = "arap_global_matrix");

/// The factor arap_solve's global steps solve with: the free rows' block of the
/// graph Laplacian (weighted as options.inverse_length_weights) plus the
/// anchor. It depends on neither Q nor the rotations, so a caller can make it
/// beside other work and hand it to arap_solve.
/// @param graph, P as arap_solve's; options: num_fixed, anchor, inverse_length_weights
/// @throws UsageError if P's rows are not the graph's vertices or num_fixed is
///         not in [1, n - 1], or edge_factors are not one finite factor > 0 per edge
/// @throws NumericalError if some free vertex has no path to a held one
std::unique_ptr<SparseLdlt> arap_factorization(const EdgeGraph& graph, const Eigen::MatrixX3d& P,
                                               const ArapSolveOptions& options);

/// Minimises the ARAP energy 1/2 sum_i sum_{j in N_i} w_ij |q_i - q_j - R_i (p_i - p_j)|^2
/// (plus the anchor; w_ij as options.inverse_length_weights) over the free rows of Q by
/// alternating best rotations R
/// (Kabsch, per vertex) and one sparse solve, or with options.lbfgs by L-BFGS
/// steps that solve with the same factor; returns Q with the free rows moved.
/// Stops after max_iterations steps, when a step (local-global: the plain one;
/// L-BFGS: the one taken) moves every free vertex by less than the tolerance,
/// or when a plain step no longer lowers the energy (then the iterate before
/// it is returned).
/// @param graph the edge graph (n vertices)
/// @param P     rest positions, n x 3
/// @param Q     n x 3: held rows and the free rows' start (and anchor)
/// @param factor arap_factorization(graph, P, options) made already, or null
///        (then it is made here, when there is a step to take)
/// @param report optional: the steps taken and whether they converged
/// @param multigrid optional, instead of a factor: arap_multigrid_precomputation(graph,
///        P, options). L-BFGS steps take its one V-cycle as their initial inverse
///        Hessian (more steps, about 1.2x, each cheaper); local-global steps solve by
///        CG with it. No factorization is made (docs/performance.md, large scans)
/// @throws UsageError if the sizes disagree, num_fixed is not in [1, n],
///         max_iterations < 0, tolerance < 0, anchor < 0, anderson < 0 or lbfgs < 0, or
///         edge_factors are not one finite factor > 0 per edge, or multigrid is given
///         with a factor or with another row count
/// @throws NumericalError if some free vertex has no path to a held one (checked
///         only when there is a step to take: max_iterations > 0)
Eigen::MatrixX3d arap_solve(const EdgeGraph& graph, const Eigen::MatrixX3d& P, Eigen::MatrixX3d Q,
                            const ArapSolveOptions& options = {},
                            const SparseLdlt* factor = nullptr, ArapSolveReport* report = nullptr,
                            const ArapMultigrid* multigrid = nullptr);

}  // namespace unfold
