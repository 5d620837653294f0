#include "solvers/fiedler_value.h"

#include <Spectra/SymEigsShiftSolver.h>
#include <glog/logging.h>

#include <Eigen/SparseCholesky>

#include "core/errors.h"
#include "core/progress.h"
#include "solvers/lobpcg.h"

namespace unfold {
namespace {

// y = P (L - sigma I)^{-1} P x with P the projector off the constant vector,
// so the zero mode never competes with lambda_2. With masses D, the same for
// the symmetric form D^{-1/2} L D^{-1/2} of L x = lambda D x, whose zero mode
// is u = D^{1/2} 1 / |D^{1/2} 1|: (D^{-1/2} L D^{-1/2} - sigma I)^{-1} =
// D^{1/2} (L - sigma D)^{-1} D^{1/2}.
class ProjectedShiftSolve {
 public:
  using Scalar = double;
  ProjectedShiftSolve(const Eigen::SparseMatrix<double>& L, const Eigen::VectorXd& masses)
      : L_(L), masses_(masses) {
    if (masses_.size()) {
      sqrt_masses_ = masses_.cwiseSqrt();
      u_ = sqrt_masses_.normalized();
    }
  }
  Eigen::Index rows() const { return L_.rows(); }
  Eigen::Index cols() const { return L_.cols(); }
  void set_shift(double sigma) {
    Eigen::SparseMatrix<double> D(L_.rows(), L_.cols());
    if (masses_.size()) {
      D = Eigen::SparseMatrix<double>(masses_.asDiagonal());
    } else {
      D.setIdentity();
    }
    solver_.compute(L_ - sigma * D);
    if (solver_.info() != Eigen::Success)
      throw NumericalError("factorizing the shifted Laplacian for lambda_2 failed");
  }
  void perform_op(const double* x_in, double* y_out) const {
    Eigen::Map<const Eigen::VectorXd> x(x_in, rows());
    Eigen::Map<Eigen::VectorXd> y(y_out, rows());
    if (masses_.size() == 0) {
      y = solver_.solve((x.array() - x.mean()).matrix());
      y.array() -= y.mean();
      return;
    }
    const Eigen::VectorXd projected = x - u_ * u_.dot(x);
    y = sqrt_masses_.cwiseProduct(solver_.solve(sqrt_masses_.cwiseProduct(projected)));
    y -= u_ * u_.dot(y);
  }

 private:
  const Eigen::SparseMatrix<double>& L_;
  const Eigen::VectorXd& masses_;
  Eigen::VectorXd sqrt_masses_, u_;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver_;
};

void check_masses(const Eigen::SparseMatrix<double>& L, const Eigen::VectorXd& masses) {
  if (masses.size() != 0 && (masses.size() != L.rows() || !(masses.minCoeff() > 0)))
    throw UsageError("lambda_2: the masses must be empty or one positive mass per vertex");
}

}  // namespace

double fiedler_value(const Eigen::SparseMatrix<double>& L, const Eigen::VectorXd& masses) {
  const Eigen::Index n = L.rows();
  if (n < 2) throw NumericalError("lambda_2 needs a graph of at least 2 vertices");
  check_masses(L, masses);
  report_stage("lambda_2 of " + std::to_string(n) + " vertices");
  // A shift far below lambda_2 (masses scale the eigenvalues by 1 / their mean).
  const double sigma = -1e-8 * L.diagonal().maxCoeff() / (masses.size() ? masses.mean() : 1.0);
  ProjectedShiftSolve op(L, masses);
  const Eigen::Index ncv = std::min<Eigen::Index>(n, 20);
  Spectra::SymEigsShiftSolver<ProjectedShiftSolve> eigs(op, 1, ncv, sigma);
  eigs.init();
  eigs.compute(Spectra::SortRule::LargestMagn, 1000, 1e-10);
  if (eigs.info() != Spectra::CompInfo::Successful)
    throw NumericalError("the eigen-solver for lambda_2 did not converge");
  return eigs.eigenvalues()(0);
}

double fiedler_value(const Eigen::SparseMatrix<double>& L, const AmgData& amg,
                     const Eigen::VectorXd& masses) {
  if (L.rows() < 100) return fiedler_value(L, masses);
  report_stage("lambda_2 of " + std::to_string(L.rows()) + " vertices (LOBPCG)");
  const LobpcgResult r = lobpcg_smallest(CsrView::of_symmetric(L), amg, {}, masses);
  if (!r.converged)
    throw NumericalError("LOBPCG for lambda_2 did not converge (relative residual " +
                         std::to_string(r.relative_residual) + " after " +
                         std::to_string(r.iterations) + " iterations)");
  VLOG(1) << "lambda_2 = " << r.values[0] << ": LOBPCG, " << r.iterations << " iterations";
  return r.values[0];
}

}  // namespace unfold
