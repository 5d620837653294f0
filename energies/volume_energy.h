// Optional volume preservation (DPMU-style): each tetrahedron's signed volume
// should keep its rest value,
//   e_v(Q) = sum_t l_t^2 (V_t(Q) / V_t(P) - 1)^2,
// with l_t^2 the tet's mean squared rest edge length, so the term has the units
// of the ARAP term and its weight is relative to beta like ARAP's. An inverted
// tetrahedron costs at least l_t^2. A rest tet flatter than kMinRestVolume l_t^3
// (a thousandth of a regular tet's volume; the robust route's carved Delaunay
// mesh has slivers down to 1e-16 l_t^3) is measured against that volume
// instead of its own: divided by its own, its term's curvature (and the
// preconditioner's) was so large that Ceres' first line search found no step.
// Not quadratic: only the Ceres backend minimises it.
#pragma once

#include <Eigen/Core>

#include "energies/energy_term.h"

namespace unfold {

/// Rest volumes below this times l_t^3 are measured against it (above).
inline constexpr double kMinRestVolume = 1e-4;

/// l (V(a, b, c, d) - V0) / Vref with V the signed volume; Vref = V0 unless V0
/// is below the floor (then the floor, with V0's sign).
struct VolumeResidual {
  VolumeResidual(double rest_volume, double reference_volume, double edge_scale)
      : v0(rest_volume), vref(reference_volume), l(edge_scale) {}
  template <typename T>
  bool operator()(const T* a, const T* b, const T* c, const T* d, T* r) const {
    T u[3], v[3], w[3];
    for (int k = 0; k < 3; ++k) {
      u[k] = b[k] - a[k];
      v[k] = c[k] - a[k];
      w[k] = d[k] - a[k];
    }
    const T volume = (u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) +
                      u[2] * (v[0] * w[1] - v[1] * w[0])) /
                     T(6.0);
    // V0 / Vref is exactly 1 for every tet above the floor.
    r[0] = T(l) * (volume / T(vref) - T(v0 / vref));
    return true;
  }
  double v0, vref, l;
};

class VolumeEnergy : public EnergyTerm {
 public:
  /// @param rest rest positions; T tetrahedra with non-zero rest volume
  VolumeEnergy(const Eigen::MatrixX3d& rest, const Eigen::MatrixX4i& T, double weight);
  std::string name() const override { return "volume"; }
  double add_residuals(const Eigen::MatrixX3d& Q, const Rotations& R,
                       ResidualSum* sum) const override;
  /// The Gauss-Newton Hessian at the rest shape, 2 sum_t (l_t / Vref_t)^2 g_t g_t^T
  /// (g_t = dV_t/dQ), averaged over the three coordinates.
  void add_preconditioner(double scale, std::vector<Eigen::Triplet<double>>* H) const override;

 private:
  Eigen::MatrixX3d rest_;
  Eigen::MatrixX4i T_;
  Eigen::VectorXd rest_volume_, edge_scale_, reference_volume_;
};

}  // namespace unfold
