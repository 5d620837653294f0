// Soft joints (docs/method.md, soft joints): where a solution's rotation field
// turns fast along an edge, the input bends there (a joint). Softening those
// edges' ARAP weights and solving again lets the joints straighten as far as
// the stretch term asks, however bent they were in the input, while the limbs
// between them stay rigid: the canonical limb directions depend less on the
// input's joint angles and on how the surface is meshed.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "mesh/edge_graph.h"

namespace unfold {

struct SoftenOptions {
  /// an edge's factor is 1 / (1 + (k / (scale * median k))^2), k the turn of the
  /// solution's rotation field per unit rest length along it; 0: off (the paper)
  double scale = 0;
  double floor = 0.4;  ///< no factor below this, in (0, 1]: a soft edge never lets go
  /// the second solve's change from the first kept at the scale of limbs
  /// (solvers/filter_change.h): its rotations filtered at this length, in units
  /// of sqrt(surface area); 0: whole
  double filter = 0;
  /// ... and the rest of it (stretch) at this length; 0: whole
  double filter_stretch = 0;
  /// the relative energy change that ends the second solve; 0: cascade.epsilon.
  /// With the filter its fine scale is dropped anyway, so it may stop sooner.
  double epsilon = 0;
};

/// Per graph edge ij, the factor its ARAP weight is multiplied by:
/// max(floor, 1 / (1 + (k_ij / (scale * median_e k_e))^2)), where
/// k_ij = angle(R_i^T R_j) / |p_i - p_j| and R_i is vertex i's best rotation
/// from P to Q over its edges (uniform weights). Scale-free: the same for any
/// scaling of P and Q, and k's unit cancels in the ratio to its median. Where
/// the median is 0 (more than half the edges do not turn) or no two neighbours'
/// rotations differ by 10^-6 radians (Q a rigid motion of P), every factor is 1.
/// @param graph   the solve's edge graph (n vertices)
/// @param P       rest positions, n x 3, no two neighbours at one position
/// @param Q       a solution, n x 3
/// @param options scale > 0, floor in (0, 1]
/// @returns one factor per graph edge, in [floor, 1]
/// @throws UsageError if the sizes disagree or scale, floor are out of range
std::vector<double> soft_joint_factors(const EdgeGraph& graph, const Eigen::MatrixX3d& P,
                                       const Eigen::MatrixX3d& Q, const SoftenOptions& options);

}  // namespace unfold
