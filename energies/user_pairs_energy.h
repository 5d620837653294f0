// User control (paper Eq. 11): pairs (i, j) whose difference q_i - q_j should
// become a given vector t_ij,
//   e_u(Q) = sum_{(i,j) in U} |q_i - q_j - t_ij|^2,
// weighted gamma = (weight) * beta (the paper sets gamma = beta).
// Quadratic: H = L_U (the pairs' graph Laplacian), B = K (Eq. 13), c = sum |t|^2,
// all derived from the residuals (energies/quadratic_term.h).
#pragma once

#include <Eigen/Core>
#include <vector>

#include "energies/quadratic_term.h"

namespace unfold {

struct UserPair {
  int i = 0, j = 0;
  Eigen::Vector3d t = Eigen::Vector3d::Zero();  ///< requested q_i - q_j
};

class UserPairsEnergy : public QuadraticTerm {
 public:
  /// @param pairs        vertex index pairs in [0, num_vertices) with their target vectors
  /// @param num_vertices n
  /// @param gamma        weight relative to beta
  UserPairsEnergy(std::vector<UserPair> pairs, int num_vertices, double gamma)
      : QuadraticTerm(num_vertices, gamma, true), pairs_(std::move(pairs)) {}
  std::string name() const override { return "user_pairs"; }
  double add_residuals(const Eigen::MatrixX3d& Q, const Rotations& R,
                       ResidualSum* sum) const override;

 private:
  std::vector<UserPair> pairs_;
};

}  // namespace unfold
