// User control (paper Eq. 11): pairs (i, j) whose difference q_i - q_j should
// become a given vector t_ij,
//   e_u(Q) = sum_{(i,j) in U} |q_i - q_j - t_ij|^2,
// weighted gamma = (weight) * beta (the paper sets gamma = beta).
// Quadratic: H = L_U (the pairs' graph Laplacian), B = K (Eq. 13).
#pragma once

#include <ceres/autodiff_cost_function.h>

#include <Eigen/Core>
#include <vector>

#include "energies/energy_term.h"

namespace unfold {

struct UserPair {
  int i = 0, j = 0;
  Eigen::Vector3d t = Eigen::Vector3d::Zero();  ///< requested q_i - q_j
};

/// q_i - q_j - t for one pair.
struct UserPairResidual {
  explicit UserPairResidual(const Eigen::Vector3d& target) : t(target) {}
  template <typename T>
  bool operator()(const T* qi, const T* qj, T* r) const {
    for (int k = 0; k < 3; ++k) r[k] = qi[k] - qj[k] - T(t[k]);
    return true;
  }
  static ceres::CostFunction* Create(const Eigen::Vector3d& target) {
    return new ceres::AutoDiffCostFunction<UserPairResidual, 3, 3, 3>(new UserPairResidual(target));
  }
  Eigen::Vector3d t;
};

class UserPairsEnergy : public EnergyTerm {
 public:
  /// @param pairs  vertex index pairs in [0, n) with their target vectors
  /// @param gamma  weight relative to beta
  UserPairsEnergy(std::vector<UserPair> pairs, double gamma)
      : EnergyTerm(gamma, true), pairs_(std::move(pairs)) {}
  std::string name() const override { return "user_pairs"; }
  double evaluate(const Eigen::MatrixX3d& Q, const Rotations& R, double scale,
                  Eigen::MatrixX3d* grad) const override;
  bool quadratic() const override { return true; }
  void add_hessian(double scale, std::vector<Eigen::Triplet<double>>* H) const override;
  void add_linear(const Rotations& R, double scale, Eigen::MatrixX3d* B) const override;
  double constant(const Rotations& R) const override;

 private:
  std::vector<UserPair> pairs_;
};

}  // namespace unfold
