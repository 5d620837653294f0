// Kernels on n x 3 row-major blocks (one row per vertex, the x, y, z columns
// side by side) shared by the iterative solvers: a sparse matrix times a block,
// per-column dot products and column means. Parallel over rows; reductions are
// summed in fixed chunks, so results do not depend on the thread count.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "core/chunked_row_sum.h"
#include "core/parallel.h"
#include "geometry/row_major.h"

namespace unfold {

using RowSparse = Eigen::SparseMatrix<double, Eigen::RowMajor>;

/// A compressed sparse row matrix seen through its arrays: a row-major sparse
/// matrix, or a symmetric column-major one (its CSC arrays are its own CSR
/// arrays). Scalar: double, or float for the AMG's single-precision V-cycle.
template <typename Scalar>
struct CsrViewOf {
  int rows = 0;
  const int* outer = nullptr;
  const int* inner = nullptr;
  const Scalar* values = nullptr;

  CsrViewOf() = default;
  /// @pre A is compressed
  explicit CsrViewOf(const Eigen::SparseMatrix<Scalar, Eigen::RowMajor>& A)
      : rows(int(A.rows())),
        outer(A.outerIndexPtr()),
        inner(A.innerIndexPtr()),
        values(A.valuePtr()) {}
  /// @pre A is compressed and symmetric (pattern and values)
  static CsrViewOf of_symmetric(const Eigen::SparseMatrix<Scalar>& A) {
    CsrViewOf v;
    v.rows = int(A.rows());
    v.outer = A.outerIndexPtr();
    v.inner = A.innerIndexPtr();
    v.values = A.valuePtr();
    return v;
  }
};
using CsrView = CsrViewOf<double>;

/// Y = A X. @pre X has A.rows rows; Y is resized (may not alias X).
/// Instantiated for double and float.
template <typename Scalar>
void multiply(const CsrViewOf<Scalar>& A, const RowMatrixX3<Scalar>& X, RowMatrixX3<Scalar>* Y);

/// R = B - A X. @pre B and X have A.rows rows; R is resized. R may alias B
/// (R -= A X), not X. Instantiated for double and float.
template <typename Scalar>
void residual(const CsrViewOf<Scalar>& A, const RowMatrixX3<Scalar>& B,
              const RowMatrixX3<Scalar>& X, RowMatrixX3<Scalar>* R);

/// Per column k: sum_i X(i, k) Y(i, k).
Eigen::Array3d column_dots(const RowMatrixX3d& X, const RowMatrixX3d& Y);

/// Subtracts each column's mean: the projection onto the complement of the
/// constant vector, where the unfolding's global matrix is definite.
void remove_column_means(RowMatrixX3d* X);

}  // namespace unfold
