#include "solvers/sparse_product.h"

#include <omp.h>

#include <algorithm>
#include <vector>

#include "core/errors.h"

namespace unfold {
namespace {

// Row i of A B (Gustavson): the columns it reaches, ascending, in `columns`,
// their sums in `sum` (indexed by column; reset to unmarked on return through
// `marked`).
void product_row(const RowSparse& A, const RowSparse& B, int i, std::vector<char>* marked,
                 std::vector<double>* sum, std::vector<int>* columns) {
  columns->clear();
  const int* a_outer = A.outerIndexPtr();
  const int* a_inner = A.innerIndexPtr();
  const double* a_value = A.valuePtr();
  const int* b_outer = B.outerIndexPtr();
  const int* b_inner = B.innerIndexPtr();
  const double* b_value = B.valuePtr();
  for (int p = a_outer[i]; p < a_outer[i + 1]; ++p) {
    const int k = a_inner[p];
    const double a = a_value[p];
    for (int q = b_outer[k]; q < b_outer[k + 1]; ++q) {
      const int j = b_inner[q];
      if (!(*marked)[size_t(j)]) {
        (*marked)[size_t(j)] = 1;
        (*sum)[size_t(j)] = b_value[q] * a;
        columns->push_back(j);
      } else {
        (*sum)[size_t(j)] += b_value[q] * a;
      }
    }
  }
  std::sort(columns->begin(), columns->end());
  for (const int j : *columns) (*marked)[size_t(j)] = 0;
}

}  // namespace

RowSparse sparse_product(const RowSparse& A, const RowSparse& B) {
  if (A.cols() != B.rows() || !A.isCompressed() || !B.isCompressed())
    throw UsageError("sparse_product: need compressed matrices with A's columns B's rows");
  const int rows = int(A.rows()), cols = int(B.cols());
  RowSparse C(rows, cols);
  int* outer = C.outerIndexPtr();
  outer[0] = 0;
  // Each thread makes its block of rows into buffers of its own; once every
  // row's count is known, the buffers are copied to their offsets.
  const int threads = rows >= kMinParallelRows ? omp_get_max_threads() : 1;
#pragma omp parallel num_threads(threads)
  {
    std::vector<char> marked(size_t(cols), 0);
    std::vector<double> sum(static_cast<size_t>(cols));
    std::vector<int> columns, my_inner;
    std::vector<double> my_value;
    int first = -1;
#pragma omp for schedule(static)
    for (int i = 0; i < rows; ++i) {
      if (first < 0) first = i;
      product_row(A, B, i, &marked, &sum, &columns);
      outer[i + 1] = int(columns.size());
      for (const int j : columns) {
        my_inner.push_back(j);
        my_value.push_back(sum[size_t(j)]);
      }
    }
#pragma omp single
    {
      for (int i = 0; i < rows; ++i) outer[i + 1] += outer[i];
      C.resizeNonZeros(outer[rows]);
    }
    if (first >= 0) {
      std::copy(my_inner.begin(), my_inner.end(), C.innerIndexPtr() + outer[first]);
      std::copy(my_value.begin(), my_value.end(), C.valuePtr() + outer[first]);
    }
  }
  return C;
}

}  // namespace unfold
