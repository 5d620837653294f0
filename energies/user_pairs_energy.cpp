#include "energies/user_pairs_energy.h"

#include "energies/jet_evaluation.h"
#include "energies/row_major.h"

namespace unfold {

double UserPairsEnergy::evaluate(const Eigen::MatrixX3d& Q, const Rotations& /*R*/, double scale,
                                 Eigen::MatrixX3d* grad) const {
  const RowMatrixX3d q = Q;
  RowMatrixX3d g;
  if (grad) g.setZero(Q.rows(), 3);
  auto at = [&](int v) { return grad ? g.data() + 3 * v : nullptr; };
  double energy = 0;
  for (const UserPair& p : pairs_) {
    const std::array<double*, 2> gij = {at(p.i), at(p.j)};
    energy += squared_norm<3, 2>(UserPairResidual(p.t), {q.row(p.i).data(), q.row(p.j).data()},
                                 scale, grad ? &gij : nullptr);
  }
  if (grad) *grad += g;
  return energy;
}

void UserPairsEnergy::add_hessian(double scale, std::vector<Eigen::Triplet<double>>* H) const {
  for (const UserPair& p : pairs_) {
    H->emplace_back(p.i, p.i, scale);
    H->emplace_back(p.j, p.j, scale);
    H->emplace_back(p.i, p.j, -scale);
    H->emplace_back(p.j, p.i, -scale);
  }
}

void UserPairsEnergy::add_linear(const Rotations& /*R*/, double scale, Eigen::MatrixX3d* B) const {
  for (const UserPair& p : pairs_) {
    B->row(p.i) += scale * p.t.transpose();
    B->row(p.j) -= scale * p.t.transpose();
  }
}

}  // namespace unfold
