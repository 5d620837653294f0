// The iteration history of a run as CSV, for plotting elsewhere.
#pragma once

#include <string>
#include <vector>

#include "solvers/cascade.h"

namespace unfold {

/// Writes "iteration,cascade,beta,energy,edge_ratio" and one row per record (atomically).
/// @throws OutputError if the file cannot be written
void write_convergence_csv(const std::string& path, const std::vector<IterationRecord>& history);

}  // namespace unfold
