// The residual most terms are made of: the difference of two vertices' positions
// against a target vector,  r = q_i - q_j - t.  ARAP uses it with t the rotated
// rest edge, the user pairs with their requested offset, the stretch term's
// neighbour pairs with t = 0.
#pragma once

#include <Eigen/Core>

namespace unfold {

struct DifferenceResidual {
  explicit DifferenceResidual(const Eigen::Vector3d& target = Eigen::Vector3d::Zero())
      : t(target) {}
  template <typename T>
  bool operator()(const T* qi, const T* qj, T* r) const {
    for (int k = 0; k < 3; ++k) r[k] = qi[k] - qj[k] - T(t[k]);
    return true;
  }
  Eigen::Vector3d t;
};

}  // namespace unfold
