#include "pipeline/retrieval_descriptors.h"

#include <fstream>
#include <iomanip>
#include <limits>
#include <sstream>

#include "core/atomic_file.h"
#include "core/errors.h"
#include "metrics/clock_matching.h"
#include "metrics/ort_dissimilarity.h"
#include "metrics/view_sphere.h"

namespace unfold {
namespace {

// v3: the ORT normalisation chooses its orientation by silhouette area, so
// the ORT samples and CMBOF features of earlier descriptors are stale.
constexpr const char* kDescriptorMagic = "unfold retrieval descriptor v3";

void write_points(std::ostream& s, const Eigen::MatrixX3d& P) {
  s << P.rows() << '\n';
  for (Eigen::Index i = 0; i < P.rows(); ++i)
    s << P(i, 0) << ' ' << P(i, 1) << ' ' << P(i, 2) << '\n';
}

bool read_points(std::istream& s, Eigen::MatrixX3d* P) {
  Eigen::Index rows = -1;
  if (!(s >> rows) || rows < 1 || rows > 100000000) return false;
  P->resize(rows, 3);
  for (Eigen::Index i = 0; i < rows; ++i)
    if (!(s >> (*P)(i, 0) >> (*P)(i, 1) >> (*P)(i, 2))) return false;
  return true;
}

// The clock's view permutations for each subdivision level, made once.
const std::vector<std::vector<int>>& clock_rotations(int subdivisions) {
  static const std::vector<std::vector<std::vector<int>>> levels = [] {
    std::vector<std::vector<std::vector<int>>> all;
    for (int level = 0; level <= 3; ++level)
      all.push_back(view_sphere_rotations(view_sphere_directions(level)));
    return all;
  }();
  view_sphere_directions(subdivisions);  // throws for a level outside [0, 3]
  return levels[size_t(subdivisions)];
}

}  // namespace

const char* framework_name(RetrievalFramework framework) {
  switch (framework) {
    case RetrievalFramework::icp:
      return "icp";
    case RetrievalFramework::ort:
      return "ort";
    case RetrievalFramework::cmbof:
      return "cmbof";
  }
  return "?";
}

RetrievalDescriptor retrieval_descriptor(const SurfaceMesh& mesh, const RetrievalOptions& options) {
  const Eigen::MatrixX3i F = triangulate_faces(mesh);
  Eigen::MatrixX3d icp = retrieval_sample(mesh.V, options);  // checks the options first
  const Eigen::MatrixX3d normalised = ort_normalise(mesh.V, F);
  return {std::move(icp),
          evenly_spaced_rows(normalised, options.sample_points),
          cmbof_features(normalised, F, options.cmbof),
          {}};
}

double framework_dissimilarity(RetrievalFramework framework, const RetrievalDescriptor& a,
                               const RetrievalDescriptor& b, const RetrievalOptions& options) {
  switch (framework) {
    case RetrievalFramework::icp:
      return shape_dissimilarity(a.icp, b.icp, options);
    case RetrievalFramework::ort:
      return ort_dissimilarity(a.ort, b.ort, options.icp_iterations);
    case RetrievalFramework::cmbof:
      if (a.cmbof_histograms.empty() || b.cmbof_histograms.empty())
        throw UsageError("CMBOF: the word histograms are not computed (no vocabulary yet)");
      return clock_matching_dissimilarity(a.cmbof_histograms, b.cmbof_histograms,
                                          clock_rotations(options.cmbof.view_subdivisions));
  }
  return 0;
}

std::string cmbof_options_key(const CmbofOptions& o) {
  std::string key;
  for (int v : {o.view_subdivisions, o.image_size, o.features_per_view, o.words,
                o.training_features, o.kmeans_iterations})
    key += (key.empty() ? "" : ",") + std::to_string(v);
  return key;
}

std::string retrieval_options_key(const RetrievalOptions& options) {
  return "points=" + std::to_string(options.sample_points) +
         " icp=" + std::to_string(options.icp_iterations) +
         " views=" + std::to_string(options.cmbof.view_subdivisions) +
         " image=" + std::to_string(options.cmbof.image_size) +
         " per_view=" + std::to_string(options.cmbof.features_per_view);
}

std::string similarity_key(RetrievalFramework framework, const RetrievalOptions& options,
                           const std::string& vocabulary_fingerprint) {
  if (framework == RetrievalFramework::cmbof)
    return "cmbof " + cmbof_options_key(options.cmbof) + " vocabulary=" + vocabulary_fingerprint;
  return std::string(framework_name(framework)) +
         " points=" + std::to_string(options.sample_points) +
         " icp=" + std::to_string(options.icp_iterations);
}

void write_retrieval_descriptor(const std::string& path, const RetrievalDescriptor& descriptor,
                                const RetrievalOptions& options) {
  write_file_atomically(
      path,
      [&](std::ostream& s) {
        s << kDescriptorMagic << '\n'
          << retrieval_options_key(options) << '\n'
          << std::setprecision(std::numeric_limits<double>::max_digits10);
        write_points(s, descriptor.icp);
        write_points(s, descriptor.ort);
        write_cmbof_features(s, descriptor.cmbof);
      },
      true);
}

std::optional<RetrievalDescriptor> read_retrieval_descriptor(const std::string& path,
                                                             const RetrievalOptions& options) {
  std::ifstream in(path, std::ios::binary);
  std::string magic, key;
  if (!std::getline(in, magic) || magic != kDescriptorMagic || !std::getline(in, key) ||
      key != retrieval_options_key(options))
    return std::nullopt;
  RetrievalDescriptor d;
  if (!read_points(in, &d.icp) || !read_points(in, &d.ort) || !read_cmbof_features(in, &d.cmbof))
    return std::nullopt;
  return d;
}

}  // namespace unfold
