// The shift-invert operator Spectra's SymEigsShiftSolver needs for the
// generalized problem L x = lambda M x (M diagonal, the masses), in its
// symmetric form M^{-1/2} L M^{-1/2}:
// (M^{-1/2} L M^{-1/2} - sigma I)^{-1} = M^{1/2} (L - sigma M)^{-1} M^{1/2}.
// Shared by lambda_2 (solvers/fiedler_value.h) and the Laplace-Beltrami basis
// (solvers/laplace_beltrami_basis.h); included by their .cpp files only.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCholesky>
#include <string>
#include <utility>

#include "core/errors.h"

namespace unfold {

class MassShiftInvert {
 public:
  using Scalar = double;
  /// @param L symmetric, kept by reference
  /// @param masses empty (M = I) or one positive mass per row, kept by reference
  /// @param deflate_constant project off the zero mode M^{1/2} 1 before and
  ///        after the solve, so that it never competes with the eigenvalues sought
  /// @param what named in the NumericalError thrown when L - sigma M cannot be factored
  MassShiftInvert(const Eigen::SparseMatrix<double>& L, const Eigen::VectorXd& masses,
                  bool deflate_constant, std::string what)
      : L_(L), masses_(masses), deflate_(deflate_constant), what_(std::move(what)) {
    if (masses_.size()) {
      sqrt_masses_ = masses_.cwiseSqrt();
      u_ = sqrt_masses_.normalized();
    }
  }
  Eigen::Index rows() const { return L_.rows(); }
  Eigen::Index cols() const { return L_.cols(); }
  void set_shift(double sigma) {
    Eigen::SparseMatrix<double> M(L_.rows(), L_.cols());
    if (masses_.size()) {
      M = Eigen::SparseMatrix<double>(masses_.asDiagonal());
    } else {
      M.setIdentity();
    }
    solver_.compute(L_ - sigma * M);
    if (solver_.info() != Eigen::Success) throw NumericalError("factorizing " + what_ + " failed");
  }
  void perform_op(const double* x_in, double* y_out) const {
    Eigen::Map<const Eigen::VectorXd> x(x_in, rows());
    Eigen::Map<Eigen::VectorXd> y(y_out, rows());
    if (masses_.size() == 0) {  // u is the constant vector: projecting is taking the mean
      y = solver_.solve(deflate_ ? Eigen::VectorXd(x.array() - x.mean()) : Eigen::VectorXd(x));
      if (deflate_) y.array() -= y.mean();
      return;
    }
    const Eigen::VectorXd projected = deflate_ ? Eigen::VectorXd(x - u_ * u_.dot(x)) : x;
    y = sqrt_masses_.cwiseProduct(solver_.solve(sqrt_masses_.cwiseProduct(projected)));
    if (deflate_) y -= u_ * u_.dot(y);
  }

 private:
  const Eigen::SparseMatrix<double>& L_;
  const Eigen::VectorXd& masses_;
  bool deflate_;
  std::string what_;
  Eigen::VectorXd sqrt_masses_, u_;  // M^{1/2} 1 and the zero mode, normalized
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver_;
};

}  // namespace unfold
