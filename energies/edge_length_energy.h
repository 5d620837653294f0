// Edge-length springs (the DPMU baseline's length preservation, Sahillioglu
// and Kavan): each tet edge should keep its rest length,
//   e_l(Q) = sum_i sum_{j in N_i} (|q_i - q_j| - |p_i - p_j|)^2,
// each undirected edge once in cell i and once in cell j, as in the ARAP term,
// so that far from the rest shape e_l grows like the ARAP term (2 L) and beta
// keeps its scale n / lambda_2 (docs/method.md). Rotation free and not
// quadratic: only the Ceres backend minimises it.
#pragma once

#include <ceres/autodiff_cost_function.h>

#include <Eigen/Core>

#include "energies/energy_term.h"
#include "mesh/edge_graph.h"

namespace unfold {

/// sqrt(2) (|q_i - q_j| - l): one edge's spring, counted for both of its cells.
struct EdgeLengthResidual {
  explicit EdgeLengthResidual(double rest_length) : l(rest_length) {}
  template <typename T>
  bool operator()(const T* qi, const T* qj, T* r) const {
    using std::sqrt;
    const T dx = qi[0] - qj[0], dy = qi[1] - qj[1], dz = qi[2] - qj[2];
    r[0] = T(M_SQRT2) * (sqrt(dx * dx + dy * dy + dz * dz) - T(l));
    return true;
  }
  static ceres::CostFunction* Create(double rest_length) {
    return new ceres::AutoDiffCostFunction<EdgeLengthResidual, 1, 3, 3>(
        new EdgeLengthResidual(rest_length));
  }
  double l;
};

/// The edge-length term (weight relative to beta).
class EdgeLengthEnergy : public EnergyTerm {
 public:
  /// @param graph edge graph; kept by reference, must outlive the term
  /// @param rest  rest positions P (n x 3); no edge of zero rest length
  EdgeLengthEnergy(const EdgeGraph& graph, const Eigen::MatrixX3d& rest, double weight);
  std::string name() const override { return "edge_length"; }
  /// @pre no edge has zero length in Q (the length's gradient is undefined there)
  double evaluate(const Eigen::MatrixX3d& Q, const Rotations& R, double scale,
                  Eigen::MatrixX3d* grad) const override;
  /// 2 L: e_l's quadratic growth far from the rest shape.
  void add_growth_hessian(double scale, std::vector<Eigen::Triplet<double>>* H) const override;
  /// 2 L as well: an upper bound of the Gauss-Newton Hessian near the rest shape.
  void add_preconditioner(double scale, std::vector<Eigen::Triplet<double>>* H) const override {
    add_growth_hessian(scale, H);
  }

 private:
  const EdgeGraph& graph_;
  Eigen::VectorXd rest_length_;
};

}  // namespace unfold
