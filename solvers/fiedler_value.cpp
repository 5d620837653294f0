#include "solvers/fiedler_value.h"

#include <Spectra/SymEigsShiftSolver.h>

#include "core/errors.h"
#include "core/progress.h"
#include "solvers/lobpcg.h"
#include "solvers/mass_shift_invert.h"

namespace unfold {
namespace {

void check_masses(const Eigen::SparseMatrix<double>& L, const Eigen::VectorXd& masses) {
  if (masses.size() != 0 && (masses.size() != L.rows() || !(masses.minCoeff() > 0)))
    throw UsageError("lambda_2: the masses must be empty or one positive mass per vertex");
}

}  // namespace

double fiedler_value(const Eigen::SparseMatrix<double>& L, const Eigen::VectorXd& masses) {
  return fiedler_pair(L, masses).value;
}

FiedlerPair fiedler_pair(const Eigen::SparseMatrix<double>& L, const Eigen::VectorXd& masses,
                         const Eigen::VectorXd& start) {
  const Eigen::Index n = L.rows();
  if (n < 2) throw NumericalError("lambda_2 needs a graph of at least 2 vertices");
  check_masses(L, masses);
  if (start.size() != 0 && start.size() != n)
    throw UsageError("lambda_2: the start vector must be empty or one entry per vertex");
  report_stage("lambda_2 of " + std::to_string(n) + " vertices");
  // A shift far below lambda_2 (masses scale the eigenvalues by 1 / their mean).
  const double sigma = -1e-8 * L.diagonal().maxCoeff() / (masses.size() ? masses.mean() : 1.0);
  // The zero mode deflated: it never competes with lambda_2.
  MassShiftInvert op(L, masses, true, "the shifted Laplacian for lambda_2");
  // From a start near the answer a short Lanczos run converges (one restart at most).
  const Eigen::Index ncv = std::min<Eigen::Index>(n, start.size() ? 10 : 20);
  Spectra::SymEigsShiftSolver<MassShiftInvert> eigs(op, 1, ncv, sigma);
  if (start.size())
    eigs.init(start.data());
  else
    eigs.init();
  eigs.compute(Spectra::SortRule::LargestMagn, 1000, 1e-10);
  if (eigs.info() != Spectra::CompInfo::Successful)
    throw NumericalError("the eigen-solver for lambda_2 did not converge");
  return {eigs.eigenvalues()(0), eigs.eigenvectors().col(0)};
}

double fiedler_value(const Eigen::SparseMatrix<double>& L, const AmgData& amg,
                     const Eigen::VectorXd& masses) {
  if (L.rows() < 100) return fiedler_value(L, masses);
  report_stage("lambda_2 of " + std::to_string(L.rows()) + " vertices (LOBPCG)");
  const LobpcgResult r = lobpcg_smallest(CsrView::of_symmetric(L), amg, {}, masses);
  if (!r.converged)
    throw NumericalError("LOBPCG for lambda_2 did not converge (relative residual " +
                         std::to_string(r.relative_residual) + " after " +
                         std::to_string(r.iterations) + " iterations)");
  report_detail([&](std::ostream& line) {
    line << "lambda_2 = " << r.values[0] << ": LOBPCG, " << r.iterations << " iterations";
  });
  return r.values[0];
}

}  // namespace unfold
