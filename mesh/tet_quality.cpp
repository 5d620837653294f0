#include "mesh/tet_quality.h"

#include <cmath>

#include "mesh/tet_volumes.h"

namespace unfold {

Eigen::VectorXd tet_quality(const Eigen::MatrixX3d& V, const Eigen::MatrixX4i& T) {
  const Eigen::VectorXd volume = tet_volumes(V, T);
  Eigen::VectorXd q(T.rows());
  for (Eigen::Index t = 0; t < T.rows(); ++t) {
    double squares = 0;
    for (int a = 0; a < 4; ++a)
      for (int b = a + 1; b < 4; ++b) squares += (V.row(T(t, a)) - V.row(T(t, b))).squaredNorm();
    const double l = std::sqrt(squares / 6);
    q[t] = l > 0 ? 6 * std::sqrt(2.0) * std::abs(volume[t]) / (l * l * l) : 0.0;
  }
  return q;
}

}  // namespace unfold
