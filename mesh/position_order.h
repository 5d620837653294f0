// Vertices ordered by position, so that vertices at one position are found
// next to each other (duplicates in real meshes: merged or separated by callers).
#pragma once

#include <Eigen/Core>
#include <vector>

namespace unfold {

/// The indices 0..n-1 of V's rows sorted by position (x, then y, then z),
/// ties by index: the vertices at one position are consecutive, lowest index first.
std::vector<int> position_order(const Eigen::MatrixX3d& V);

}  // namespace unfold
