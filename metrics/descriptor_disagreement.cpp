#include "metrics/descriptor_disagreement.h"

#include "core/errors.h"

namespace unfold {

double descriptor_disagreement(const Eigen::MatrixXd& source_descriptors,
                               const Eigen::MatrixXd& target_descriptors,
                               const Eigen::VectorXd& source_masses, const std::vector<int>& rows,
                               const Eigen::VectorXi& map) {
  if (rows.empty() || Eigen::Index(rows.size()) != map.size() ||
      source_descriptors.cols() != target_descriptors.cols() ||
      source_masses.size() != source_descriptors.rows())
    throw UsageError("descriptor_disagreement: sizes do not fit");
  double sum = 0, mass = 0;
  for (size_t r = 0; r < rows.size(); ++r) {
    const int i = rows[r], j = map(Eigen::Index(r));
    if (i < 0 || i >= source_descriptors.rows() || j < 0 || j >= target_descriptors.rows())
      throw UsageError("descriptor_disagreement: a vertex id is out of range");
    sum += source_masses(i) * (source_descriptors.row(i) - target_descriptors.row(j)).lpNorm<1>();
    mass += source_masses(i);
  }
  return sum / mass;
}

}  // namespace unfold
