#include "solvers/sparse_ldlt.h"

#include <cholmod.h>
#include <omp.h>

#include <Eigen/SparseCholesky>
#include <cmath>
#include <memory>
#include <string>

#include "core/errors.h"
#include "solvers/subtree_parallel_solve.h"

namespace unfold {
namespace {

// Rows from which a factor's solves are split among the threads: below it one
// thread does them (opening a parallel region costs more than it saves).
constexpr int kMinParallelSolveRows = 20000;

// A's lower triangle as a CHOLMOD matrix of the given xtype (pattern, or real
// with the values left to fill), or null when CHOLMOD runs out of memory.
cholmod_sparse* lower_triangle(const Eigen::SparseMatrix<double>& A, int xtype,
                               cholmod_common* common) {
  const int n = int(A.rows());
  size_t nnz = 0;
  for (int j = 0; j < A.outerSize(); ++j)
    for (Eigen::SparseMatrix<double>::InnerIterator it(A, j); it; ++it) nnz += it.row() >= j;
  cholmod_sparse* L = cholmod_allocate_sparse(size_t(n), size_t(n), nnz, /*sorted=*/1,
                                              /*packed=*/1, /*stype=*/-1, xtype, common);
  if (!L) return nullptr;
  int* p = static_cast<int*>(L->p);
  int* i = static_cast<int*>(L->i);
  size_t k = 0;
  for (int j = 0; j < A.outerSize(); ++j) {
    p[j] = int(k);
    for (Eigen::SparseMatrix<double>::InnerIterator it(A, j); it; ++it)
      if (it.row() >= j) i[k++] = int(it.row());
  }
  p[n] = int(k);
  return L;
}

}  // namespace

struct SparseLdlt::Impl {
  // Eigen backend.
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> eigen;
  // CHOLMOD backend: A's lower triangle in CHOLMOD's CSC, kept so that each
  // factorization only copies values.
  cholmod_common common;
  cholmod_sparse* A = nullptr;
  cholmod_factor* L = nullptr;
  // kCholmodCholesky: the supernodal analysis, kept because each
  // factorization's factor is turned simplicial for the solves.
  cholmod_factor* supernodal = nullptr;
  // The solves of the current factor (CHOLMOD backends).
  std::unique_ptr<SubtreeParallelSolve> solves;
  bool cholmod_started = false;
  int n = -1;

  ~Impl() {
    if (!cholmod_started) return;
    cholmod_free_factor(&L, &common);
    cholmod_free_factor(&supernodal, &common);
    cholmod_free_sparse(&A, &common);
    cholmod_finish(&common);
  }

  // The solves of the simplicial factor L, made anew with each factor (2-4 ms
  // at 53k rows). On david0's anchored ARAP steps (53k rows, 2.35M entries)
  // CHOLMOD's own solves took 7.8-9 ms (a column on a second thread), these
  // 5.2-7.2 ms (docs/history/performance.md, solves by subtrees).
  void make_solves() {
    SubtreeParallelSolve::Factor f;
    f.n = n;
    f.column_start = static_cast<const int*>(L->p);
    f.column_count = static_cast<const int*>(L->nz);
    f.row = static_cast<const int*>(L->i);
    f.value = static_cast<const double*>(L->x);
    f.permutation = static_cast<const int*>(L->Perm);
    f.cholesky = L->is_ll;
    solves = std::make_unique<SubtreeParallelSolve>(
        f, n >= kMinParallelSolveRows ? omp_get_max_threads() : 1);
  }

