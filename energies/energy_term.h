// One term of the unfolding energy. Terms are pluggable: a solver sums them and
// never needs to know which terms there are (adding a term = a new file in
// energies/ and a config key in config/config_keys.h).
//
// The energy at beta is  E(Q; R) = sum_t w_t(beta) e_t(Q; R),  where w_t(beta) is
// the term's weight, times beta for terms that scale with it (the cascade
// doubles beta). Each term evaluates its unweighted value e_t and gradient
// through Ceres cost functors (energies/jet_evaluation.h).
//
// Quadratic terms also expose e_t = tr(Q^T H Q) - 2 tr(Q^T B(R)) + c with a
// constant sparse H, so the local-global solver can assemble its linear system
// sum_t w_t H_t Q = sum_t w_t B_t(R). Every term is translation invariant, so
// H may differ from the true Hessian by multiples of 1 1^T: the solvers work on
// zero-mean Q, where those vanish.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <string>
#include <vector>

#include "geometry/rotations.h"

namespace unfold {

class EnergyTerm {
 public:
  EnergyTerm(double weight, bool scales_with_beta)
      : weight_(weight), scales_with_beta_(scales_with_beta) {}
  virtual ~EnergyTerm() = default;

  /// Short name, as in the config and in reports ("stretch", "arap", ...).
  virtual std::string name() const = 0;

  /// w_t(beta): the weight, times beta if the term scales with beta.
  double weight(double beta) const { return scales_with_beta_ ? weight_ * beta : weight_; }
  bool scales_with_beta() const { return scales_with_beta_; }

  /// The unweighted value e_t(Q; R); when grad is not null, adds scale * de_t/dQ
  /// (at fixed R) into it. @pre grad is n x 3 when given.
  virtual double evaluate(const Eigen::MatrixX3d& Q, const Rotations& R, double scale,
                          Eigen::MatrixX3d* grad) const = 0;

  /// True for terms of the form tr(Q^T H Q) - 2 tr(Q^T B(R)) + c.
  virtual bool quadratic() const { return false; }
  /// Adds scale * H as triplets (quadratic terms only).
  virtual void add_hessian(double /*scale*/, std::vector<Eigen::Triplet<double>>* /*H*/) const {}
  /// Adds scale * B(R) (quadratic terms only).
  virtual void add_linear(const Rotations& /*R*/, double /*scale*/, Eigen::MatrixX3d* /*B*/) const {
  }
  /// c(R) (quadratic terms only): the value at Q = 0. The local-global solver
  /// gets the energy after a global step from it without a sweep over the
  /// mesh; terms override this with their closed form.
  virtual double constant(const Rotations& R) const {
    return evaluate(Eigen::MatrixX3d::Zero(R.size(), 3), R, 0, nullptr);
  }

  /// Adds scale * the Hessian of the term's quadratic growth far from the rest
  /// shape (acting alike on x, y, z): what bounds the concave stretch term,
  /// so it sets the boundedness bound and the scale of beta. Quadratic terms
  /// add H; non-quadratic terms that grow quadratically override.
  virtual void add_growth_hessian(double scale, std::vector<Eigen::Triplet<double>>* H) const {
    add_hessian(scale, H);
  }

  /// Adds scale * an n x n positive semi-definite approximation of the term's
  /// Hessian (acting alike on x, y, z), used to precondition iterative solvers.
  /// Quadratic terms add H; others override.
  virtual void add_preconditioner(double scale, std::vector<Eigen::Triplet<double>>* H) const {
    add_hessian(scale, H);
  }

  /// True if e_t depends on the per-vertex rotations R.
  virtual bool uses_rotations() const { return false; }
  /// Adds scale * this term's cell covariances sum_j w_ij (p_i - p_j)(q_i - q_j)^T,
  /// so the local step minimises the sum of all rotation terms (one 3x3 per vertex).
  virtual void add_rotation_covariance(const Eigen::MatrixX3d& /*Q*/, double /*scale*/,
                                       std::vector<Eigen::Matrix3d>* /*S*/) const {}

 private:
  double weight_;
  bool scales_with_beta_;
};

}  // namespace unfold
