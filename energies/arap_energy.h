// The as-rigid-as-possible term of the paper (Eq. 2 summed over cells, w_ij = 1):
//   E_r(Q; R) = sum_i sum_{j in N_i} |q_i - q_j - R_i (p_i - p_j)|^2,
// each undirected edge appearing once in cell i and once in cell j.
#pragma once

#include <ceres/autodiff_cost_function.h>

#include <Eigen/Core>

#include "mesh/edge_graph.h"
#include "solvers/best_rotations.h"

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

/// E_r(Q; R) in O(m).
/// @param P    rest positions (n x 3)
/// @param Q    current positions (n x 3)
/// @param R    one rotation per vertex (n)
/// @param grad if not null, receives dE_r/dQ at fixed R (resized to n x 3)
double arap_energy(const EdgeGraph& graph, const Eigen::MatrixX3d& P, const Eigen::MatrixX3d& Q,
                   const Rotations& R, Eigen::MatrixX3d* grad = nullptr);

}  // namespace unfold
