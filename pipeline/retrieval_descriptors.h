// What retrieval keeps of one shape, computed once per shape and form and
// cached beside the batch outputs, so that the similarity matrix (in blocks,
// pipeline/similarity_blocks.h) never reads or normalises a mesh again.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>

#include "mesh/surface_mesh.h"
#include "metrics/shape_retrieval.h"
#include "metrics/visual_vocabulary.h"
#include "pipeline/cmbof_features.h"

namespace unfold {

/// The retrieval frameworks: the ICP dissimilarity (metrics/shape_retrieval.h),
/// ORT (metrics/ort_dissimilarity.h) and CM-BOF (pipeline/cmbof_features.h,
/// metrics/clock_matching.h). Their names are used in file names and in
/// retrieval.csv.
enum class RetrievalFramework { icp, ort, cmbof };
constexpr RetrievalFramework kRetrievalFrameworks[] = {
    RetrievalFramework::icp, RetrievalFramework::ort, RetrievalFramework::cmbof};
const char* framework_name(RetrievalFramework framework);

/// One shape's descriptor, a part per framework.
struct RetrievalDescriptor {
  Eigen::MatrixX3d icp, ort;  ///< normalised samples
  CmbofFeatures cmbof;        ///< the views' SIFT features
  /// The views' word histograms over the dataset's vocabulary
  /// (pipeline/cmbof_vocabulary.h): set once the vocabulary is known, not cached.
  std::vector<WordHistogram> cmbof_histograms;
};

/// The descriptor of a mesh (no histograms).
/// @throws UsageError as retrieval_sample, ort_sample, cmbof_features
RetrievalDescriptor retrieval_descriptor(const SurfaceMesh& mesh, const RetrievalOptions& options);

/// The framework's dissimilarity of two descriptors (not symmetric in general:
/// the matrices use it with the lower index first).
/// @throws UsageError for CMBOF without histograms
double framework_dissimilarity(RetrievalFramework framework, const RetrievalDescriptor& a,
                               const RetrievalDescriptor& b, const RetrievalOptions& options);

/// The options a descriptor depends on, as text for file headers
/// ("points=1000 icp=20 views=2 image=256 per_view=0"; not the vocabulary's,
/// which the cached SIFT features do not depend on).
std::string retrieval_options_key(const RetrievalOptions& options);

/// CM-BOF's options as text ("2,256,0,1500,20000,10", the CmbofOptions fields).
std::string cmbof_options_key(const CmbofOptions& options);

/// What a framework's similarity matrix depends on, as text for block files:
/// "icp points=1000 icp=20", "ort ..." likewise, "cmbof <cmbof_options_key>
/// vocabulary=<vocabulary_fingerprint>" (empty fingerprint for the others).
std::string similarity_key(RetrievalFramework framework, const RetrievalOptions& options,
                           const std::string& vocabulary_fingerprint);

/// Writes the descriptor (text, exact round trip) atomically. @throws OutputError
void write_retrieval_descriptor(const std::string& path, const RetrievalDescriptor& descriptor,
                                const RetrievalOptions& options);

/// The descriptor in `path`, or nothing if the file is missing, malformed or
/// was written with other options.
std::optional<RetrievalDescriptor> read_retrieval_descriptor(const std::string& path,
                                                             const RetrievalOptions& options);

}  // namespace unfold
