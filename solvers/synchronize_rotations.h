// Rotation synchronization: from measured relative rotations between pairs of
// a collection, one rotation per member that explains them all at once. A
// relative rotation that a pair's own alignment got wrong disagrees with the
// ones its cycles through the other members imply (unfold_match's batch uses
// this to correct a body placed turned round, docs/results/correspondence.md).
#pragma once

#include <Eigen/Core>
#include <vector>

namespace unfold {

/// A measured relative rotation: member `to` ~ R * member `from` (in each
/// member's own frame).
struct RelativeRotation {
  int from = 0, to = 0;
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
};

struct SynchronizedRotations {
  /// per member its rotation G into a common frame (G_to * R ~ G_from); one
  /// common frame per connected component of the pairs
  std::vector<Eigen::Matrix3d> global;
  /// per measured rotation the one the synchronized rotations imply,
  /// G_to^T G_from; the measured one itself where no cycle constrains it
  std::vector<Eigen::Matrix3d> implied;
  /// per measured rotation the angle (degrees) between it and `implied`
  std::vector<double> disagreement_degrees;
};

/// Spectral synchronization (the three leading eigenvectors of the block
/// matrix of relative rotations, each block projected onto a rotation), per
/// connected component, reweighted `rounds` times so that measurements far
/// from the current solution count little (robust to a minority of wrong
/// ones). Components without a cycle keep their measurements.
/// @param num_members members, numbered 0 .. num_members - 1
/// @param measured the relative rotations; at most one per unordered pair
/// @throws UsageError for a member out of range, a pair measured twice or a
///         member paired with itself
SynchronizedRotations synchronize_rotations(int num_members,
                                            const std::vector<RelativeRotation>& measured,
                                            int rounds = 3);

}  // namespace unfold
