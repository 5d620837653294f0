#include "solvers/zoomout.h"

#include <algorithm>
#include <string>
#include <vector>

#include "core/errors.h"
#include "geometry/nearest_rows_brute_force.h"

namespace unfold {

namespace {

// Every (n / count)-th index of [0, n) (all of them when count is 0 or >= n).
std::vector<int> stride_sample(Eigen::Index n, int count) {
  std::vector<int> rows;
  if (count <= 0 || count >= n) {
    for (Eigen::Index i = 0; i < n; ++i) rows.push_back(int(i));
    return rows;
  }
  for (int k = 0; k < count; ++k) rows.push_back(int(double(k) * double(n) / count));
  return rows;
}

}  // namespace

Eigen::MatrixXd zoomout_functional_map(const LaplaceBeltramiBasis& source,
                                       const LaplaceBeltramiBasis& target,
                                       const Eigen::VectorXi& initial,
                                       const ZoomOutOptions& options) {
  if (options.start_size < 1 || options.step < 1 || options.final_size < options.start_size ||
      options.samples < 0)
    throw UsageError("zoomout: need 1 <= start_size <= final_size, step >= 1, samples >= 0");
  if (options.final_size > source.phi.cols() || options.final_size > target.phi.cols())
    throw UsageError("zoomout: final_size " + std::to_string(options.final_size) +
                     " exceeds a basis of " +
                     std::to_string(std::min(source.phi.cols(), target.phi.cols())));
  if (initial.size() != source.phi.rows() || source.masses.size() != source.phi.rows())
    throw UsageError("zoomout: the initial map has " + std::to_string(initial.size()) +
                     " entries for " + std::to_string(source.phi.rows()) + " source vertices");
  if (initial.size() > 0 && (initial.minCoeff() < 0 || initial.maxCoeff() >= target.phi.rows()))
    throw UsageError("zoomout: the initial map names a vertex outside the target");
  const std::vector<int> S = stride_sample(source.phi.rows(), options.samples);
  const std::vector<int> D = stride_sample(target.phi.rows(), options.samples);
  const Eigen::Index ns = Eigen::Index(S.size()), nd = Eigen::Index(D.size());
  // The sampled source rows, weighted so that their masses sum to the area.
  Eigen::MatrixXd source_rows(ns, source.phi.cols());
  Eigen::VectorXd weights(ns);
  for (Eigen::Index r = 0; r < ns; ++r) {
    source_rows.row(r) = source.phi.row(S[r]);
    weights(r) = source.masses(S[r]);
  }
  weights *= source.masses.sum() / weights.sum();
  Eigen::MatrixXd target_rows(nd, target.phi.cols());
  for (Eigen::Index r = 0; r < nd; ++r) target_rows.row(r) = target.phi.row(D[r]);
  Eigen::VectorXi sample_map(ns);  // sampled source vertex -> target vertex
  for (Eigen::Index r = 0; r < ns; ++r) sample_map(r) = initial(S[r]);
  for (int k = options.start_size;; k = std::min(k + options.step, options.final_size)) {
    Eigen::MatrixXd pulled(ns, k);
    for (Eigen::Index r = 0; r < ns; ++r) pulled.row(r) = target.phi.row(sample_map(r)).head(k);
    Eigen::MatrixXd C = (weights.asDiagonal() * source_rows.leftCols(k)).transpose() * pulled;
    if (k == options.final_size) return C;
    const Eigen::MatrixXf queries = source_rows.leftCols(k).cast<float>();
    const Eigen::MatrixXf database = (target_rows.leftCols(k) * C.transpose()).cast<float>();
    const Eigen::VectorXi nearest = nearest_rows_brute_force(queries, database);
    for (Eigen::Index r = 0; r < ns; ++r) sample_map(r) = D[nearest(r)];
  }
}

Eigen::VectorXi pointwise_map(const LaplaceBeltramiBasis& source,
                              const LaplaceBeltramiBasis& target, const Eigen::MatrixXd& C,
                              const std::vector<int>& rows) {
  const Eigen::Index k = C.rows();
  if (C.cols() != k || k > source.phi.cols() || k > target.phi.cols())
    throw UsageError("pointwise_map: a functional map of " + std::to_string(k) + " x " +
                     std::to_string(C.cols()) + " for bases of " +
                     std::to_string(std::min(source.phi.cols(), target.phi.cols())));
  const Eigen::MatrixXf database = (target.phi.leftCols(k) * C.transpose()).cast<float>();
  if (rows.empty()) return nearest_rows_brute_force(source.phi.leftCols(k).cast<float>(), database);
  Eigen::MatrixXf queries(Eigen::Index(rows.size()), k);
  for (size_t r = 0; r < rows.size(); ++r) {
    if (rows[r] < 0 || rows[r] >= source.phi.rows())
      throw UsageError("pointwise_map: a source row is out of range");
    queries.row(Eigen::Index(r)) = source.phi.row(rows[r]).head(k).cast<float>();
  }
  return nearest_rows_brute_force(queries, database);
}

Eigen::VectorXi zoomout(const LaplaceBeltramiBasis& source, const LaplaceBeltramiBasis& target,
                        const Eigen::VectorXi& initial, const ZoomOutOptions& options) {
  return pointwise_map(source, target, zoomout_functional_map(source, target, initial, options));
}

}  // namespace unfold
