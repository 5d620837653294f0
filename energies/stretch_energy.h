// The stretch term of the paper's Eq. 3 with k_ij = 1:
//   e_s(Q) = - sum_i sum_{j not in N_i} |q_i - q_j|^2   (ordered pairs).
// Over all ordered pairs sum |q_i - q_j|^2 = 2n sum_i |q_i - c|^2 (c the
// centroid), so e_s = -2n sum_i |q_i - c|^2 + 2 sum_{edges} |q_i - q_j|^2: an
// O(n + m) sum of squared residuals with weights -2n and 2, never O(n^2).
// Quadratic: H = 2 L - 2n I (+ 2 1 1^T, which vanishes on zero-mean Q), B = 0;
// H has a closed form, faster than the derived one and tested equal to it.
//
// With vertex masses m (stretch.masses: lumped; scaled to mean 1, so M = sum m
// = n) every pair is weighted by m_i m_j: e_s = -2M sum_i m_i |q_i - c_m|^2 +
// 2 sum_{edges} m_i m_j |q_i - q_j|^2 with c_m the mass-weighted centroid, and
// H = 2 L_mm - 2M diag(m) + 2 m m^T. The last part is not a multiple of 1 1^T:
// it is the term's rank_one_hessian(), which the iterative solver adds to its
// products and the direct one needs not (docs/method.md). Each vertex then
// pulls with its share of the shape, not as one vertex: the result no longer
// depends on where the mesh is dense.
//
// Local spread (stretch.local t > 0, energies/spread_regions.h): a share t of
// the spread is taken within soft regions (weights w_ik, sum_k w_ik = 1) about
// their own centroids c_k: -2M [(1 - t) sum_i m_i |q_i - c_m|^2 + t sum_k sum_i
// m_i w_ik |q_i - c_k|^2]. By the law of total variance the second sum is the
// first less the spread of the regions' centroids, sum_k M_k |c_k - c_m|^2, so
// the energy is bounded wherever t = 0's is, and H's sparse part is unchanged:
// the centroids add 2M t sum_k a_k a_k^T / M_k (a_ik = m_i w_ik), whose columns
// region_hessian() returns (the direct global step adds them by Woodbury's
// identity, docs/method.md). add_residuals evaluates it in closed form, one
// residual a vertex, not one per vertex and region.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <memory>

#include "energies/quadratic_term.h"
#include "energies/spread_regions.h"
#include "mesh/edge_graph.h"

namespace unfold {

/// q_i - c: the spread of one vertex about the centroid c. The centroid is held
/// fixed: at the true centroid the derivative through c vanishes because
/// sum_i m_i (q_i - c) = 0.
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
  /// @param graph  edge graph of the tet mesh
  /// @param masses vertex masses (positive, scaled here to mean 1); empty: every vertex 1 (paper)
  /// @param regions the local spread's regions; count 0: none (the paper's spread)
  /// @throws UsageError if masses has the wrong size or a mass is not positive and
  ///         finite, or a region weight names a vertex or region out of range
  StretchEnergy(std::shared_ptr<const EdgeGraph> graph, double weight,
                Eigen::VectorXd masses = Eigen::VectorXd(), SpreadRegions regions = {});
  std::string name() const override { return "stretch"; }
  double add_residuals(const Eigen::MatrixX3d& Q, const Rotations& R,
                       ResidualSum* sum) const override;
  /// H in closed form: 2 (D - n I) on the diagonal and -2 per edge (n + 2m
  /// triplets where the derived form has n + 4m, docs/performance.md); with
  /// masses 2 (sum_j m_i m_j - M m_i) and -2 m_i m_j.
  void add_hessian(double scale, std::vector<Eigen::Triplet<double>>* H) const override;
  /// sqrt(2 (1 - t)) m with masses; empty without (1 1^T vanishes on zero-mean Q).
  Eigen::VectorXd rank_one_hessian() const override;
  /// Columns sqrt(2 M t / M_k) a_k, one per region (n x 0 without regions).
  Eigen::MatrixXd region_hessian() const override;
  /// Vertex i's mass (at mean 1); 1 without masses.
  double mass(int i) const { return masses_.size() ? masses_[i] : 1.0; }

 private:
  std::shared_ptr<const EdgeGraph> graph_;
  Eigen::VectorXd masses_;
  double local_;                                          ///< the share t in the regions
  Eigen::SparseMatrix<double, Eigen::RowMajor> weights_;  ///< W (n x regions): w_ik
  Eigen::VectorXd region_mass_;                           ///< M_k = sum_i m_i w_ik
};

}  // namespace unfold
