#include "solvers/arap_solve.h"

#include <glog/logging.h>

#include <cmath>

#include "core/errors.h"
#include "core/parallel.h"
#include "mesh/best_rotations.h"
#include "solvers/anderson_acceleration.h"
#include "solvers/sparse_ldlt.h"

namespace unfold {

Eigen::MatrixX3d arap_solve(const EdgeGraph& graph, const Eigen::MatrixX3d& P, Eigen::MatrixX3d Q,
                            const ArapSolveOptions& options) {
  const int n = graph.num_vertices, num_fixed = options.num_fixed, m = n - num_fixed;
  if (P.rows() != n || Q.rows() != n || num_fixed < 1 || num_fixed > n)
    throw UsageError("arap_solve: need P and Q with one row per graph vertex and 1 to n held");
  if (options.max_iterations < 0 || !(options.tolerance >= 0) || !(options.anchor >= 0) ||
      options.anderson < 0)
    throw UsageError("arap_solve: max_iterations, tolerance, anchor and anderson must be >= 0");
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
  const Eigen::MatrixX3d start = Q.bottomRows(m);
  // The right side's parts that do not change: the anchor, and the held neighbours.
  Eigen::MatrixX3d fixed_rhs = options.anchor * start;
#pragma omp parallel for schedule(static) if (m >= kMinParallelRows)
  for (int i = num_fixed; i < n; ++i)
    for (int k = graph.offsets[size_t(i)]; k < graph.offsets[size_t(i) + 1]; ++k)
      if (graph.neighbors[size_t(k)] < num_fixed)
        fixed_rhs.row(i - num_fixed) += Q.row(graph.neighbors[size_t(k)]);
  // The centroid first: inside the expression Eigen recomputes it per row
  // (O(n^2): 0.67 s at 33k vertices, per call).
  const Eigen::RowVector3d centroid = Q.colwise().mean();
  const double radius = std::sqrt((Q.rowwise() - centroid).rowwise().squaredNorm().mean());

  // At X's best rotations R (per cell): B_i = sum_j (R_i + R_j)/2 (p_i - p_j), the
  // right side's part that changes, and the energy the steps lower,
  // 1/2 sum_i sum_{j in N_i} |x_i - x_j - R_i (p_i - p_j)|^2 + anchor |free rows - start|^2:
  // the local step minimises it over R, the global step over the free rows
  // (its gradient is 2 (L x - B) + 2 anchor (x - start)), so plain steps never raise it.
  Rotations R;
  Eigen::MatrixX3d B(n, 3);
  const auto fit = [&](const Eigen::MatrixX3d& X) {
    best_rotations(graph, P, X, &R);
    double energy = 0;
#pragma omp parallel for schedule(static) reduction(+ : energy) if (n >= kMinParallelRows)
    for (int i = 0; i < n; ++i) {
      Eigen::RowVector3d b = Eigen::RowVector3d::Zero();
      for (int k = graph.offsets[size_t(i)]; k < graph.offsets[size_t(i) + 1]; ++k) {
        const int j = graph.neighbors[size_t(k)];
        const Eigen::Vector3d e = (P.row(i) - P.row(j)).transpose();
        b += (0.5 * (R[size_t(i)] + R[size_t(j)]) * e).transpose();
        energy += 0.5 * (X.row(i) - X.row(j) - (R[size_t(i)] * e).transpose()).squaredNorm();
      }
      B.row(i) = b;
    }
    return energy + options.anchor * (X.bottomRows(m) - start).squaredNorm();
  };
  const bool accelerate = options.anderson > 0;
  AndersonAcceleration anderson(std::max(1, options.anderson));
  double level = fit(Q);
  Eigen::MatrixX3d free;
  int it = 0;
  while (it < options.max_iterations) {
    ++it;
    // d/dq_i of the energy = 0 for the free rows, R held.
    ldlt.solve(fixed_rhs + B.bottomRows(m), &free);
    const double step = (free - Q.bottomRows(m)).rowwise().norm().maxCoeff();
    const Eigen::MatrixX3d x = Q.bottomRows(m);
    bool plain = !accelerate;
    double energy = 0;
    if (accelerate) {
      Q.bottomRows(m) = anderson.next(x.reshaped(), free.reshaped()).reshaped(m, 3);
      energy = fit(Q);
      if (!(energy < level)) {
        anderson.reset();
        plain = true;
      }
    }
    const bool last = step <= options.tolerance * radius || it == options.max_iterations;
    if (plain) {
      Q.bottomRows(m) = free;
      if (last) break;  // no rotations needed after it
      energy = fit(Q);
      // A plain step that does not lower the energy: converged as far as
      // rounding lets it tell; keep the lower iterate.
      if (!(energy < level)) {
        Q.bottomRows(m) = x;
        break;
      }
    }
    level = energy;
    if (last) break;
  }
  VLOG(1) << "ARAP: " << it << " steps, " << m << " free vertices, anchor " << options.anchor
          << ", Anderson " << options.anderson << ", energy " << level;
  return Q;
}

}  // namespace unfold
