#include "solvers/woodbury_update.h"

#include <algorithm>

#include "core/errors.h"

namespace unfold {

void woodbury_precomputation(const SparseLdlt& ldlt, const Eigen::MatrixXd& U,
                             WoodburyUpdate* update) {
  update->U = U;
  const int n = int(U.rows()), k = int(U.cols());
  update->Z.resize(n, k);
  update->negative_eigenvalues = 0;
  if (k == 0) return;
  // The factor solves three right-hand sides at a time.
  Eigen::MatrixX3d b(n, 3), x;
  for (int first = 0; first < k; first += 3) {
    const int cols = std::min(3, k - first);
    b.setZero();
    b.leftCols(cols) = U.middleCols(first, cols);
    ldlt.solve(b, &x);
    update->Z.middleCols(first, cols) = x.leftCols(cols);
  }
  update->S.compute(Eigen::MatrixXd::Identity(k, k) + U.transpose() * update->Z);
  const Eigen::VectorXd d = update->S.vectorD();
  if (update->S.info() != Eigen::Success || !d.allFinite() || (d.array() == 0).any())
    throw NumericalError("the global matrix with the local spread's centroids is singular");
  update->negative_eigenvalues = int((d.array() < 0).count());
}

void woodbury_solve(const WoodburyUpdate& update, Eigen::MatrixX3d* x) {
  if (update.U.cols() == 0) return;
  *x -= update.Z * update.S.solve(Eigen::MatrixXd(update.U.transpose() * *x));
}

}  // namespace unfold
