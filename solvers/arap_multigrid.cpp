#include "solvers/arap_multigrid.h"

#include <string>

#include "core/errors.h"

namespace unfold {

std::unique_ptr<ArapMultigrid> arap_multigrid_precomputation(const EdgeGraph& graph,
                                                             const Eigen::MatrixX3d& P,
                                                             const ArapSolveOptions& options) {
  auto multigrid = std::make_unique<ArapMultigrid>();
  const Eigen::SparseMatrix<double> M =
      arap_global_matrix(graph, P, options, "arap_multigrid_precomputation");
  multigrid->matrix = M;
  multigrid->matrix.makeCompressed();
  // Chebyshev smoothing of degree 3, not 2: 59 L-BFGS steps then end nearer
  // the factor's E_rig (docs/history/performance.md, 2026-12-07).
  AmgOptions amg;
  amg.smoothing_degree = 3;
  // The L-BFGS steps need a positive definite V-cycle: on a 1.3M-vertex tet
  // mesh the power steps' lambda_max let it turn a gradient uphill.
  amg.gershgorin_lambda_max = true;
  amg_precomputation(M, amg, &multigrid->amg);
  return multigrid;
}

void arap_multigrid_vcycle(const ArapMultigrid& multigrid, const Eigen::MatrixX3d& b,
                           Eigen::MatrixX3d* x) {
  RowMatrixX3d y;
  amg_vcycle(multigrid.amg, RowMatrixX3d(b), &y);
  *x = y;
}

void arap_multigrid_solve(const ArapMultigrid& multigrid, const Eigen::MatrixX3d& b,
                          Eigen::MatrixX3d* x, double tolerance) {
  CgOptions options;
  options.tolerance = tolerance;
  options.zero_mean = false;
  RowMatrixX3d y = RowMatrixX3d::Zero(b.rows(), 3);
  const CgResult r =
      projected_cg(CsrView(multigrid.matrix), multigrid.amg, RowMatrixX3d(b), &y, options);
  if (!r.converged)
    throw NumericalError("arap_multigrid_solve: CG reached a relative residual of " +
                         std::to_string(r.relative_residual) + " in " +
                         std::to_string(r.iterations) + " iterations");
  *x = y;
}

}  // namespace unfold
