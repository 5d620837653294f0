// lambda_2 of the graph Laplacian (the Fiedler value): it sets the scale of
// beta, since the unfolding energy is bounded below only for (beta+1) lambda_2 > n.
#pragma once

#include <Eigen/SparseCore>

namespace unfold {

/// Smallest non-zero eigenvalue of a connected graph's Laplacian, by
/// shift-invert Lanczos (Spectra) on the complement of the constant vector.
/// @param L symmetric graph Laplacian of a connected graph (n >= 2)
/// @throws NumericalError if the eigen-solver does not converge
double fiedler_value(const Eigen::SparseMatrix<double>& L);

}  // namespace unfold
