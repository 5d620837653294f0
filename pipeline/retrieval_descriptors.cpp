#include "pipeline/retrieval_descriptors.h"

#include <fstream>
#include <iomanip>
#include <limits>
#include <sstream>

#include "core/atomic_file.h"
#include "metrics/ort_dissimilarity.h"

namespace unfold {
namespace {

constexpr const char* kMagic = "unfold retrieval descriptor v1";

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

}  // namespace

const char* framework_name(RetrievalFramework framework) {
  return framework == RetrievalFramework::icp ? "icp" : "ort";
}

RetrievalDescriptor retrieval_descriptor(const SurfaceMesh& mesh, const RetrievalOptions& options) {
  return {retrieval_sample(mesh.V, options),
          ort_sample(mesh.V, triangulate_faces(mesh), options.sample_points)};
}

double framework_dissimilarity(RetrievalFramework framework, const RetrievalDescriptor& a,
                               const RetrievalDescriptor& b, const RetrievalOptions& options) {
  return framework == RetrievalFramework::icp
             ? shape_dissimilarity(a.icp, b.icp, options)
             : ort_dissimilarity(a.ort, b.ort, options.icp_iterations);
}

std::string retrieval_options_key(const RetrievalOptions& options) {
  return "points=" + std::to_string(options.sample_points) +
         " icp=" + std::to_string(options.icp_iterations);
}

void write_retrieval_descriptor(const std::string& path, const RetrievalDescriptor& descriptor,
                                const RetrievalOptions& options) {
  write_file_atomically(path, [&](std::ostream& s) {
    s << kMagic << '\n'
      << retrieval_options_key(options) << '\n'
      << std::setprecision(std::numeric_limits<double>::max_digits10);
    write_points(s, descriptor.icp);
    write_points(s, descriptor.ort);
  });
}

std::optional<RetrievalDescriptor> read_retrieval_descriptor(const std::string& path,
                                                             const RetrievalOptions& options) {
  std::ifstream in(path);
  std::string magic, key;
  if (!std::getline(in, magic) || magic != kMagic || !std::getline(in, key) ||
      key != retrieval_options_key(options))
    return std::nullopt;
  RetrievalDescriptor d;
  if (!read_points(in, &d.icp) || !read_points(in, &d.ort)) return std::nullopt;
  return d;
}

}  // namespace unfold
