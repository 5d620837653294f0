// How much a point-to-point map disagrees with per-vertex descriptors of the
// two shapes: what unfold_match's placement decision compares between a body
// placed the right way round and turned round (solvers/match_canonical_forms.h).
#pragma once

#include <Eigen/Core>
#include <vector>

namespace unfold {

/// sum_r m_r |D_s(rows[r]) - D_t(map[r])|_1 / sum_r m_r: the mass-weighted mean
/// L1 distance between each source row's descriptor and its image's.
/// @param source_descriptors n_s x d, target_descriptors n_t x d
/// @param source_masses n_s lumped masses (mesh/lumped_masses.h)
/// @param rows source vertices, map their target vertices (equal sizes)
/// @throws UsageError for sizes that differ, no row or an id out of range
double descriptor_disagreement(const Eigen::MatrixXd& source_descriptors,
                               const Eigen::MatrixXd& target_descriptors,
                               const Eigen::VectorXd& source_masses, const std::vector<int>& rows,
                               const Eigen::VectorXi& map);

}  // namespace unfold
