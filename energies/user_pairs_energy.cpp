#include "energies/user_pairs_energy.h"

#include "energies/jet_evaluation.h"
#include "geometry/row_major.h"

namespace unfold {

double UserPairsEnergy::evaluate(const Eigen::MatrixX3d& Q, const Rotations& /*R*/, double scale,
                                 Eigen::MatrixX3d* grad) const {
  ResidualSum sum(Q, scale, grad);
  double energy = 0;
  for (const UserPair& p : pairs_) energy += sum.add<3, 2>(UserPairResidual(p.t), {p.i, p.j});
  sum.finish();
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

double UserPairsEnergy::constant(const Rotations& /*R*/) const {
  double c = 0;
  for (const UserPair& p : pairs_) c += p.t.squaredNorm();
  return c;
}

}  // namespace unfold
