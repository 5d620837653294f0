// The stretch term of the paper's Eq. 3 with k_ij = 1:
//   e_s(Q) = - sum_i sum_{j not in N_i} |q_i - q_j|^2   (ordered pairs).
// Over all ordered pairs sum |q_i - q_j|^2 = 2n sum_i |q_i - c|^2 (c the
// centroid), so e_s = -2n sum_i |q_i - c|^2 + 2 sum_{edges} |q_i - q_j|^2: an
// O(n + m) sum of squared Ceres residuals with signs -1 and +1, never O(n^2).
// Quadratic: H = 2 L - 2n I (+ 2 1 1^T, which vanishes on zero-mean Q), B = 0.
#pragma once

#include <ceres/autodiff_cost_function.h>

#include <Eigen/Core>

#include "energies/energy_term.h"
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

/// The stretch term (weight k, not scaled by beta).
class StretchEnergy : public EnergyTerm {
 public:
  /// @param graph edge graph of the tet mesh; kept by reference, must outlive the term
  StretchEnergy(const EdgeGraph& graph, double weight) : EnergyTerm(weight, false), graph_(graph) {}
  std::string name() const override { return "stretch"; }
  double evaluate(const Eigen::MatrixX3d& Q, const Rotations& R, double scale,
                  Eigen::MatrixX3d* grad) const override;
  bool quadratic() const override { return true; }
  void add_hessian(double scale, std::vector<Eigen::Triplet<double>>* H) const override;
  double constant(const Rotations& /*R*/) const override { return 0; }

 private:
  const EdgeGraph& graph_;
};

}  // namespace unfold
