// The as-rigid-as-possible term of the paper (Eq. 2 summed over cells):
//   e_r(Q; R) = sum_i sum_{j in N_i} w_ij |q_i - q_j - R_i (p_i - p_j)|^2,
// each undirected edge appearing once in cell i and once in cell j.
// Quadratic (H = 2 L_w, B_i = sum_j w_ij (R_i + R_j)(p_i - p_j), docs/method.md)
// and a rotation term. The local-global solver needs B and c every iteration:
// they, and H, have closed forms here, faster than the derived ones and tested
// equal to them (tests/energy_test.cpp).
#pragma once

#include <Eigen/Core>
#include <memory>
#include <vector>

#include "energies/quadratic_term.h"
#include "energies/rotation_term.h"
#include "mesh/cell_covariances.h"
#include "mesh/edge_graph.h"

namespace unfold {

/// The ARAP term (weight relative to beta: the cascade's beta multiplies it).
class ArapEnergy : public QuadraticTerm, public RotationTerm {
 public:
  /// @param rest         rest positions P (n x 3)
  /// @param edge_weights w_ij per graph edge (all 1 for the paper's uniform weights), > 0
  ArapEnergy(std::shared_ptr<const EdgeGraph> graph, const Eigen::MatrixX3d& rest,
             std::vector<double> edge_weights, double weight);
  std::string name() const override { return "arap"; }
  /// w_ij |q_i - q_j - R_i (p_i - p_j)|^2 for every cell i and neighbour j.
  double add_residuals(const Eigen::MatrixX3d& Q, const Rotations& R,
                       ResidualSum* sum) const override;
  void add_hessian(double scale, std::vector<Eigen::Triplet<double>>* H) const override;
  void add_linear(const Rotations& R, double scale, Eigen::MatrixX3d* B) const override;
  /// sum_i sum_j w_ij |p_i - p_j|^2: rotations keep lengths, so c does not depend on R.
  double constant(const Rotations& /*R*/) const override { return cells_.weighted_squared_length; }
  void add_rotation_covariance(const Eigen::MatrixX3d& Q, double scale,
                               std::vector<Eigen::Matrix3d>* S) const override;

 private:
  std::shared_ptr<const EdgeGraph> graph_;
  RowMatrixX3d rest_;
  std::vector<double> weights_;
  // The local and global steps sweep every cell each iteration: they read
  // these, laid out in the graph's CSR order, instead of gathering from rest_.
  CellRestEdges cells_;
};

}  // namespace unfold
