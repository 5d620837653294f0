// The full nonlinear solve: Ceres minimises the same energy as the
// local-global solver over all vertex positions, with the rotations
// eliminated (the optimal R per evaluation; by the envelope theorem the
// gradient of min_R E(Q; R) is the fixed-R gradient). The stretch term is
// concave, so the energy is no sum of squares: ceres::GradientProblem with
// GradientProblemSolver (L-BFGS by default). The cascade on beta applies as
// for local-global, with one Ceres solve per cascade.
//
// Preconditioning by a change of variables: with M = beta A_beta + eps I (the
// summed Hessians of the beta-scaled quadratic terms, positive definite after
// the small shift) and its Cholesky factor M = P^T L L^T P, Ceres works on
// z = L^T P Q, where the energy's Hessian is close to the identity (on the
// zero-mean subspace its eigenvalues lie in [1 - n/(beta lambda_2), 1] for the
// paper's energy). Same energy, same minimisers; without it L-BFGS needs
// thousands of iterations (the condition number grows like 1/lambda_2).
#pragma once

#include <Eigen/SparseCholesky>
#include <string>

#include "solvers/cascade.h"
#include "solvers/unfold_problem.h"

namespace unfold {

/// Ceres GradientProblemSolver options, named as in ceres::GradientProblemSolver::Options.
struct CeresOptions {
  std::string line_search_direction_type =
      "LBFGS";                    ///< LBFGS, BFGS, NONLINEAR_CONJUGATE_GRADIENT, STEEPEST_DESCENT
  int max_num_iterations = 2000;  ///< per cascade
  double function_tolerance = 1e-10;
  double gradient_tolerance = 1e-12;
  double parameter_tolerance = 1e-14;
  int max_lbfgs_rank = 20;
};

/// Checks the option values. @throws UsageError naming the ceres.* key
void validate_ceres_options(const CeresOptions& options);

class CeresBackend : public CascadeBackend {
 public:
  /// @param problem kept by reference, must outlive the backend
  /// @throws UsageError for bad options
  CeresBackend(const UnfoldProblem& problem, const CeresOptions& options);
  void set_beta(double beta) override;
  bool bounded() const override { return bounded_; }
  /// Solves at the current beta to convergence (Ceres's own limits and
  /// tolerances; options.max_iterations and epsilon are not used), then checks
  /// the edge-ratio band once: a cascade is one converged Ceres solve.
  bool run_stage(const StageOptions& options, int cascade, Eigen::MatrixX3d* Q,
                 double* previous_energy, std::vector<IterationRecord>* history) override;
  /// The function Ceres minimises at the current beta, over the preconditioned
  /// variables z (3n doubles, row-major n x 3; Q = P^T L^-T z): min_R E(Q; R),
  /// and with gradient (3n doubles) its gradient in z.
  double objective(const double* z, double* gradient) const;

 private:
  const UnfoldProblem& problem_;
  CeresOptions options_;
  double beta_ = 0;
  bool bounded_ = true;
  Eigen::SimplicialLLT<Eigen::SparseMatrix<double>> preconditioner_;
};

}  // namespace unfold
