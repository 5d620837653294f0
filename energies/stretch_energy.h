// The stretch term of the paper's Eq. 3 with k_ij = 1:
//   E_s(Q) = - sum_i sum_{j not in N_i} |q_i - q_j|^2   (ordered pairs).
// Over all ordered pairs sum |q_i - q_j|^2 = 2n sum_i |q_i - c|^2 (c the
// centroid), so E_s = -2n sum_i |q_i - c|^2 + 2 sum_{edges} |q_i - q_j|^2,
// an O(n + m) sum of squared Ceres residuals with signs -1 and +1.
#pragma once

#include <ceres/autodiff_cost_function.h>

#include <Eigen/Core>

#include "mesh/edge_graph.h"

namespace unfold {

/// sqrt(2n) (q_i - c): the spread of one vertex about the centroid c. The
/// centroid is held fixed: at the true centroid the derivative through c
/// vanishes because sum_i (q_i - c) = 0.
struct StretchSpreadResidual {
  StretchSpreadResidual(const Eigen::Vector3d& centroid, double num_vertices)
      : c(centroid), scale(std::sqrt(2.0 * num_vertices)) {}
  template <typename T>
  bool operator()(const T* q, T* r) const {
    for (int k = 0; k < 3; ++k) r[k] = T(scale) * (q[k] - T(c[k]));
    return true;
  }
  static ceres::CostFunction* Create(const Eigen::Vector3d& centroid, double num_vertices) {
    return new ceres::AutoDiffCostFunction<StretchSpreadResidual, 3, 3>(
        new StretchSpreadResidual(centroid, num_vertices));
  }
  Eigen::Vector3d c;
  double scale;
};

/// sqrt(2) (q_i - q_j) for one edge: the neighbour pairs that the stretch term excludes.
struct StretchEdgeResidual {
  template <typename T>
  bool operator()(const T* qi, const T* qj, T* r) const {
    for (int k = 0; k < 3; ++k) r[k] = T(M_SQRT2) * (qi[k] - qj[k]);
    return true;
  }
  static ceres::CostFunction* Create() {
    return new ceres::AutoDiffCostFunction<StretchEdgeResidual, 3, 3, 3>(new StretchEdgeResidual);
  }
};

/// E_s(Q) in O(n + m).
/// @param Q    positions (n x 3), n = graph.num_vertices
/// @param grad if not null, receives dE_s/dQ (resized to n x 3)
double stretch_energy(const EdgeGraph& graph, const Eigen::MatrixX3d& Q,
                      Eigen::MatrixX3d* grad = nullptr);

}  // namespace unfold
