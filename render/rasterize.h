// Z-buffered triangle rasterisation with per-vertex colours (flat shading is
// three equal colours, Gouraud three different ones).
#pragma once

#include <Eigen/Core>
#include <limits>
#include <vector>

#include "render/image.h"

namespace unfold {

/// An image with one depth per pixel; smaller depth is nearer the viewer.
struct Canvas {
  Image image;
  std::vector<double> depth;  ///< width * height, row-major, +infinity where nothing is drawn
  /// Nothing nearer than this depth is drawn: a close-up cuts away what lies
  /// between the viewer and the part it looks at (-infinity: nothing is cut).
  double near_depth = -std::numeric_limits<double>::infinity();

  /// A width x height canvas filled with `background`, depth +infinity.
  Canvas(int width, int height, Rgb background = {255, 255, 255});
};

/// Fills the pixels whose centres (x + 0.5, y + 0.5) lie inside the triangle and
/// are nearer than what the canvas holds there and not nearer than its
/// near_depth, interpolating colour and depth linearly. Pixel coordinates: x
/// right, y down; both windings are drawn; a degenerate (zero-area) triangle
/// draws nothing.
/// @param xyz    the three corners: pixel x, pixel y, depth
/// @param colors the corners' colours, RGB in [0, 1] (clamped)
void rasterize_triangle(const Eigen::Matrix3d& xyz, const Eigen::Matrix3f& colors, Canvas* canvas);

}  // namespace unfold
