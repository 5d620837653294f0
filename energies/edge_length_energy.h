// Edge-length springs (the DPMU baseline's length preservation, Sahillioglu
// and Kavan): each tet edge should keep its rest length,
//   e_l(Q) = sum_i sum_{j in N_i} (|q_i - q_j| - |p_i - p_j|)^2,
// each undirected edge once in cell i and once in cell j, as in the ARAP term,
// so that far from the rest shape e_l grows like the ARAP term (2 L) and beta
// keeps its scale n / lambda_2 (docs/method.md). Rotation free and not
// quadratic: only the Ceres backend minimises it.
#pragma once

#include <Eigen/Core>
#include <memory>

#include "energies/energy_term.h"
#include "mesh/edge_graph.h"

namespace unfold {

/// |q_i - q_j| - l: one edge's spring (weighted 2: counted for both of its cells).
struct EdgeLengthResidual {
  explicit EdgeLengthResidual(double rest_length) : l(rest_length) {}
  template <typename T>
  bool operator()(const T* qi, const T* qj, T* r) const {
    using std::sqrt;
    const T dx = qi[0] - qj[0], dy = qi[1] - qj[1], dz = qi[2] - qj[2];
    r[0] = sqrt(dx * dx + dy * dy + dz * dz) - T(l);
    return true;
  }
  double l;
};

/// The edge-length term (weight relative to beta).
class EdgeLengthEnergy : public EnergyTerm {
 public:
  /// @param rest  rest positions P (n x 3); no edge of zero rest length
  EdgeLengthEnergy(std::shared_ptr<const EdgeGraph> graph, const Eigen::MatrixX3d& rest,
                   double weight);
  std::string name() const override { return "edge_length"; }
  /// @pre (gradients) no edge has zero length in Q: the length's gradient is undefined there
  double add_residuals(const Eigen::MatrixX3d& Q, const Rotations& R,
                       ResidualSum* sum) const override;
  /// 2 L: e_l's quadratic growth far from the rest shape.
  void add_growth_hessian(double scale, std::vector<Eigen::Triplet<double>>* H) const override;
  /// 2 L as well: an upper bound of the Gauss-Newton Hessian near the rest shape.
  void add_preconditioner(double scale, std::vector<Eigen::Triplet<double>>* H) const override {
    add_growth_hessian(scale, H);
  }

 private:
  std::shared_ptr<const EdgeGraph> graph_;
  Eigen::VectorXd rest_length_;
};

}  // namespace unfold
