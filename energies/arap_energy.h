// The as-rigid-as-possible term of the paper (Eq. 2 summed over cells):
//   e_r(Q; R) = sum_i sum_{j in N_i} w_ij |q_i - q_j - R_i (p_i - p_j)|^2,
// each undirected edge appearing once in cell i and once in cell j.
// Quadratic: H = 2 L_w, B_i = sum_j w_ij (R_i + R_j)(p_i - p_j) (docs/method.md).
#pragma once

#include <ceres/autodiff_cost_function.h>

#include <Eigen/Core>
#include <vector>

#include "energies/energy_term.h"
#include "geometry/row_major.h"
#include "mesh/cell_covariances.h"
#include "mesh/edge_graph.h"

namespace unfold {

/// sqrt(w) (q_i - q_j - b) with b = R_i (p_i - p_j) the rotated rest edge, R_i held fixed.
struct ArapEdgeResidual {
  ArapEdgeResidual(const Eigen::Vector3d& rotated_rest_edge, double weight = 1.0)
      : b(rotated_rest_edge), sqrt_weight(std::sqrt(weight)) {}
  template <typename T>
  bool operator()(const T* qi, const T* qj, T* r) const {
    for (int k = 0; k < 3; ++k) r[k] = T(sqrt_weight) * (qi[k] - qj[k] - T(b[k]));
    return true;
  }
  static ceres::CostFunction* Create(const Eigen::Vector3d& rotated_rest_edge,
                                     double weight = 1.0) {
    return new ceres::AutoDiffCostFunction<ArapEdgeResidual, 3, 3, 3>(
        new ArapEdgeResidual(rotated_rest_edge, weight));
  }
  Eigen::Vector3d b;
  double sqrt_weight;
};

/// The ARAP term (weight relative to beta: the cascade's beta multiplies it).
class ArapEnergy : public EnergyTerm {
 public:
  /// @param graph        edge graph; kept by reference, must outlive the term
  /// @param rest         rest positions P (n x 3)
  /// @param edge_weights w_ij per graph edge (all 1 for the paper's uniform weights), > 0
  ArapEnergy(const EdgeGraph& graph, const Eigen::MatrixX3d& rest, std::vector<double> edge_weights,
             double weight);
  std::string name() const override { return "arap"; }
  double evaluate(const Eigen::MatrixX3d& Q, const Rotations& R, double scale,
                  Eigen::MatrixX3d* grad) const override;
  bool quadratic() const override { return true; }
  void add_hessian(double scale, std::vector<Eigen::Triplet<double>>* H) const override;
  void add_linear(const Rotations& R, double scale, Eigen::MatrixX3d* B) const override;
  /// sum_i sum_j w_ij |p_i - p_j|^2: rotations keep lengths, so c does not depend on R.
  double constant(const Rotations& /*R*/) const override { return cells_.weighted_squared_length; }
  bool uses_rotations() const override { return true; }
  void add_rotation_covariance(const Eigen::MatrixX3d& Q, double scale,
                               std::vector<Eigen::Matrix3d>* S) const override;

 private:
  const EdgeGraph& graph_;
  RowMatrixX3d rest_;
  std::vector<double> weights_;
  // The local and global steps sweep every cell each iteration: they read
  // these, laid out in the graph's CSR order, instead of gathering from rest_.
  CellRestEdges cells_;
};

}  // namespace unfold
