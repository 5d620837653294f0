// What retrieval keeps of one shape, computed once per shape and form and
// cached beside the batch outputs, so that the similarity matrix (in blocks,
// pipeline/similarity_blocks.h) never reads or normalises a mesh again.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>

#include "mesh/surface_mesh.h"
#include "metrics/shape_retrieval.h"

namespace unfold {

/// The retrieval frameworks: the ICP dissimilarity (metrics/shape_retrieval.h)
/// and ORT (metrics/ort_dissimilarity.h). Their names are used in file names
/// and in retrieval.csv.
enum class RetrievalFramework { icp, ort };
constexpr RetrievalFramework kRetrievalFrameworks[] = {RetrievalFramework::icp,
                                                       RetrievalFramework::ort};
const char* framework_name(RetrievalFramework framework);

/// One shape's normalised samples, one per framework.
struct RetrievalDescriptor {
  Eigen::MatrixX3d icp, ort;
};

/// The descriptor of a mesh. @throws UsageError as retrieval_sample, ort_sample
RetrievalDescriptor retrieval_descriptor(const SurfaceMesh& mesh, const RetrievalOptions& options);

/// The framework's dissimilarity of two descriptors (not symmetric in general:
/// the matrices use it with the lower index first).
double framework_dissimilarity(RetrievalFramework framework, const RetrievalDescriptor& a,
                               const RetrievalDescriptor& b, const RetrievalOptions& options);

/// The options a descriptor or a similarity block depends on, as text for
/// file headers ("points=1000 icp=20").
std::string retrieval_options_key(const RetrievalOptions& options);

/// Writes the descriptor (text, exact round trip) atomically. @throws OutputError
void write_retrieval_descriptor(const std::string& path, const RetrievalDescriptor& descriptor,
                                const RetrievalOptions& options);

/// The descriptor in `path`, or nothing if the file is missing, malformed or
/// was written with other options.
std::optional<RetrievalDescriptor> read_retrieval_descriptor(const std::string& path,
                                                             const RetrievalOptions& options);

}  // namespace unfold
