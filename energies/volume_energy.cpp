#include "energies/volume_energy.h"

#include <Eigen/Geometry>
#include <cmath>

#include "energies/residual_sum.h"
#include "mesh/tet_volumes.h"

namespace unfold {

VolumeEnergy::VolumeEnergy(const Eigen::MatrixX3d& rest, const Eigen::MatrixX4i& T, double weight)
    : EnergyTerm(weight, true),
      rest_(rest),
      T_(T),
      rest_volume_(tet_volumes(rest, T)),
      edge_scale_(T.rows()),
      reference_volume_(T.rows()) {
  static const int edges[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
  for (Eigen::Index t = 0; t < T.rows(); ++t) {
    double sum = 0;
    for (const auto& e : edges) sum += (rest.row(T(t, e[0])) - rest.row(T(t, e[1]))).squaredNorm();
    edge_scale_[t] = std::sqrt(sum / 6.0);
    const double floor = kMinRestVolume * std::pow(edge_scale_[t], 3);
    const double v0 = rest_volume_[t];
    reference_volume_[t] = std::abs(v0) >= floor ? v0 : std::copysign(floor, v0);
  }
}

double VolumeEnergy::add_residuals(const Eigen::MatrixX3d& /*Q*/, const Rotations& /*R*/,
                                   ResidualSum* sum) const {
  double energy = 0;
  for (Eigen::Index t = 0; t < T_.rows(); ++t)
    energy += sum->add<1, 4>(VolumeResidual(rest_volume_[t], reference_volume_[t], edge_scale_[t]),
                             {T_(t, 0), T_(t, 1), T_(t, 2), T_(t, 3)});
  return energy;
}

void VolumeEnergy::add_preconditioner(double scale, std::vector<Eigen::Triplet<double>>* H) const {
  for (Eigen::Index t = 0; t < T_.rows(); ++t) {
    // dV/dq_a = (1/6) (q_c - q_b) x (q_d - q_b) for the face opposite a, oriented.
    Eigen::Matrix<double, 4, 3> g;
    const int v[4] = {T_(t, 0), T_(t, 1), T_(t, 2), T_(t, 3)};
    const auto p = [&](int k) { return Eigen::Vector3d(rest_.row(v[k])); };
    g.row(0) = (p(3) - p(1)).cross(p(2) - p(1)).transpose() / 6.0;
    g.row(1) = (p(2) - p(0)).cross(p(3) - p(0)).transpose() / 6.0;
    g.row(2) = (p(3) - p(0)).cross(p(1) - p(0)).transpose() / 6.0;
    g.row(3) = (p(1) - p(0)).cross(p(2) - p(0)).transpose() / 6.0;
    const double w = 2.0 * scale * std::pow(edge_scale_[t] / reference_volume_[t], 2) / 3.0;
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b) H->emplace_back(v[a], v[b], w * g.row(a).dot(g.row(b)));
  }
}

}  // namespace unfold
