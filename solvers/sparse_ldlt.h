// Sparse symmetric LDL^T factorization behind one small interface, so the
// backend is chosen by measurement (docs/performance.md), not by the caller:
// the symbolic analysis (fill-reducing ordering, elimination tree) once per
// sparsity pattern, the numeric factorization per matrix with that pattern,
// then solves. Handles indefinite matrices (no pivoting beyond the ordering),
// and reports the inertia through the count of negative pivots.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <memory>

namespace unfold {

class SparseLdlt {
 public:
  enum class Backend {
    kEigen,    ///< Eigen::SimplicialLDLT with AMD ordering
    kCholmod,  ///< CHOLMOD simplicial LDL^T, its own ordering choice (AMD, METIS if better)
    /// CHOLMOD supernodal LL^T (dense blocks through BLAS): positive definite
    /// matrices only, several times faster to factorize where the fill is large
    /// (ARAP with held or anchored vertices, docs/history/performance.md); each
    /// factor is then turned simplicial, whose solves are the faster
    kCholmodCholesky,
  };

  explicit SparseLdlt(Backend backend = Backend::kCholmod);
  ~SparseLdlt();
  SparseLdlt(const SparseLdlt&) = delete;
  SparseLdlt& operator=(const SparseLdlt&) = delete;

  /// Ordering and symbolic factorization of A's pattern.
  /// @param A square, symmetric; only its lower triangle is read
  /// @throws NumericalError if the backend fails (out of memory)
  void analyze(const Eigen::SparseMatrix<double>& A);

  /// Numeric factorization of A, which must have the pattern given to analyze().
  /// @throws UsageError if analyze() was not called or the size differs
  /// @throws NumericalError on a zero (or non-finite) pivot; kCholmodCholesky:
  ///         on a matrix that is not positive definite
  void factorize(const Eigen::SparseMatrix<double>& A);

  /// x = A^{-1} b for the last factorized A. Reuses internal buffers: no
  /// allocation after the first call, and not safe to call concurrently. CHOLMOD
  /// backends: the three columns in one pass over the factor, from 20,000 rows
  /// on its elimination tree's subtrees on the OpenMP threads
  /// (SubtreeParallelSolve: the same solution to roundoff whatever the thread
  /// count).
  /// @throws UsageError if b's rows are not A's or nothing was factorized
  /// @param b n x 3; x is resized to n x 3 (may not alias b)
  void solve(const Eigen::MatrixX3d& b, Eigen::MatrixX3d* x) const;

  /// Number of negative entries of D: the count of negative eigenvalues of A
  /// (Sylvester's law of inertia).
  int negative_pivots() const { return negative_pivots_; }

  Backend backend() const { return backend_; }

  /// Nonzeros of the factor L and flops of one numeric factorization, as
  /// predicted by the analysis (CHOLMOD backend; 0 for Eigen's): the fill-in
  /// that makes a direct solver superlinear on 3D meshes.
  double factor_nonzeros() const { return factor_nonzeros_; }
  double factor_flops() const { return factor_flops_; }

 private:
  struct Impl;
  Backend backend_;
  std::unique_ptr<Impl> impl_;
  int negative_pivots_ = 0;
  double factor_nonzeros_ = 0;
  double factor_flops_ = 0;
};

/// Flops of one LDL^T factorization of A's pattern with CHOLMOD's AMD
/// ordering, from a pattern-only symbolic analysis (0.15 s at 100k vertices,
/// a small part of one factorization): what decides between a direct and an
/// iterative solver. The ordering the factorization itself picks may do a
/// little better (METIS).
/// @param A square, symmetric; only its lower triangle's pattern is read
/// @throws NumericalError if CHOLMOD fails (out of memory)
double predicted_factorization_flops(const Eigen::SparseMatrix<double>& A);

}  // namespace unfold
