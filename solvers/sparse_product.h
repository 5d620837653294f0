// The product of two row-major sparse matrices, rows in parallel: the AMG
// setup's Galerkin products (solvers/smoothed_aggregation.h), where Eigen's
// product runs on one thread and sorts its result by transposing it twice.
#pragma once

#include "solvers/block_kernels.h"

namespace unfold {

/// A B, every entry the sum of A(i, k) B(k, j) over A's row i in its stored
/// order, as Eigen's A * B sums it (the same values, bit for bit), with the same
/// pattern: products that cancel to zero are kept as explicit zeros.
/// @pre A and B compressed, A.cols() == B.rows()
/// @return compressed, each row's columns ascending
RowSparse sparse_product(const RowSparse& A, const RowSparse& B);

}  // namespace unfold
