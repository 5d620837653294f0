// The alternating local-global solver of the paper (Sec. 3-4), libigl style:
// a precomputation (assembly and symbolic factorization, once per mesh), a
// per-beta numeric factorization, and cheap iterations that reuse it
// (optionally Anderson-accelerated, CascadeOptions::anderson).
//
// With the rotations fixed the global step solves A(beta) Q = B(R) on zero-mean
// Q (solvers/quadratic_part.h); for the paper's energy A = 2((beta+1) L - n I)
// (docs/method.md). Terms that are not quadratic (volume, edge lengths) are
// refused (solvers/backend_support.h): use the Ceres backend.
//
// Two ways to solve it (docs/performance.md): a sparse LDL^T, exact and fastest
// up to a few ten thousand vertices, and conjugate gradients preconditioned by
// an AMG hierarchy of the beta-scaled Laplacian, warm-started from the current
// positions, whose cost grows near-linearly where the factorization's does not.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <memory>
#include <string>
#include <vector>

#include "energies/quadratic_term.h"
#include "solvers/cascade.h"
#include "solvers/projected_cg.h"
#include "solvers/quadratic_part.h"
#include "solvers/smoothed_aggregation.h"
#include "solvers/sparse_ldlt.h"
#include "solvers/unfold_problem.h"
#include "solvers/woodbury_update.h"

