// The spread by distances (stretch.distance, docs/method.md, spread by
// distances): a second spread term beside the squared one,
//   e_d(Q) = - sum_{a<b} M_a M_b |c_a - c_b|,
// over clusters a of the rest shape (energies/distance_clusters.h), c_a =
// sum_{i in a} m_i q_i / M_a their mass-weighted centroids and M_a their
// masses. The squared spread, sum of m_i m_j |q_i - q_j|^2, grows fastest by
// moving mass away from the one centroid, so it lines limbs up along the body
// (a biped's arms up beside its head); unsquared, a pair gains as much from
// parting when near as when far, so parts beside each other push apart: limbs
// splay. Over clusters, not vertices, the sum costs O(clusters^2) a call
// whatever the mesh's size, and it is exact for what it is (no far-field
// approximation): the gradient is the true one.
//
// |d| is convex, so e_d is concave: its tangent plane at Q majorizes it
// (energies/concave_term.h), -|d'| <= -u.d' with u = d / |d| the pair's
// direction at Q; the global step takes that tangent, the right-hand side
// gaining (scale / 2) m_i F_a for i in cluster a, F_a = sum_b M_b u_ab. It adds
// nothing to the matrix and grows linearly, so the boundedness bound (set by
// the squared spread against ARAP) is unchanged.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "energies/concave_term.h"
#include "energies/energy_term.h"

namespace unfold {

class DistanceSpreadEnergy : public EnergyTerm, public ConcaveTerm {
 public:
  /// @param cluster_of each vertex's cluster, in [0, clusters)
  /// @param masses     vertex masses (positive); empty: every vertex 1
  /// @param weight     kappa (not scaled by beta, as the squared spread)
  /// @throws UsageError if masses has the wrong size, a mass is not positive and
  ///         finite, a cluster index is out of range or a cluster is empty
  DistanceSpreadEnergy(std::vector<int> cluster_of, int clusters, Eigen::VectorXd masses,
                       double weight);
  std::string name() const override { return "stretch_distance"; }
  /// Not a sum of squares: refused (UsageError); evaluate() gives the value and gradient.
  double add_residuals(const Eigen::MatrixX3d& Q, const Rotations& R,
                       ResidualSum* sum) const override;
  double evaluate(const Eigen::MatrixX3d& Q, const Rotations& R, double scale,
                  Eigen::MatrixX3d* grad) const override;
  void add_tangent(const Eigen::MatrixX3d& Q, double scale, Eigen::MatrixX3d* B) const override;
  int clusters() const { return int(cluster_mass_.size()); }

 private:
  /// The clusters' centroids at Q and, per cluster, F_a = sum_b M_b u_ab; returns
  /// e_d(Q). Each cluster's sums in a fixed order: the same whatever the threads.
  double field(const Eigen::MatrixX3d& Q, Eigen::MatrixX3d* F) const;

  std::vector<int> cluster_of_;
  Eigen::VectorXd masses_;        ///< m_i
  Eigen::VectorXd cluster_mass_;  ///< M_a
};

/// kappa for stretch.distance = share: share times the paper's squared spread's
/// pull (stretch.weight 1) on a vertex at the rest shape's radius, 4 M r (its
/// gradient 4 M m_i (q_i - c)), over the most the distance spread's can be, M:
/// kappa = 4 share r, r the masses' root-mean-square distance from their
/// centroid. Relative to the shape's size, so every meshing and scale of a
/// shape gets the same balance; apart from stretch.weight, which sets the
/// squared spread alone.
/// @param masses empty: every vertex 1
double distance_spread_weight(const Eigen::MatrixX3d& V, const Eigen::VectorXd& masses,
                              double share);

}  // namespace unfold
