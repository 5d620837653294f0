// The stretch term of the paper's Eq. 3 with k_ij = 1:
//   e_s(Q) = - sum_i sum_{j not in N_i} |q_i - q_j|^2   (ordered pairs).
// Over all ordered pairs sum |q_i - q_j|^2 = 2n sum_i |q_i - c|^2 (c the
// centroid), so e_s = -2n sum_i |q_i - c|^2 + 2 sum_{edges} |q_i - q_j|^2: an
// O(n + m) sum of squared residuals with weights -2n and 2, never O(n^2).
// Quadratic: H = 2 L - 2n I (+ 2 1 1^T, which vanishes on zero-mean Q), B = 0;
// H has a closed form, faster than the derived one and tested equal to it.
#pragma once

#include <Eigen/Core>
#include <memory>

#include "energies/quadratic_term.h"
#include "mesh/edge_graph.h"

namespace unfold {

/// q_i - c: the spread of one vertex about the centroid c. The centroid is held
/// fixed: at the true centroid the derivative through c vanishes because
/// sum_i (q_i - c) = 0.
struct SpreadResidual {
  explicit SpreadResidual(const Eigen::Vector3d& centroid) : c(centroid) {}
  template <typename T>
  bool operator()(const T* q, T* r) const {
    for (int k = 0; k < 3; ++k) r[k] = q[k] - T(c[k]);
    return true;
  }
  Eigen::Vector3d c;
};

/// The stretch term (weight k, not scaled by beta).
class StretchEnergy : public QuadraticTerm {
 public:
  /// @param graph edge graph of the tet mesh
  StretchEnergy(std::shared_ptr<const EdgeGraph> graph, double weight)
      : QuadraticTerm(graph->num_vertices, weight, false), graph_(std::move(graph)) {}
  std::string name() const override { return "stretch"; }
  double add_residuals(const Eigen::MatrixX3d& Q, const Rotations& R,
                       ResidualSum* sum) const override;
  /// H in closed form, 2 (D - n I) on the diagonal and -2 per edge: n + 2m
  /// triplets where the derived form has n + 4m (docs/performance.md).
  void add_hessian(double scale, std::vector<Eigen::Triplet<double>>* H) const override;

 private:
  std::shared_ptr<const EdgeGraph> graph_;
};

}  // namespace unfold
