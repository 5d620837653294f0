// Side-by-side pictures: one column per shape (before/after, or one per beta),
// one row per view, the same cameras and scale for every column so that the
// columns compare directly.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "render/image.h"
#include "render/render_mesh.h"

namespace unfold {

struct RenderPanel {
  std::string title;
  Eigen::MatrixX3d V;
  Eigen::MatrixX3i F;      ///< triangles
  Eigen::VectorXd values;  ///< per-vertex values to colour by, or empty for plain shading
  /// per-vertex RGB colours in [0, 1] (V.rows() x 3), drawn instead of `values` when not empty
  Eigen::MatrixX3f colors{};
  /// line segments drawn over the shaded mesh (not hidden by it), e.g. a
  /// skeleton inside it: endpoints line_points.row(lines(k, 0)) and (lines(k, 1))
  Eigen::MatrixX3d line_points{};
  Eigen::MatrixX2i lines{};
};

struct RenderOptions {
  int panel_width = 360;   ///< pixels per column
  int panel_height = 240;  ///< pixels per view row
  int up_axis = 2;         ///< 0, 1, 2: x, y, z is up in the shapes (TOSCA and the demo: z)
  Shading shading = Shading::kGouraud;
  int supersample = 2;  ///< drawn this many times larger, then averaged (anti-aliasing)
};

/// Height of the caption band above the panels, in pixels.
constexpr int kCaptionHeight = 28;

/// Renders the panels side by side: image size columns * panel_width by
/// kCaptionHeight + views * panel_height. The views (side_and_top_views) come
/// from the first panel's shape; each row uses one scale for all columns.
/// Panels with values are coloured by them on one common scale from 0 to the
/// 98th percentile of all values (higher values take the top colour).
/// Panels with lines have them drawn in red over the mesh, 2 pixels wide.
/// @throws UsageError for no panels, sizes < 16 pixels, supersample < 1, bad up_axis,
///         or panel data of inconsistent sizes (a line naming a point that does not exist)
Image render_comparison(const std::vector<RenderPanel>& panels, const RenderOptions& options);

}  // namespace unfold
