// Reads user pair constraints (paper Eq. 11): vertex pairs (i, j) with the
// vector t_ij that q_i - q_j should become.
#pragma once

#include <string>
#include <vector>

#include "energies/user_pairs_energy.h"

namespace unfold {

/// Reads pairs from CSV (.csv/.txt: one "i, j, tx, ty, tz" per line; '#' starts a
/// comment; a header line of non-numbers is skipped) or YAML (.yaml/.yml: a list
/// of [i, j, tx, ty, tz]).
/// @param num_vertices vertex count of the surface the indices refer to
/// @throws InputError naming the file and line for unreadable files, malformed
///         lines, non-finite values, i == j, or an index outside [0, num_vertices)
std::vector<UserPair> read_user_pairs(const std::string& path, int num_vertices);

}  // namespace unfold
