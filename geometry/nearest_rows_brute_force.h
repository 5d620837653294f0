// Exact nearest neighbours in tens of dimensions (a spectral embedding), where
// space-partitioning trees do not help: every distance, computed in tiles.
#pragma once

#include <Eigen/Core>

namespace unfold {

/// The nearest row of `database` for every row of `queries` (Euclidean; of
/// rows at one distance, the first). Single precision, in tiles that stay in
/// cache, on every OpenMP thread, with the widest vector instructions the
/// processor has (the same result on any of them up to rounding ties).
/// @param queries m x k
/// @param database n x k, n >= 1
/// @return m indices into database's rows
/// @throws UsageError if the column counts differ or database is empty
Eigen::VectorXi nearest_rows_brute_force(const Eigen::MatrixXf& queries,
                                         const Eigen::MatrixXf& database);

/// The vector instructions a scan can use; nearest_rows_brute_force uses the
/// widest the processor has.
enum class VectorInstructions { baseline, avx2, avx512 };

/// Whether this processor (and build) can run `instructions`.
bool supports(VectorInstructions instructions);

/// nearest_rows_brute_force with the given instructions (to test each one).
/// @throws UsageError as nearest_rows_brute_force, or if !supports(instructions)
Eigen::VectorXi nearest_rows_brute_force(const Eigen::MatrixXf& queries,
                                         const Eigen::MatrixXf& database,
                                         VectorInstructions instructions);

}  // namespace unfold
