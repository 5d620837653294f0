#include "solvers/projected_cg.h"

#include <cmath>

#include "core/parallel.h"

namespace unfold {
namespace {

using Array6d = Eigen::Array<double, 6, 1>;

// z = one V-cycle on r; returns r^T z and z's column means from one sweep
// (r has zero mean, so r^T z is the same once z's mean is removed), or zeros
// for the means where none is removed.
Array6d precondition(const AmgData& amg, const RowMatrixX3d& r, RowMatrixX3d* z, bool zero_mean) {
  amg_vcycle(amg, r, z);
  const int n = int(r.rows());
  Array6d sums = chunked_row_sum(n, [&](int i) {
    Array6d v;
    v << (r.row(i).array() * z->row(i).array()).transpose(), z->row(i).array().transpose();
    return v;
  });
  sums.tail<3>() = zero_mean ? Eigen::Array3d(sums.tail<3>() / n) : Eigen::Array3d::Zero();
  return sums;
}

// p = (z - mean) + beta p, column by column.
void update_direction(const RowMatrixX3d& z, const Eigen::Array3d& mean, const Eigen::Array3d& beta,
                      RowMatrixX3d* p) {
  const Eigen::RowVector3d m = mean.transpose().matrix(), s = beta.transpose().matrix();
#pragma omp parallel for schedule(static) if (z.rows() >= kMinParallelRows)
  for (int i = 0; i < int(z.rows()); ++i) p->row(i) = (z.row(i) - m) + s.cwiseProduct(p->row(i));
}

}  // namespace

CgResult projected_cg(const CsrView& A, const AmgData& preconditioner, const RowMatrixX3d& b,
                      RowMatrixX3d* x, const CgOptions& options, CgWorkspace* workspace,
                      const Eigen::MatrixXd* U) {
  CgResult result;
  const int n = A.rows;
  const bool low_rank = U && U->cols() > 0;
  if (options.zero_mean) remove_column_means(x);
  const Eigen::Array3d b_norm = column_dots(b, b).sqrt();
  CgWorkspace local;
  CgWorkspace& w = workspace ? *workspace : local;
  RowMatrixX3d &r = w.r, &z = w.z, &p = w.p, &q = w.q;
  residual(A, b, *x, &r);
  if (low_rank) r.noalias() -= *U * (U->transpose() * *x);
  if (options.zero_mean) remove_column_means(&r);
  Eigen::Array3d active = Eigen::Array3d::Ones();  // columns still iterating
  const auto relative = [&](const Eigen::Array3d& r_squared) {
    Eigen::Array3d rel;
    for (int k = 0; k < 3; ++k) rel[k] = b_norm[k] > 0 ? std::sqrt(r_squared[k]) / b_norm[k] : 0.0;
    return rel;
  };
  Eigen::Array3d rel = relative(column_dots(r, r));
  const Eigen::Array3d target = (options.forcing * rel).max(options.tolerance);
  for (int k = 0; k < 3; ++k)
    if (rel[k] <= options.tolerance) active[k] = 0;
  Array6d pre = precondition(preconditioner, r, &z, options.zero_mean);
  Eigen::Array3d rz = pre.head<3>();
  p.setZero(n, 3);
  update_direction(z, pre.tail<3>(), Eigen::Array3d::Zero(), &p);
  while (active.any() && result.iterations < options.max_iterations) {
    ++result.iterations;
    multiply(A, p, &q);
    if (low_rank) q.noalias() += *U * (U->transpose() * p);
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
    // x += alpha p, r -= alpha q and |r|^2, in one sweep.
    const Eigen::RowVector3d a = alpha.transpose().matrix();
    rel = relative(chunked_row_sum(n, [&](int i) {
      x->row(i) += a.cwiseProduct(p.row(i));
      r.row(i) -= a.cwiseProduct(q.row(i));
      return r.row(i).array().square().transpose().eval();
    }));
    for (int k = 0; k < 3; ++k)
      if (rel[k] <= target[k]) active[k] = 0;
    if (!active.any()) break;
    pre = precondition(preconditioner, r, &z, options.zero_mean);
    Eigen::Array3d beta = Eigen::Array3d::Zero();
    for (int k = 0; k < 3; ++k)
      if (active[k] && rz[k] != 0) beta[k] = pre[k] / rz[k];
    rz = pre.head<3>();
    update_direction(z, pre.tail<3>(), beta, &p);
  }
  if (options.zero_mean) remove_column_means(x);
  result.relative_residual = rel.maxCoeff();
  result.converged = (rel <= target).all();
  return result;
}

}  // namespace unfold
