// One term of the unfolding energy. A term is its functor: it lists its
// residual blocks once (add_residuals), and everything a solver needs of it is
// derived from that list (energies/residual_sum.h). Solvers sum terms and never
// know which terms there are.
//
// The energy at beta is  E(Q; R) = sum_t w_t(beta) e_t(Q; R),  where w_t(beta) is
// the term's weight, times beta for terms that scale with it (the cascade
// doubles beta).
//
// Capabilities, each a small interface:
//  - every term (this class): its value and gradient, and the matrices that
//    bound and precondition it;
//  - QuadraticTerm (energies/quadratic_term.h): residuals affine in Q for fixed
//    R, so e_t = tr(Q^T H Q) - 2 tr(Q^T B(R)) + c(R): the local-global solver's
//    global step;
//  - RotationTerm (energies/rotation_term.h): depends on per-vertex rotations R
//    and gives the local step its cell covariances;
//  - ConcaveTerm (energies/concave_term.h): concave in Q, so its tangent plane
//    majorizes it: the local-global solver's global step takes that tangent.
// Which backend runs which terms is decided from these alone
// (solvers/backend_support.h).
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <string>
#include <vector>

#include "geometry/rotations.h"

namespace unfold {

class ResidualSum;

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

  /// Adds every residual block of e_t at (Q, R) into sum (ResidualSum::add) and
  /// returns the sum of what add returned: e_t(Q; R) = sum_b w_b |f_b|^2. The
  /// blocks' functors may depend on Q itself only where that dependence has no
  /// first-order effect (the stretch term's centroid).
  /// @pre Q is n x 3 and R holds n rotations
  virtual double add_residuals(const Eigen::MatrixX3d& Q, const Rotations& R,
                               ResidualSum* sum) const = 0;

  /// scale * e_t(Q; R); when grad is not null, adds scale * de_t/dQ (at fixed R)
  /// into it. From add_residuals; a term that is no sum of squares (the spread
  /// by distances, energies/distance_spread_energy.h) overrides it.
  /// @pre grad is n x 3 when given
  virtual double evaluate(const Eigen::MatrixX3d& Q, const Rotations& R, double scale,
                          Eigen::MatrixX3d* grad) const;

  /// Adds scale * the Hessian of the term's quadratic growth far from the rest
  /// shape (acting alike on x, y, z): what bounds the concave stretch term,
  /// so it sets the boundedness bound and the scale of beta. Quadratic terms
  /// add H; others that grow quadratically override; the default adds nothing.
  virtual void add_growth_hessian(double /*scale*/,
                                  std::vector<Eigen::Triplet<double>>* /*H*/) const {}

  /// Adds scale * an n x n positive semi-definite approximation of the term's
  /// Hessian (acting alike on x, y, z), used to precondition the Ceres backend.
  /// Quadratic terms add H; the default adds nothing.
  virtual void add_preconditioner(double /*scale*/,
                                  std::vector<Eigen::Triplet<double>>* /*H*/) const {}

 private:
  double weight_;
  bool scales_with_beta_;
};

}  // namespace unfold
