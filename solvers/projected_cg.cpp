#include "solvers/projected_cg.h"

#include <cmath>

#include "core/parallel.h"

namespace unfold {
namespace {

// Per column k: Y.col(k) += a[k] X.col(k).
void add_scaled(const Eigen::Array3d& a, const RowMatrixX3d& X, RowMatrixX3d* Y) {
  const Eigen::RowVector3d s = a.transpose().matrix();
#pragma omp parallel for schedule(static) if (X.rows() >= kMinParallelRows)
  for (int i = 0; i < int(X.rows()); ++i) Y->row(i) += s.cwiseProduct(X.row(i));
}

}  // namespace

CgResult projected_cg(const CsrView& A, const AmgData& preconditioner, const RowMatrixX3d& b,
                      RowMatrixX3d* x, const CgOptions& options, CgWorkspace* workspace) {
  CgResult result;
  remove_column_means(x);
  const Eigen::Array3d b_norm = column_dots(b, b).sqrt();
  CgWorkspace local;
  CgWorkspace& w = workspace ? *workspace : local;
  RowMatrixX3d &r = w.r, &z = w.z, &p = w.p, &q = w.q;
  residual(A, b, *x, &r);
  remove_column_means(&r);
  Eigen::Array3d active = Eigen::Array3d::Ones();  // columns still iterating
  const auto relative = [&](const Eigen::Array3d& r_norm) {
    Eigen::Array3d rel;
    for (int k = 0; k < 3; ++k) rel[k] = b_norm[k] > 0 ? r_norm[k] / b_norm[k] : 0.0;
    return rel;
  };
  Eigen::Array3d rel = relative(column_dots(r, r).sqrt());
  const Eigen::Array3d target = (options.forcing * rel).max(options.tolerance);
  for (int k = 0; k < 3; ++k)
    if (rel[k] <= options.tolerance) active[k] = 0;
  amg_vcycle(preconditioner, r, &z);
  remove_column_means(&z);
  p = z;
  Eigen::Array3d rz = column_dots(r, z);
  while (active.any() && result.iterations < options.max_iterations) {
    ++result.iterations;
    multiply(A, p, &q);
    const Eigen::Array3d pq = column_dots(p, q);
    Eigen::Array3d alpha = Eigen::Array3d::Zero();
    for (int k = 0; k < 3; ++k) {
      if (!active[k]) continue;
      if (!(pq[k] > 0)) {
        result.negative_curvature = true;
        active[k] = 0;
        continue;
      }
      alpha[k] = rz[k] / pq[k];
    }
    add_scaled(alpha, p, x);
    add_scaled(-alpha, q, &r);
    rel = relative(column_dots(r, r).sqrt());
    for (int k = 0; k < 3; ++k)
      if (rel[k] <= target[k]) active[k] = 0;
    if (!active.any()) break;
    amg_vcycle(preconditioner, r, &z);
    remove_column_means(&z);
    const Eigen::Array3d rz_next = column_dots(r, z);
    Eigen::Array3d beta = Eigen::Array3d::Zero();
    for (int k = 0; k < 3; ++k)
      if (active[k] && rz[k] != 0) beta[k] = rz_next[k] / rz[k];
    rz = rz_next;
    // p = z + beta p, column by column (inactive columns keep their p unused).
    const Eigen::RowVector3d s = beta.transpose().matrix();
#pragma omp parallel for schedule(static) if (p.rows() >= kMinParallelRows)
    for (int i = 0; i < int(p.rows()); ++i) p.row(i) = z.row(i) + s.cwiseProduct(p.row(i));
  }
  remove_column_means(x);
  result.relative_residual = rel.maxCoeff();
  result.converged = (rel <= target).all();
  return result;
}

}  // namespace unfold
