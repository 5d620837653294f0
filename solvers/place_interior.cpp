#include "solvers/place_interior.h"

#include <Eigen/SparseCholesky>
#include <cmath>

#include "core/errors.h"
#include "mesh/best_rotations.h"

namespace unfold {

Eigen::MatrixX3d place_interior(const EdgeGraph& graph, const Eigen::MatrixX3d& P,
                                Eigen::MatrixX3d Q, int num_fixed, int max_iterations,
                                double tolerance) {
  const int n = graph.num_vertices, m = n - num_fixed;
  if (P.rows() != n || Q.rows() != n || num_fixed < 1 || num_fixed > n)
    throw UsageError("place_interior: need P and Q with one row per graph vertex and 1 to n fixed");
  if (m == 0) return Q;
  // The free vertices' block of the graph Laplacian; edges to fixed vertices go to the right side.
  const Eigen::SparseMatrix<double> L = graph_laplacian(graph).bottomRightCorner(m, m);
  const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(L);
  if (ldlt.info() != Eigen::Success)
    throw NumericalError(
        "interior placement: some interior vertex is not connected to the surface");
  const double radius =
      std::sqrt((Q.rowwise() - Q.colwise().mean()).rowwise().squaredNorm().mean());
  Rotations R;
  Eigen::MatrixX3d rhs(m, 3);
  for (int it = 0; it < max_iterations; ++it) {
    best_rotations(graph, P, Q, &R);
    // d/dq_i of sum over edges |q_i - q_j - (R_i + R_j)/2 (p_i - p_j)|^2 = 0.
    for (int i = num_fixed; i < n; ++i) {
      Eigen::RowVector3d b = Eigen::RowVector3d::Zero();
      for (int k = graph.offsets[size_t(i)]; k < graph.offsets[size_t(i) + 1]; ++k) {
        const int j = graph.neighbors[size_t(k)];
        b += (0.5 * (R[size_t(i)] + R[size_t(j)]) * (P.row(i) - P.row(j)).transpose()).transpose();
        if (j < num_fixed) b += Q.row(j);
      }
      rhs.row(i - num_fixed) = b;
    }
    const Eigen::MatrixX3d free = ldlt.solve(rhs);
    const double step = (free - Q.bottomRows(m)).rowwise().norm().maxCoeff();
    Q.bottomRows(m) = free;
    if (step <= tolerance * radius) break;
  }
  return Q;
}

}  // namespace unfold
