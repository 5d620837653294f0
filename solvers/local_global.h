// The alternating local-global solver of the paper (Sec. 3-4), libigl style:
// a precomputation (assembly and symbolic factorization, once per mesh), a
// per-beta numeric factorization, and cheap iterations that reuse it.
//
// With the rotations fixed, every quadratic term t contributes
// w_t(beta) (tr(Q^T H_t Q) - 2 tr(Q^T B_t(R))), so the global step solves
//   A(beta) Q = sum_t w_t(beta) B_t(R),   A(beta) = sum_t w_t(beta) H_t,
// on zero-mean Q. For the paper's energy A = 2((beta+1) L - n I) (docs/method.md).
// Non-quadratic terms (volume) are refused: use the Ceres backend.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "solvers/cascade.h"
#include "solvers/sparse_ldlt.h"
#include "solvers/unfold_problem.h"

namespace unfold {

struct LocalGlobalData {
  const UnfoldProblem* problem = nullptr;
  Eigen::SparseMatrix<double> A_fixed;  ///< sum of w_t H_t over terms not scaled by beta
  Eigen::SparseMatrix<double> A_beta;   ///< the same at beta = 1 over terms scaled by beta
  Eigen::SparseMatrix<double> A;        ///< A_fixed + beta A_beta: one pattern, refilled per beta
  double beta = 0;                      ///< beta of the current factorization
  int negative_pivots = 0;              ///< inertia of A: 1 iff the energy is bounded
  SparseLdlt ldlt;                      ///< analyzed once, factorized per beta
  mutable Eigen::MatrixX3d rhs;         ///< global_step's right-hand side buffer, reused
};

/// Assembles the system's two parts and does the symbolic factorization.
/// @param problem kept by pointer, must outlive data
/// @throws UsageError if a term is not quadratic (e.g. volume)
void local_global_precomputation(const UnfoldProblem& problem, LocalGlobalData* data);

/// Numeric factorization of A(beta).
/// @throws NumericalError if the factorization breaks down
void local_global_set_beta(double beta, LocalGlobalData* data);

/// True when A is positive definite off the constant vector (its only negative
/// direction is 1, from the stretch term): the global step is then a minimiser.
/// That negative direction (eigenvalue -2n) can vanish in rounding when beta
/// is huge, so no negative pivot counts as bounded too.
inline bool energy_bounded(const LocalGlobalData& data) { return data.negative_pivots <= 1; }

/// Whether the quadratic terms at beta are bounded below off the constant
/// vector (one LDL^T factorization; non-quadratic terms are ignored).
bool quadratic_part_bounded(const UnfoldProblem& problem, double beta);

/// Global step: the zero-mean minimiser over Q for fixed rotations R.
/// No allocation once Q has n rows; uses data's buffers, so one `data` must
/// not serve two global steps at the same time.
void global_step(const LocalGlobalData& data, const Rotations& R, Eigen::MatrixX3d* Q);

/// Algorithm 1's iterations for the cascade driver (solvers/cascade.h).
class LocalGlobalBackend : public CascadeBackend {
 public:
  explicit LocalGlobalBackend(const UnfoldProblem& problem);
  void set_beta(double beta) override;
  bool bounded() const override { return energy_bounded(data_); }
  bool run_stage(const StageOptions& options, int cascade, Eigen::MatrixX3d* Q,
                 double* previous_energy, std::vector<IterationRecord>* history) override;

 private:
  LocalGlobalData data_;
  Rotations R_;
};

}  // namespace unfold
