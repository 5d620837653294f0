#include "solvers/laplace_beltrami_basis.h"

#include <Spectra/SymEigsShiftSolver.h>

#include <algorithm>
#include <numeric>
#include <string>

#include "core/errors.h"
#include "mesh/cotangent_laplacian.h"
#include "mesh/lumped_masses.h"
#include "solvers/mass_shift_invert.h"

namespace unfold {

LaplaceBeltramiBasis laplace_beltrami_basis(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F,
                                            int count) {
  const int n = int(V.rows());
  if (count < 1 || count >= n)
    throw UsageError("laplace_beltrami_basis: count " + std::to_string(count) + " must be in [1, " +
                     std::to_string(n - 1) + "]");
  const Eigen::SparseMatrix<double> W = cotangent_laplacian(V, F);
  LaplaceBeltramiBasis basis;
  basis.masses = lumped_masses(V, F);
  // Below the zero eigenvalue by a small fraction of the operator's scale.
  const double sigma = -1e-8 * W.diagonal().maxCoeff() / basis.masses.mean();
  MassShiftInvert op(W, basis.masses, false, "the shifted cotangent Laplacian");
  const int ncv = std::min(n, std::max(2 * count + 1, count + 20));
  Spectra::SymEigsShiftSolver<MassShiftInvert> eigs(op, count, ncv, sigma);
  eigs.init();
  eigs.compute(Spectra::SortRule::LargestMagn, 1000, 1e-8);
  if (eigs.info() != Spectra::CompInfo::Successful)
    throw NumericalError("the Laplace-Beltrami eigensolver did not converge (" +
                         std::to_string(count) + " eigenpairs of " + std::to_string(n) +
                         " vertices)");
  const Eigen::VectorXd values = eigs.eigenvalues();
  const Eigen::MatrixXd vectors = eigs.eigenvectors();
  std::vector<int> order(count);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int a, int b) { return values(a) < values(b); });
  basis.values.resize(count);
  basis.phi.resize(n, count);
  const Eigen::VectorXd inverse_sqrt = basis.masses.cwiseSqrt().cwiseInverse();
  for (int k = 0; k < count; ++k) {
    basis.values(k) = values(order[k]);
    // Back from the symmetric form: phi = M^{-1/2} u is M-orthonormal.
    basis.phi.col(k) = inverse_sqrt.cwiseProduct(vectors.col(order[k]));
  }
  return basis;
}

}  // namespace unfold
