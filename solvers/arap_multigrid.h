// The anchored steps' global matrix L + A as an algebraic multigrid hierarchy:
// the alternative to its factorization on large tet meshes, where the factor's
// fill and its solves (bound by reading it from memory) grow faster than the
// mesh. One V-cycle is the L-BFGS steps' initial inverse Hessian; CG with it
// solves to a tolerance where an exact solve is wanted (the pose pull's filter).
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <memory>

#include "mesh/edge_graph.h"
#include "solvers/arap_solve.h"
#include "solvers/projected_cg.h"
#include "solvers/smoothed_aggregation.h"

namespace unfold {

struct ArapMultigrid {
  RowSparse matrix;  ///< arap_global_matrix: L + A on the free rows
  AmgData amg;       ///< its smoothed-aggregation hierarchy
};

/// Builds L + A (as arap_factorization would factorize it) and its hierarchy.
/// It depends on neither Q nor the rotations, so a caller can make it beside
/// other work and hand it to arap_solve.
/// @param graph, P, options as arap_factorization's
/// @throws UsageError as arap_factorization
std::unique_ptr<ArapMultigrid> arap_multigrid_precomputation(const EdgeGraph& graph,
                                                             const Eigen::MatrixX3d& P,
                                                             const ArapSolveOptions& options);

/// One V-cycle for (L + A) x = b: a fixed symmetric positive definite
/// approximation of (L + A)^-1 b. @param b free rows x 3; x resized
void arap_multigrid_vcycle(const ArapMultigrid& multigrid, const Eigen::MatrixX3d& b,
                           Eigen::MatrixX3d* x);

/// (L + A) x = b by CG preconditioned with V-cycles, each column to |r| <=
/// tolerance |b|. The default serves the integration's one step and the pose
/// pull's filter, whose results the anchored steps then move until a step is
/// below 1e-4 of the radius: at 1e-6 they differ from 1e-10's by at most 2.4e-6
/// of it, in 20-22 CG iterations instead of 32-34 (186k-vertex scan;
/// docs/performance.md, large scans).
/// @throws NumericalError if CG does not converge within its iterations
void arap_multigrid_solve(const ArapMultigrid& multigrid, const Eigen::MatrixX3d& b,
                          Eigen::MatrixX3d* x, double tolerance = 1e-6);

}  // namespace unfold
