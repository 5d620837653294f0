// Orthographic cameras and framing: which way a panel looks at a shape, and
// one scale shared by every shape shown in that view so sizes compare.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

namespace unfold {

struct View {
  std::string name;
  /// Rows: screen right, screen up, towards the viewer (a rotation).
  Eigen::Matrix3d axes;
};

/// 0, 1, 2 for "x", "y", "z". @throws UsageError naming `what` for anything else
int axis_index(const std::string& name, const std::string& what);

/// A side view and a top view of a shape standing along `up_axis`: screen x is
/// the principal horizontal direction of `V` (its longest horizontal extent,
/// e.g. an animal's body), screen y is up (side) or the other horizontal
/// direction (top). Deterministic for a given V.
/// @param V       the shape that fixes the cameras (the input: before/after share them)
/// @param up_axis 0, 1 or 2 (x, y, z)
/// @throws UsageError for another up_axis
std::vector<View> side_and_top_views(const Eigen::MatrixX3d& V, int up_axis);

/// A view looking at a surface face on: towards -`normal` (the viewer on the
/// side `normal` points to), screen up as near the shape's up axis as the
/// normal allows (the next axis when the normal is nearly vertical), so that
/// close-ups of different shapes stand the same way up.
/// @param normal  any nonzero direction, e.g. a region's mean normal
/// @param up_axis 0, 1 or 2 (x, y, z)
/// @throws UsageError for another up_axis or a zero or non-finite normal
View view_facing(const Eigen::Vector3d& normal, int up_axis);

/// The largest pixels-per-unit scale at which every shape fits a width x height
/// panel with `margin` pixels to spare on each side, each centred on its own
/// bounding box; 1 if all shapes are empty or points.
double common_scale(const std::vector<const Eigen::MatrixX3d*>& shapes, const View& view, int width,
                    int height, int margin);

/// Pixel coordinates (x right, y down) and depth (smaller = nearer) of V seen
/// through `view` at `scale`, its bounding box centred in a width x height panel.
Eigen::MatrixX3d project(const Eigen::MatrixX3d& V, const View& view, double scale, int width,
                         int height);

/// project() of `points` with the point `centre` at the panel's centre
/// instead of a bounding box's: a close-up (points outside the panel get
/// pixel coordinates outside it, for the rasteriser to clip).
Eigen::MatrixX3d project_about(const Eigen::MatrixX3d& points, const Eigen::Vector3d& centre,
                               const View& view, double scale, int width, int height);

/// project() of `points` in the frame of V: placed where project(V, ...) puts
/// the same positions (V's bounding box centred), e.g. lines drawn over V.
Eigen::MatrixX3d project_in_frame(const Eigen::MatrixX3d& points, const Eigen::MatrixX3d& V,
                                  const View& view, double scale, int width, int height);

}  // namespace unfold
