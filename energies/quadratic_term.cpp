#include "energies/quadratic_term.h"

#include "core/errors.h"
#include "energies/residual_sum.h"

namespace unfold {
namespace {

Eigen::MatrixX3d zero_positions(int n) { return Eigen::MatrixX3d::Zero(n, 3); }

}  // namespace

void QuadraticTerm::add_derived_hessian(double scale,
                                        std::vector<Eigen::Triplet<double>>* H) const {
  // J does not depend on R (the interface's precondition): any rotations serve.
  const Rotations identity(size_t(num_vertices_), Eigen::Matrix3d::Identity());
  const Eigen::MatrixX3d zero = zero_positions(num_vertices_);
  ResidualSum sum(zero, scale, H);
  try {
    add_residuals(zero, identity, &sum);
  } catch (const UsageError& e) {
    throw UsageError("the " + name() + " term: " + e.what());
  }
  sum.finish();
}

void QuadraticTerm::add_derived_linear(const Rotations& R, double scale,
                                       Eigen::MatrixX3d* B) const {
  evaluate(zero_positions(num_vertices_), R, -0.5 * scale, B);
}

double QuadraticTerm::derived_constant(const Rotations& R) const {
  return evaluate(zero_positions(num_vertices_), R, 1.0, nullptr);
}

}  // namespace unfold
