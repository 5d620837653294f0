// lambda_2 of the graph Laplacian (the Fiedler value): it sets the scale of
// beta, since the unfolding energy is bounded below only for (beta+1) lambda_2 > n.
#pragma once

#include <Eigen/SparseCore>

#include "solvers/smoothed_aggregation.h"

namespace unfold {

/// Smallest non-zero eigenvalue of a connected graph's Laplacian, by
/// shift-invert Lanczos (Spectra) on the complement of the constant vector.
/// With masses, of the generalized problem L x = lambda diag(masses) x (on the
/// masses-weighted complement of 1): what bounds the mass-weighted stretch term.
/// @param L      symmetric graph Laplacian of a connected graph (n >= 2)
/// @param masses empty, or n positive vertex masses
/// @throws NumericalError if the eigen-solver does not converge
/// @throws UsageError if masses has the wrong size or a mass is not positive
double fiedler_value(const Eigen::SparseMatrix<double>& L,
                     const Eigen::VectorXd& masses = Eigen::VectorXd());

/// lambda_2 and its eigenvector, in the symmetric form's coordinates (M^{1/2} x).
struct FiedlerPair {
  double value = 0;
  Eigen::VectorXd vector;
};

/// The same as fiedler_value, with the eigenvector; from `start`, when given, the
/// vector of a problem near this one (the same graph reweighted: soft joints): the
/// Lanczos run is then shorter (11 solves instead of 21 on david0's surface).
/// @param start empty, or one entry per vertex
/// @throws as fiedler_value, and UsageError if start has the wrong size
FiedlerPair fiedler_pair(const Eigen::SparseMatrix<double>& L,
                         const Eigen::VectorXd& masses = Eigen::VectorXd(),
                         const Eigen::VectorXd& start = Eigen::VectorXd());

/// The same by LOBPCG preconditioned with an AMG hierarchy of L (solvers/lobpcg.h):
/// no factorization, near-linear in n; relative accuracy about 1e-12. Graphs of
/// fewer than 100 vertices go to the direct overload.
/// @throws NumericalError if LOBPCG does not converge
double fiedler_value(const Eigen::SparseMatrix<double>& L, const AmgData& amg,
                     const Eigen::VectorXd& masses = Eigen::VectorXd());

}  // namespace unfold
