#include "energies/distance_spread_energy.h"

#include <cmath>
#include <string>
#include <utility>

#include "core/errors.h"

namespace unfold {

DistanceSpreadEnergy::DistanceSpreadEnergy(std::vector<int> cluster_of, int clusters,
                                           Eigen::VectorXd masses, double weight)
    : EnergyTerm(weight, false), cluster_of_(std::move(cluster_of)) {
  const int n = int(cluster_of_.size());
  if (masses.size() == 0) masses = Eigen::VectorXd::Ones(n);
  if (masses.size() != n)
    throw UsageError("stretch.distance: " + std::to_string(masses.size()) + " masses for " +
                     std::to_string(n) + " vertices");
  if (!(masses.array() > 0).all() || !masses.allFinite())
    throw UsageError("stretch.distance: every vertex mass must be positive and finite");
  masses_ = std::move(masses);
  cluster_mass_.setZero(clusters);
  for (int i = 0; i < n; ++i) {
    const int a = cluster_of_[size_t(i)];
    if (a < 0 || a >= clusters)
      throw UsageError("stretch.distance: vertex " + std::to_string(i) + "'s cluster " +
                       std::to_string(a) + " is not in [0, " + std::to_string(clusters) + ")");
    cluster_mass_[a] += masses_[i];
  }
  for (int a = 0; a < clusters; ++a)
    if (!(cluster_mass_[a] > 0))
      throw UsageError("stretch.distance: cluster " + std::to_string(a) + " has no vertex");
}

double DistanceSpreadEnergy::add_residuals(const Eigen::MatrixX3d& /*Q*/, const Rotations& /*R*/,
                                           ResidualSum* /*sum*/) const {
  throw UsageError(
      "the stretch_distance term is not a sum of squared residuals: it has no residual blocks");
}

namespace {

// One cluster's pull, F_a = sum_b M_b (c_a - c_b) / |c_a - c_b|, and its reach,
// sum_b M_b |c_a - c_b|, over the centroids in columns (x, y, z): a lane loop
// that vectorizes (sqrt free of errno, CMakeLists.txt), itself left out (r = 0).
__attribute__((target_clones("avx2", "default"))) void pull_of(int a, int k, const double* x,
                                                               const double* y, const double* z,
                                                               const double* mass, double* f) {
  const double xa = x[a], ya = y[a], za = z[a];
  double fx = 0, fy = 0, fz = 0, reach = 0;
#pragma omp simd reduction(+ : fx, fy, fz, reach)
  for (int b = 0; b < k; ++b) {
    const double dx = xa - x[b], dy = ya - y[b], dz = za - z[b];
    const double r = std::sqrt(dx * dx + dy * dy + dz * dz);
    const double w = r > 0 ? mass[b] / r : 0.0;
    fx += w * dx;
    fy += w * dy;
    fz += w * dz;
    reach += mass[b] * r;
  }
  f[0] = fx;
  f[1] = fy;
  f[2] = fz;
  f[3] = reach;
}

}  // namespace

double DistanceSpreadEnergy::field(const Eigen::MatrixX3d& Q, Eigen::MatrixX3d* F) const {
  const int k = clusters();
  Eigen::MatrixX3d C = Eigen::MatrixX3d::Zero(k, 3);  // columns x, y, z: the lanes' arrays
  for (size_t i = 0; i < cluster_of_.size(); ++i)
    C.row(cluster_of_[i]) += masses_[Eigen::Index(i)] * Q.row(Eigen::Index(i));
  C.array().colwise() /= cluster_mass_.array();
  Eigen::Matrix<double, Eigen::Dynamic, 4, Eigen::RowMajor> pull(k, 4);
#pragma omp parallel for schedule(static) if (k >= 256)
  for (int a = 0; a < k; ++a)
    pull_of(a, k, C.col(0).data(), C.col(1).data(), C.col(2).data(), cluster_mass_.data(),
            pull.row(a).data());
  *F = pull.leftCols<3>();
  return -0.5 * cluster_mass_.dot(pull.col(3));
}

double DistanceSpreadEnergy::evaluate(const Eigen::MatrixX3d& Q, const Rotations& /*R*/,
                                      double scale, Eigen::MatrixX3d* grad) const {
  Eigen::MatrixX3d F;
  const double value = field(Q, &F);
  if (grad)
    for (size_t i = 0; i < cluster_of_.size(); ++i)
      grad->row(Eigen::Index(i)) -= scale * masses_[Eigen::Index(i)] * F.row(cluster_of_[i]);
  return scale * value;
}

void DistanceSpreadEnergy::add_tangent(const Eigen::MatrixX3d& Q, double scale,
                                       Eigen::MatrixX3d* B) const {
  Eigen::MatrixX3d F;
  field(Q, &F);
  for (size_t i = 0; i < cluster_of_.size(); ++i)
    B->row(Eigen::Index(i)) += 0.5 * scale * masses_[Eigen::Index(i)] * F.row(cluster_of_[i]);
}

double distance_spread_weight(const Eigen::MatrixX3d& V, const Eigen::VectorXd& masses,
                              double share) {
  const Eigen::VectorXd m = masses.size() ? masses : Eigen::VectorXd::Ones(V.rows());
  const Eigen::RowVector3d c = (m.transpose() * V) / m.sum();
  const double r2 = (m.array() * (V.rowwise() - c).rowwise().squaredNorm().array()).sum() / m.sum();
  return 4 * share * std::sqrt(r2);
}

}  // namespace unfold
