#include "pipeline/convergence_csv.h"

#include <iomanip>
#include <ostream>

#include "core/atomic_file.h"

namespace unfold {

void write_convergence_csv(const std::string& path, const std::vector<IterationRecord>& history) {
  write_file_atomically(path, [&](std::ostream& out) {
    out << "iteration,cascade,beta,energy,edge_ratio\n" << std::setprecision(10);
    for (const IterationRecord& r : history)
      out << r.iteration << ',' << r.cascade << ',' << r.beta << ',' << r.energy << ','
          << r.edge_ratio << '\n';
  });
}

}  // namespace unfold
