// One rotation per vertex: the R_i of the rigidity term and of the local step.
#pragma once

#include <Eigen/Core>
#include <vector>

namespace unfold {

using Rotations = std::vector<Eigen::Matrix3d>;

}  // namespace unfold
