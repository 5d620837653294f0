#include "mesh/lumped_masses.h"

#include <Eigen/Geometry>
#include <string>

#include "core/errors.h"
#include "mesh/tet_volumes.h"

namespace unfold {
namespace {

void require_positive(const Eigen::VectorXd& m, const char* what) {
  for (Eigen::Index i = 0; i < m.size(); ++i)
    if (!(m[i] > 0))
      throw InputError("vertex " + std::to_string(i) + " has no " + what +
                       " (in no element, or only in flat ones): no lumped mass");
}

}  // namespace

Eigen::VectorXd lumped_masses(const Eigen::MatrixX3d& V, const Eigen::MatrixX4i& T) {
  const Eigen::VectorXd volumes = tet_volumes(V, T).cwiseAbs();
  Eigen::VectorXd m = Eigen::VectorXd::Zero(V.rows());
  for (Eigen::Index t = 0; t < T.rows(); ++t)
    for (int k = 0; k < 4; ++k) m[T(t, k)] += volumes[t] / 4;
  require_positive(m, "volume");
  return m;
}

Eigen::VectorXd lumped_masses(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F) {
  Eigen::VectorXd m = Eigen::VectorXd::Zero(V.rows());
  for (Eigen::Index f = 0; f < F.rows(); ++f) {
    const Eigen::Vector3d a = V.row(F(f, 0)), b = V.row(F(f, 1)), c = V.row(F(f, 2));
    const double area = 0.5 * (b - a).cross(c - a).norm();
    for (int k = 0; k < 3; ++k) m[F(f, k)] += area / 3;
  }
  require_positive(m, "area");
  return m;
}

}  // namespace unfold
