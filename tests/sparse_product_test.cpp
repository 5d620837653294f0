// The AMG setup's sparse product (solvers/sparse_product.h): the same matrix
// as Eigen's A * B, bit for bit, pattern included, on one thread and on many.
#include "solvers/sparse_product.h"

#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "core/errors.h"

namespace unfold {
namespace {

// rows x cols with about per_row entries a row, some of them equal and of
// opposite sign, so that products cancel to exact zeros.
RowSparse random_sparse(int rows, int cols, int per_row, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_int_distribution<int> column(0, cols - 1), pick(0, 3);
  std::normal_distribution<double> normal;
  std::vector<Eigen::Triplet<double>> t;
  for (int i = 0; i < rows; ++i)
    for (int k = 0; k < per_row; ++k) {
      const int p = pick(random);
      t.emplace_back(i, column(random), p == 0 ? 1.0 : p == 1 ? -1.0 : normal(random));
    }
  RowSparse M(rows, cols);
  M.setFromTriplets(t.begin(), t.end());
  M.makeCompressed();
  return M;
}

void expect_identical(const RowSparse& C, const RowSparse& expected) {
  ASSERT_EQ(C.rows(), expected.rows());
  ASSERT_EQ(C.cols(), expected.cols());
  ASSERT_EQ(C.nonZeros(), expected.nonZeros());
  for (Eigen::Index i = 0; i <= C.rows(); ++i)
    ASSERT_EQ(C.outerIndexPtr()[i], expected.outerIndexPtr()[i]) << "row " << i;
  for (Eigen::Index k = 0; k < C.nonZeros(); ++k) {
    ASSERT_EQ(C.innerIndexPtr()[k], expected.innerIndexPtr()[k]) << "entry " << k;
    ASSERT_EQ(C.valuePtr()[k], expected.valuePtr()[k]) << "entry " << k;  // bit for bit
  }
}

TEST(SparseProduct, IsEigensProductBitForBit) {
  // Small (one thread) and above kMinParallelRows (rows in parallel); square,
  // tall times thin (A P) and thin times tall (R A P).
  for (const int rows : {300, 3 * kMinParallelRows}) {
    const RowSparse A = random_sparse(rows, rows, 7, 1);
    const RowSparse P = random_sparse(rows, rows / 9, 2, 2);
    const RowSparse R = RowSparse(P.transpose());
    const RowSparse AP = A * P;
    expect_identical(sparse_product(A, P), AP);
    expect_identical(sparse_product(R, AP), RowSparse(R * AP));
    expect_identical(sparse_product(A, A), RowSparse(A * A));
  }
}

TEST(SparseProduct, KeepsCancellingProductsAsExplicitZeros) {
  // Row 0 of A times B: 1 * 1 + 1 * (-1) = 0 in column 0.
  RowSparse A(1, 2), B(2, 1);
  A.insert(0, 0) = 1;
  A.insert(0, 1) = 1;
  B.insert(0, 0) = 1;
  B.insert(1, 0) = -1;
  A.makeCompressed();
  B.makeCompressed();
  const RowSparse C = sparse_product(A, B);
  ASSERT_EQ(C.nonZeros(), 1);
  EXPECT_EQ(C.coeff(0, 0), 0.0);
}

TEST(SparseProduct, MismatchedOrUncompressedMatricesAreUsageErrors) {
  RowSparse A(3, 4), B(3, 2);
  A.makeCompressed();
  B.makeCompressed();
  EXPECT_THROW(sparse_product(A, B), UsageError);
  RowSparse C(4, 2);
  C.insert(0, 0) = 1;  // not compressed
  EXPECT_THROW(sparse_product(A, C), UsageError);
}

}  // namespace
}  // namespace unfold
