// Pose invariance at a glance: the forms of every pose of one shape side by
// side, each scaled to its own unit surface area and rigidly aligned to the
// first on their corresponding points, with the same cameras and scale, so
// that equal forms look equal, however each pose is meshed.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "render/image.h"

namespace unfold {

struct PosePanel {
  std::string title;   ///< the pose's name
  Eigen::MatrixX3d V;  ///< its form (raw pose or canonical form)
  Eigen::MatrixX3i F;  ///< its triangles
  /// The vertices that correspond across panels (row k the same point in
  /// every panel, e.g. read_vts); empty: all vertices, in shared order.
  Eigen::VectorXi rows;
};

/// Side and top views of every panel's form, scaled to unit surface area and
/// moved by the best rigid alignment (metrics/rigid_alignment.h) of its
/// corresponding points onto the first panel's.
/// @param title goes before each panel's title in its caption (e.g. the method)
/// @throws UsageError for no panels, a surface of zero area, or panels whose
///         corresponding points differ in number
Image render_poses(const std::vector<PosePanel>& panels, const std::string& title);

}  // namespace unfold
