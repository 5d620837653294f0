#include "energies/volume_energy.h"

#include "energies/jet_evaluation.h"
#include "energies/row_major.h"
#include "mesh/tet_volumes.h"

namespace unfold {

VolumeEnergy::VolumeEnergy(const Eigen::MatrixX3d& rest, const Eigen::MatrixX4i& T, double weight)
    : EnergyTerm(weight, true), T_(T), rest_volume_(tet_volumes(rest, T)), edge_scale_(T.rows()) {
  static const int edges[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
  for (Eigen::Index t = 0; t < T.rows(); ++t) {
    double sum = 0;
    for (const auto& e : edges) sum += (rest.row(T(t, e[0])) - rest.row(T(t, e[1]))).squaredNorm();
    edge_scale_[t] = std::sqrt(sum / 6.0);
  }
}

double VolumeEnergy::evaluate(const Eigen::MatrixX3d& Q, const Rotations& /*R*/, double scale,
                              Eigen::MatrixX3d* grad) const {
  const RowMatrixX3d q = Q;
  RowMatrixX3d g;
  if (grad) g.setZero(Q.rows(), 3);
  auto at = [&](int v) { return grad ? g.data() + 3 * v : nullptr; };
  double energy = 0;
  for (Eigen::Index t = 0; t < T_.rows(); ++t) {
    const int a = T_(t, 0), b = T_(t, 1), c = T_(t, 2), d = T_(t, 3);
    const std::array<double*, 4> gt = {at(a), at(b), at(c), at(d)};
    energy +=
        squared_norm<1, 4>(VolumeResidual(rest_volume_[t], edge_scale_[t]),
                           {q.row(a).data(), q.row(b).data(), q.row(c).data(), q.row(d).data()},
                           scale, grad ? &gt : nullptr);
  }
  if (grad) *grad += g;
  return energy;
}

}  // namespace unfold