  // Copies the lower triangle of M's values (pattern fixed by analyze) into A.
  void copy_lower_values(const Eigen::SparseMatrix<double>& M) {
    double* x = static_cast<double*>(A->x);
    size_t k = 0;
    for (int j = 0; j < M.outerSize(); ++j)
      for (Eigen::SparseMatrix<double>::InnerIterator it(M, j); it; ++it)
        if (it.row() >= j) x[k++] = it.value();
  }
};

SparseLdlt::SparseLdlt(Backend backend) : backend_(backend), impl_(new Impl) {
  if (backend_ != Backend::kEigen) {
    cholmod_start(&impl_->common);
    impl_->cholmod_started = true;
    // Supernodal is LL^T only: the simplicial LDL^T serves indefinite matrices.
    const bool cholesky = backend_ == Backend::kCholmodCholesky;
    impl_->common.supernodal = cholesky ? CHOLMOD_SUPERNODAL : CHOLMOD_SIMPLICIAL;
    impl_->common.final_ll = cholesky;
  }
}

SparseLdlt::~SparseLdlt() = default;

void SparseLdlt::analyze(const Eigen::SparseMatrix<double>& A) {
  if (A.rows() != A.cols()) throw UsageError("SparseLdlt::analyze: matrix is not square");
  Impl& m = *impl_;
  m.n = int(A.rows());
  if (backend_ == Backend::kEigen) {
    m.eigen.analyzePattern(A);
    if (m.eigen.info() != Eigen::Success)
      throw NumericalError("SparseLdlt: symbolic analysis failed (Eigen backend)");
    return;
  }
  m.solves.reset();
  cholmod_free_factor(&m.L, &m.common);
  cholmod_free_factor(&m.supernodal, &m.common);
  cholmod_free_sparse(&m.A, &m.common);
  m.A = lower_triangle(A, CHOLMOD_REAL, &m.common);
  if (!m.A) throw NumericalError("SparseLdlt: CHOLMOD could not allocate the matrix");
  m.copy_lower_values(A);
  m.L = cholmod_analyze(m.A, &m.common);
  if (!m.L || m.common.status < CHOLMOD_OK)
    throw NumericalError("SparseLdlt: symbolic analysis failed (CHOLMOD status " +
                         std::to_string(m.common.status) + ")");
  factor_nonzeros_ = m.common.lnz;
  factor_flops_ = m.common.fl;
  if (backend_ == Backend::kCholmodCholesky) {
    m.supernodal = cholmod_copy_factor(m.L, &m.common);
    if (!m.supernodal) throw NumericalError("SparseLdlt: CHOLMOD could not copy the analysis");
  }
}

void SparseLdlt::factorize(const Eigen::SparseMatrix<double>& A) {
  Impl& m = *impl_;
  if (m.n < 0 || A.rows() != m.n || A.cols() != m.n)
    throw UsageError("SparseLdlt::factorize: call analyze() first with a matrix of this size");
  negative_pivots_ = 0;
  if (backend_ == Backend::kEigen) {
    m.eigen.factorize(A);
    if (m.eigen.info() != Eigen::Success)
      throw NumericalError("SparseLdlt: numeric factorization failed (Eigen backend)");
    const Eigen::VectorXd& D = m.eigen.vectorD();
    if (!D.allFinite() || (D.array() == 0).any())
      throw NumericalError("SparseLdlt: zero or non-finite pivot (Eigen backend)");
    negative_pivots_ = int((D.array() < 0).count());
    return;
  }
  m.solves.reset();
  m.copy_lower_values(A);
  if (backend_ == Backend::kCholmodCholesky) {
    if (!m.L->is_super) {  // the last factorization's, turned simplicial
      cholmod_free_factor(&m.L, &m.common);
      m.L = cholmod_copy_factor(m.supernodal, &m.common);
      if (!m.L) throw NumericalError("SparseLdlt: CHOLMOD could not copy the analysis");
    }
    // A pivot that is not positive stops LL^T there: L->minor < n.
    if (!cholmod_factorize(m.A, m.L, &m.common) || m.L->minor < m.L->n)
      throw NumericalError("SparseLdlt: not positive definite (CHOLMOD LL^T stopped at column " +
                           std::to_string(m.L->minor) + ")");
    // Solves by the simplicial sweeps (SubtreeParallelSolve): through ATLAS a
    // supernodal solve of two columns took twice as long as CHOLMOD's
    // simplicial one (david11's anchored steps, docs/history/performance.md).
    if (!cholmod_change_factor(CHOLMOD_REAL, /*to_ll=*/1, /*to_super=*/0, /*to_packed=*/1,
                               /*to_monotonic=*/1, m.L, &m.common))
      throw NumericalError("SparseLdlt: CHOLMOD could not convert the factor (status " +
                           std::to_string(m.common.status) + ")");
    m.make_solves();
    return;
  }
  // CHOLMOD's LDL^T does not stop at negative pivots; a zero one sets L->minor < n.
  if (!cholmod_factorize(m.A, m.L, &m.common) || m.L->minor < m.L->n)
    throw NumericalError("SparseLdlt: numeric factorization failed (CHOLMOD status " +
                         std::to_string(m.common.status) + ", column " +
                         std::to_string(m.L->minor) + ")");
  // Simplicial LDL^T stores D on L's diagonal: the first entry of each column.
  const int* p = static_cast<const int*>(m.L->p);
  const double* x = static_cast<const double*>(m.L->x);
  for (int j = 0; j < m.n; ++j) {
    const double d = x[p[j]];
    if (!std::isfinite(d) || d == 0)
      throw NumericalError("SparseLdlt: zero or non-finite pivot at column " + std::to_string(j));
    negative_pivots_ += d < 0;
  }
  m.make_solves();
}

void SparseLdlt::solve(const Eigen::MatrixX3d& b, Eigen::MatrixX3d* x) const {
  Impl& m = *impl_;
  if (b.rows() != m.n) throw UsageError("SparseLdlt::solve: right-hand side has the wrong size");
  if (backend_ == Backend::kEigen) {
    *x = m.eigen.solve(b);
    return;
  }
  if (!m.solves) throw UsageError("SparseLdlt::solve: no factorization to solve with");
  m.solves->solve(b, x);
}

double predicted_factorization_flops(const Eigen::SparseMatrix<double>& A) {
  if (A.rows() != A.cols()) throw UsageError("predicted_factorization_flops: matrix is not square");
  cholmod_common common;
  cholmod_start(&common);
  common.nmethods = 1;
  common.method[0].ordering = CHOLMOD_AMD;
  common.supernodal = CHOLMOD_SIMPLICIAL;
  cholmod_sparse* pattern = lower_triangle(A, CHOLMOD_PATTERN, &common);
  double flops = -1;
  if (pattern) {
    cholmod_factor* L = cholmod_analyze(pattern, &common);
    if (L && common.status >= CHOLMOD_OK) flops = common.fl;
    cholmod_free_factor(&L, &common);
    cholmod_free_sparse(&pattern, &common);
  }
  cholmod_finish(&common);
  if (flops < 0) throw NumericalError("predicted_factorization_flops: CHOLMOD's analysis failed");
  return flops;
}

}  // namespace unfold
