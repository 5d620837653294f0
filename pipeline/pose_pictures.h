// Pose invariance at a glance: the forms of every pose of one shape side by
// side, each rigidly aligned to the first and scaled to unit surface area, with
// the same cameras and scale, so that equal forms look equal.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "render/image.h"

namespace unfold {

struct PosePanel {
  std::string title;   ///< the pose's name
  Eigen::MatrixX3d V;  ///< its form (raw pose or canonical form), vertices in shared order
  double scale = 1;    ///< sqrt(surface area of the form): forms are divided by it
};

/// Side and top views of every panel's form after the best rigid alignment
/// (metrics/rigid_alignment.h) to the first panel's; panels whose vertex count
/// differs from the first's are left out.
/// @param F     triangles shared by the forms
/// @param title goes before each panel's title in its caption (e.g. the method)
/// @throws UsageError for no panels or a zero scale
Image render_poses(const std::vector<PosePanel>& panels, const Eigen::MatrixX3i& F,
                   const std::string& title);

}  // namespace unfold
