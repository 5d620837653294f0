// Capability of a term concave in Q, whose tangent plane at any Q lies above
// it: e_t(Q') <= e_t(Q) + <de_t/dQ(Q), Q' - Q>. The local-global solver's
// global step takes the tangent at the iterate in place of the term (its
// linear part joins the right-hand side), so a plain step still lowers the
// energy (majorize-minimize, as the local step's rotations do for ARAP). The
// term adds nothing to the global matrix; its value and gradient are
// EnergyTerm::evaluate's.
#pragma once

#include <Eigen/Core>

namespace unfold {

class ConcaveTerm {
 public:
  virtual ~ConcaveTerm() = default;
  /// Adds -scale/2 de_t/dQ at Q into *B (n x 3): the linear part of the
  /// tangent at Q written as -2 tr(Q'^T B), as the global step's B is.
  virtual void add_tangent(const Eigen::MatrixX3d& Q, double scale, Eigen::MatrixX3d* B) const = 0;
};

}  // namespace unfold
