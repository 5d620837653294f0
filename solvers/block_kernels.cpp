#include "solvers/block_kernels.h"

namespace unfold {

template <typename Scalar>
void multiply(const CsrViewOf<Scalar>& A, const RowMatrixX3<Scalar>& X, RowMatrixX3<Scalar>* Y) {
  Y->resize(A.rows, 3);
  const Scalar* x = X.data();
  Scalar* y = Y->data();
#pragma omp parallel for schedule(static) if (A.rows >= kMinParallelRows)
  for (int i = 0; i < A.rows; ++i) {
    Scalar s0 = 0, s1 = 0, s2 = 0;
    for (int k = A.outer[i]; k < A.outer[i + 1]; ++k) {
      const Scalar a = A.values[k];
      const Scalar* xj = x + 3 * size_t(A.inner[k]);
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
template <typename Scalar>
void residual(const CsrViewOf<Scalar>& A, const RowMatrixX3<Scalar>& B,
              const RowMatrixX3<Scalar>& X, RowMatrixX3<Scalar>* R) {
  R->resize(A.rows, 3);
  const Scalar* x = X.data();
  const Scalar* b = B.data();
  Scalar* r = R->data();
#pragma omp parallel for schedule(static) if (A.rows >= kMinParallelRows)
  for (int i = 0; i < A.rows; ++i) {
    Scalar s0 = b[3 * size_t(i)], s1 = b[3 * size_t(i) + 1], s2 = b[3 * size_t(i) + 2];
    for (int k = A.outer[i]; k < A.outer[i + 1]; ++k) {
      const Scalar a = A.values[k];
      const Scalar* xj = x + 3 * size_t(A.inner[k]);
      s0 -= a * xj[0];
      s1 -= a * xj[1];
      s2 -= a * xj[2];
    }
    r[3 * size_t(i)] = s0;
    r[3 * size_t(i) + 1] = s1;
    r[3 * size_t(i) + 2] = s2;
  }
}

template void multiply(const CsrViewOf<double>&, const RowMatrixX3d&, RowMatrixX3d*);
template void multiply(const CsrViewOf<float>&, const RowMatrixX3f&, RowMatrixX3f*);
template void residual(const CsrViewOf<double>&, const RowMatrixX3d&, const RowMatrixX3d&,
                       RowMatrixX3d*);
template void residual(const CsrViewOf<float>&, const RowMatrixX3f&, const RowMatrixX3f&,
                       RowMatrixX3f*);

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
