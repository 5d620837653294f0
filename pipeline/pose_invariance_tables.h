// The pose invariance tables of a batch (docs/evaluation.md): per class and
// method, the pose distance of every pair of poses on the class's
// correspondence (pipeline/class_correspondence.h), its ratio to the raw
// poses' distance, and a picture of the forms side by side.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

namespace unfold {

struct PoseShape {
  std::string name, shape_class;
  std::string mesh_path;  ///< the input mesh (its .vts is looked for beside it)
  Eigen::MatrixX3i F;     ///< the input's triangles
  /// Per method label: the form on the input's vertices (input order), if the
  /// method produced one. Label 0 is "raw": the input pose itself.
  std::vector<std::optional<Eigen::MatrixX3d>> forms;
};

/// Writes output_dir/pose_pairs.csv
/// (class,method,shape_a,shape_b,raw_distance,pose_distance,ratio,correspondence),
/// pose_invariance.csv (class,method,pose_distance,mean_ratio,max_ratio,pairs,
/// correspondence) and poses_<class>_<method>.png. A class of two poses or more
/// without a correspondence gets one line in the log and, per method, a row of
/// pose_invariance.csv with empty numbers, 0 pairs and correspondence "none".
/// @param labels the method labels, "raw" first; shapes[i].forms has one entry per label
/// @throws UsageError if a shape lacks its raw form or a label's entry,
///         OutputError if a file cannot be written
void write_pose_invariance_tables(const std::string& output_dir,
                                  const std::vector<std::string>& labels,
                                  const std::vector<PoseShape>& shapes);

}  // namespace unfold
