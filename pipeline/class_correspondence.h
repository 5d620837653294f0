// Which points of the poses of one class are the same body point, for the
// pose distances of a batch (docs/evaluation.md): the .vts files beside the
// meshes when every pose has one, else the vertex order when the poses share
// their vertex count, else none (and why).
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

namespace unfold {

enum class CorrespondenceBasis { kNone, kVertexOrder, kVts };

/// "none", "vertex_order" or "vts", as in pose_pairs.csv.
const char* correspondence_name(CorrespondenceBasis basis);

struct ClassCorrespondence {
  CorrespondenceBasis basis = CorrespondenceBasis::kNone;
  std::vector<Eigen::VectorXi> rows;  ///< kVts: per pose, its zero-based ids (read_vts)
  std::string problem;                ///< kNone: why, one line naming the class
};

/// Decides the correspondence of one class's poses. The .vts files win over
/// the vertex order: two poses meshed independently can have the same vertex
/// count by chance (faust_remeshed's tr_reg_000 and tr_reg_002 do).
/// @param class_name for the message
/// @param mesh_paths the poses' mesh files (their .vts files are looked for beside them)
/// @param vertex_counts the poses' vertex counts
/// @return kNone with the problem if the vertex counts differ and a pose has no
///         .vts, or a .vts is unreadable or does not fit (read_vts's message)
ClassCorrespondence class_correspondence(const std::string& class_name,
                                         const std::vector<std::string>& mesh_paths,
                                         const std::vector<int>& vertex_counts);

}  // namespace unfold
