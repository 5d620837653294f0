#include "solvers/fiedler_value.h"

#include <Spectra/SymEigsShiftSolver.h>
#include <glog/logging.h>

#include <Eigen/SparseCholesky>

#include "core/errors.h"
#include "solvers/lobpcg.h"

namespace unfold {
namespace {

// y = P (L - sigma I)^{-1} P x with P the projector off the constant vector,
// so the zero mode never competes with lambda_2.
class ProjectedShiftSolve {
 public:
  using Scalar = double;
  explicit ProjectedShiftSolve(const Eigen::SparseMatrix<double>& L) : L_(L) {}
  Eigen::Index rows() const { return L_.rows(); }
  Eigen::Index cols() const { return L_.cols(); }
  void set_shift(double sigma) {
    Eigen::SparseMatrix<double> I(L_.rows(), L_.cols());
    I.setIdentity();
    solver_.compute(L_ - sigma * I);
    if (solver_.info() != Eigen::Success)
      throw NumericalError("factorizing the shifted Laplacian for lambda_2 failed");
  }
  void perform_op(const double* x_in, double* y_out) const {
    Eigen::Map<const Eigen::VectorXd> x(x_in, rows());
    Eigen::Map<Eigen::VectorXd> y(y_out, rows());
    y = solver_.solve((x.array() - x.mean()).matrix());
    y.array() -= y.mean();
  }

 private:
  const Eigen::SparseMatrix<double>& L_;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver_;
};

}  // namespace

double fiedler_value(const Eigen::SparseMatrix<double>& L) {
  const Eigen::Index n = L.rows();
  if (n < 2) throw NumericalError("lambda_2 needs a graph of at least 2 vertices");
  const double sigma = -1e-8 * L.diagonal().maxCoeff();
  ProjectedShiftSolve op(L);
  const Eigen::Index ncv = std::min<Eigen::Index>(n, 20);
  Spectra::SymEigsShiftSolver<ProjectedShiftSolve> eigs(op, 1, ncv, sigma);
  eigs.init();
  eigs.compute(Spectra::SortRule::LargestMagn, 1000, 1e-10);
  if (eigs.info() != Spectra::CompInfo::Successful)
    throw NumericalError("the eigen-solver for lambda_2 did not converge");
  return eigs.eigenvalues()(0);
}

double fiedler_value(const Eigen::SparseMatrix<double>& L, const AmgData& amg) {
  if (L.rows() < 100) return fiedler_value(L);
  const LobpcgResult r = lobpcg_smallest(CsrView::of_symmetric(L), amg);
  if (!r.converged)
    throw NumericalError("LOBPCG for lambda_2 did not converge (relative residual " +
                         std::to_string(r.relative_residual) + " after " +
                         std::to_string(r.iterations) + " iterations)");
  VLOG(1) << "lambda_2 = " << r.values[0] << ": LOBPCG, " << r.iterations << " iterations";
  return r.values[0];
}

}  // namespace unfold
