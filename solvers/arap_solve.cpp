#include "solvers/arap_solve.h"

#include <glog/logging.h>

#include <cmath>

#include "core/errors.h"
#include "core/parallel.h"
#include "mesh/best_rotations.h"
#include "solvers/sparse_ldlt.h"

namespace unfold {

Eigen::MatrixX3d arap_solve(const EdgeGraph& graph, const Eigen::MatrixX3d& P, Eigen::MatrixX3d Q,
                            const ArapSolveOptions& options) {
  const int n = graph.num_vertices, num_fixed = options.num_fixed, m = n - num_fixed;
  if (P.rows() != n || Q.rows() != n || num_fixed < 1 || num_fixed > n)
    throw UsageError("arap_solve: need P and Q with one row per graph vertex and 1 to n held");
  if (options.max_iterations < 0 || !(options.tolerance >= 0) || !(options.anchor >= 0))
    throw UsageError("arap_solve: max_iterations, tolerance and anchor must be >= 0");
  if (m == 0 || options.max_iterations == 0) return Q;  // nothing to move: no factorization
  // The free vertices' block of the graph Laplacian (plus the anchor); edges
  // to held vertices go to the right side.
  Eigen::SparseMatrix<double> L = graph_laplacian(graph).bottomRightCorner(m, m);
  if (options.anchor > 0) {
    Eigen::SparseMatrix<double> I(m, m);
    I.setIdentity();
    L += options.anchor * I;
  }
  SparseLdlt ldlt;
  ldlt.analyze(L);
  try {
    ldlt.factorize(L);
  } catch (const NumericalError&) {
    throw NumericalError("ARAP: some free vertex is not connected to a held one");
  }
  const Eigen::MatrixX3d anchored = options.anchor * Q.bottomRows(m);
  // The centroid first: inside the expression Eigen recomputes it per row
  // (O(n^2): 0.67 s at 33k vertices, per call).
  const Eigen::RowVector3d centroid = Q.colwise().mean();
  const double radius = std::sqrt((Q.rowwise() - centroid).rowwise().squaredNorm().mean());
  Rotations R;
  Eigen::MatrixX3d rhs(m, 3);
  Eigen::MatrixX3d free;
  int it = 0;
  while (it < options.max_iterations) {
    ++it;
    best_rotations(graph, P, Q, &R);
    // d/dq_i of sum over edges |q_i - q_j - (R_i + R_j)/2 (p_i - p_j)|^2 = 0.
#pragma omp parallel for schedule(static) if (m >= kMinParallelRows)
    for (int i = num_fixed; i < n; ++i) {
      Eigen::RowVector3d b = anchored.row(i - num_fixed);
      for (int k = graph.offsets[size_t(i)]; k < graph.offsets[size_t(i) + 1]; ++k) {
        const int j = graph.neighbors[size_t(k)];
        b += (0.5 * (R[size_t(i)] + R[size_t(j)]) * (P.row(i) - P.row(j)).transpose()).transpose();
        if (j < num_fixed) b += Q.row(j);
      }
      rhs.row(i - num_fixed) = b;
    }
    ldlt.solve(rhs, &free);
    const double step = (free - Q.bottomRows(m)).rowwise().norm().maxCoeff();
    Q.bottomRows(m) = free;
    if (step <= options.tolerance * radius) break;
  }
  VLOG(1) << "ARAP: " << it << " steps, " << m << " free vertices, anchor " << options.anchor;
  return Q;
}

}  // namespace unfold
