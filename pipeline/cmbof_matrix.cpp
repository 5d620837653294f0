#include "pipeline/cmbof_matrix.h"

#include <exception>

#include "core/errors.h"
#include "metrics/ort_dissimilarity.h"
#include "pipeline/cmbof_vocabulary.h"
#include "pipeline/similarity_blocks.h"

namespace unfold {

Eigen::MatrixXd cmbof_matrix(const std::vector<SurfaceMesh>& shapes, const CmbofOptions& options) {
  if (shapes.size() < 2) throw UsageError("CMBOF matrix: at least 2 shapes are needed");
  std::vector<RetrievalDescriptor> d(shapes.size());
  std::vector<std::exception_ptr> errors(shapes.size());
#pragma omp parallel for schedule(dynamic)
  for (size_t i = 0; i < shapes.size(); ++i) {
    try {
      const Eigen::MatrixX3i F = triangulate_faces(shapes[i]);
      d[i].cmbof = cmbof_features(ort_normalise(shapes[i].V, F), F, options);
    } catch (...) {
      errors[i] = std::current_exception();
    }
  }
  for (const auto& e : errors)
    if (e) std::rethrow_exception(e);
  std::vector<const CmbofFeatures*> features;
  for (const auto& descriptor : d) features.push_back(&descriptor.cmbof);
  const Eigen::MatrixXf vocabulary = cmbof_vocabulary(features, options);
  for (auto& descriptor : d)
    descriptor.cmbof_histograms = cmbof_histograms(descriptor.cmbof, vocabulary);
  RetrievalOptions retrieval;
  retrieval.cmbof = options;
  Eigen::MatrixXd D = similarity_block(d, RetrievalFramework::cmbof, 0, 1, retrieval);
  for (Eigen::Index i = 0; i < D.rows(); ++i) {
    D(i, i) = 0;
    for (Eigen::Index j = 0; j < i; ++j) D(i, j) = D(j, i);
  }
  return D;
}

}  // namespace unfold
