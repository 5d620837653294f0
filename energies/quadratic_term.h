// Capability of a term whose residuals are affine in Q for fixed rotations R,
// with Jacobians J that act alike on x, y, z and do not depend on R:
//   e_t(Q; R) = |J q + r_0(R)|^2 = tr(Q^T H Q) - 2 tr(Q^T B(R)) + c(R),
//   H = J^T J,   B(R) = -J^T r_0(R),   c(R) = |r_0(R)|^2   (weights included),
// all three derived from the term's residuals (add_residuals): H by
// ResidualSum's Gauss-Newton mode, B as -1/2 the gradient at Q = 0, c as the
// value at Q = 0. The local-global solver assembles H once per mesh, and B and
// c once per mesh too for terms that are no RotationTerm. A term may override
// them with a faster closed form (ARAP does, for the per-iteration B and c);
// tests check the overrides against the derived forms (tests/energy_test.cpp).
//
// Every term is translation invariant, so H may differ from the true Hessian
// by multiples of 1 1^T: the solvers work on zero-mean Q, where those vanish.
// A term whose true Hessian is H + u u^T for some other u (the mass-weighted
// stretch term: H's residuals hold the centroid fixed) returns u from
// rank_one_hessian(): the direct global step needs not add it (its solution is
// then the exact minimiser up to a translation), the iterative one adds it to
// its products so that its matrix keeps zero-mean vectors zero-mean.
#pragma once

#include "energies/energy_term.h"

namespace unfold {

class QuadraticTerm : public EnergyTerm {
 public:
  /// @param num_vertices n, the rows of the Q the term is evaluated at
  QuadraticTerm(int num_vertices, double weight, bool scales_with_beta)
      : EnergyTerm(weight, scales_with_beta), num_vertices_(num_vertices) {}
  int num_vertices() const { return num_vertices_; }

  /// Adds scale * H as triplets (n x n). Default: add_derived_hessian.
  virtual void add_hessian(double scale, std::vector<Eigen::Triplet<double>>* H) const {
    add_derived_hessian(scale, H);
  }
  /// Adds scale * B(R) (n x 3). Default: add_derived_linear.
  virtual void add_linear(const Rotations& R, double scale, Eigen::MatrixX3d* B) const {
    add_derived_linear(R, scale, B);
  }
  /// c(R), the value at Q = 0. Default: derived_constant.
  virtual double constant(const Rotations& R) const { return derived_constant(R); }
  /// u with true Hessian = H + u u^T (up to multiples of 1 1^T); empty: none. Default: none.
  virtual Eigen::VectorXd rank_one_hessian() const { return {}; }
  /// U with true Hessian = H + U U^T + (rank_one_hessian part); n x 0: none.
  virtual Eigen::MatrixXd region_hessian() const { return {}; }

  /// H = J^T J from the residuals' Jacobians at Q = 0.
  /// @throws UsageError if a residual block's Jacobian does not act alike on x, y, z
  void add_derived_hessian(double scale, std::vector<Eigen::Triplet<double>>* H) const;
  /// B(R) = -1/2 de_t/dQ at Q = 0.
  void add_derived_linear(const Rotations& R, double scale, Eigen::MatrixX3d* B) const;
  /// c(R) = e_t(0; R).
  double derived_constant(const Rotations& R) const;

  /// H: the quadratic growth is the quadratic form itself.
  void add_growth_hessian(double scale, std::vector<Eigen::Triplet<double>>* H) const override {
    add_hessian(scale, H);
  }
  /// H: exact for a quadratic term.
  void add_preconditioner(double scale, std::vector<Eigen::Triplet<double>>* H) const override {
    add_hessian(scale, H);
  }

 private:
  int num_vertices_;
};

}  // namespace unfold