namespace unfold {

struct LinearSolverOptions {
  std::string method = "auto";  ///< direct (sparse LDL^T), iterative (AMG + CG) or auto
  /// auto: direct while one factorization is predicted to cost at most this
  /// many GFlop (the fill of a volume-filling 3D mesh makes it grow ~n^2)
  double direct_max_gflop = 0.3;
  double cg_tolerance = 1e-8;    ///< iterative: relative residual of each global step at least
  double cg_forcing = 1e-2;      ///< iterative: or this reduction of the warm start's residual
  int cg_max_iterations = 1000;  ///< iterative: CG iterations per global step at most
};

/// Whether `options` pick the iterative solver for the global matrix A (its
/// pattern): auto compares predicted_factorization_flops(A) with
/// direct_max_gflop (a symbolic analysis: 0.15 s at 100k vertices).
bool use_iterative_solver(const LinearSolverOptions& options, const Eigen::SparseMatrix<double>& A);

/// @throws UsageError naming the config key of a bad option
void validate_linear_solver_options(const LinearSolverOptions& options);

/// What the iterative global steps did.
struct CgStats {
  int solves = 0;
  int iterations = 0;          ///< CG iterations over all solves
  int unconverged_solves = 0;  ///< stopped at cg_max_iterations
  double worst_relative_residual = 0;
  bool negative_curvature = false;  ///< since the last set_beta: A is not definite off 1
};

struct LocalGlobalData {
  const UnfoldProblem* problem = nullptr;
  QuadraticPart part;             ///< A_fixed, A_beta, and B and c of terms free of R
  Eigen::SparseMatrix<double> A;  ///< A_fixed + beta A_beta: one pattern, refilled per beta
  double beta = 0;                ///< beta of the current matrix
  Eigen::MatrixX3d B_free;        ///< B_fixed + beta B_beta: the terms free of R
  double c_free = 0;              ///< c_fixed + beta c_beta
  std::vector<const QuadraticTerm*> rotation_terms;  ///< the terms whose B and c depend on R
  std::vector<const EnergyTerm*> concave_terms;      ///< taken by their tangent at the iterate
  bool iterative = false;                            ///< CG with `amg`, else `ldlt`
  int negative_pivots = 0;  ///< direct: inertia of A (+ U_regions U_regions^T), 1 iff bounded
  SparseLdlt ldlt;          ///< direct: analyzed once, factorized per beta
  WoodburyUpdate regions;   ///< direct: the stretch term's region centroids
  std::shared_ptr<const AmgData> amg;     ///< iterative: AMG hierarchy of A_beta, built once
  CgOptions cg;                           ///< iterative: tolerance and iteration limit
  mutable CgStats cg_stats;               ///< iterative: what the global steps did
  mutable Eigen::MatrixX3d rhs;           ///< global_step's right-hand side buffer, reused
  mutable Eigen::MatrixX3d tangent;       ///< the concave terms' part of rhs (empty: none)
  mutable RowMatrixX3d rhs_rows, x_rows;  ///< iterative: the same in CG's layout
  mutable CgWorkspace cg_workspace;       ///< iterative: CG's vectors, reused
};

/// Assembles the system's two parts and prepares the solver: the symbolic
/// factorization (direct), or the AMG hierarchy of A_beta (iterative; `amg`
/// when given, e.g. the one that served lambda_2, must be built from a
/// multiple of A_beta).
/// @param problem kept by pointer, must outlive data
/// @throws UsageError if a term is not quadratic (e.g. volume; why_backend_cannot_run)
void local_global_precomputation(const UnfoldProblem& problem, LocalGlobalData* data,
                                 const LinearSolverOptions& options = {},
                                 std::shared_ptr<const AmgData> amg = nullptr);

/// A(beta): its numeric factorization (direct) or just its values (iterative).
/// @throws NumericalError if the factorization breaks down
void local_global_set_beta(double beta, LocalGlobalData* data);

/// True when A is positive definite off the constant vector (its only negative
/// direction is 1, from the stretch term): the global step is then a minimiser.
/// Direct: from the inertia; that negative direction (eigenvalue -2n) can vanish
/// in rounding when beta is huge, so no negative pivot counts as bounded too.
/// Iterative: no global step since set_beta met negative curvature.
inline bool energy_bounded(const LocalGlobalData& data) {
  return data.iterative ? !data.cg_stats.negative_curvature : data.negative_pivots <= 1;
}

/// Global step: the zero-mean minimiser over Q for fixed rotations R (iterative:
/// to cg_tolerance, from *Q), the concave terms taken by their tangent at *Q. No allocation once Q
/// has n rows; uses data's buffers, so one `data` must not serve two global steps at the same time.
void global_step(const LocalGlobalData& data, const Rotations& R, Eigen::MatrixX3d* Q);

/// E(Q; R) at data.beta right after global_step(data, R, Q), from the quadratic
/// form instead of a sweep over every cell (total_energy): with A Q = B - r,
/// r the solve's residual (roundoff for the direct solver, the CG residual for
/// the iterative one), E = sum_t w_t c_t(R) - tr(Q^T B) - tr(Q^T r).
double energy_after_global_step(const LocalGlobalData& data, const Rotations& R,
                                const Eigen::MatrixX3d& Q);

/// E(Q; R) at data.beta from the quadratic form and the cell covariances S the
/// local step fitted R from (fit_rotations' buffer), instead of a sweep over
/// every term's residual blocks: for quadratic terms, and rotation terms whose
/// B(R) is linear in R (energies/rotation_term.h),
///   E = tr(Q^T (A + U U^T) Q) - 2 tr(Q^T B_free) + c_free + sum_t w_t c_t(R) - 2 sum_i tr(R_i
///   S_i).
/// A sum over rows in fixed chunks: the same value whatever the number of threads.
/// @pre S holds the rotation terms' covariances at Q, weighted at data.beta
double energy_from_covariances(const LocalGlobalData& data, const Eigen::MatrixX3d& Q,
                               const Rotations& R, const std::vector<Eigen::Matrix3d>& S);

/// Algorithm 1's iterations for the cascade driver (solvers/cascade.h).
class LocalGlobalBackend : public CascadeBackend {
 public:
  explicit LocalGlobalBackend(const UnfoldProblem& problem, const LinearSolverOptions& options = {},
                              std::shared_ptr<const AmgData> amg = nullptr);
  void set_beta(double beta) override;
  const LocalGlobalData& data() const { return data_; }
  bool bounded() const override { return energy_bounded(data_); }
  bool run_stage(const StageOptions& options, int cascade, Eigen::MatrixX3d* Q,
                 double* previous_energy, std::vector<IterationRecord>* history) override;

 private:
  LocalGlobalData data_;
  Rotations R_;
  std::vector<Eigen::Matrix3d> covariances_;  ///< the local step's buffer
  Eigen::VectorXd rest_lengths_;              ///< for the edge ratio of every iteration
};

}  // namespace unfold
