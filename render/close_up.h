// Close-ups: a mesh seen about a ball (one region of it, e.g. its worst
// damage) instead of whole, and sheets of captioned close-ups side by side,
// for detail that whole-body pictures are too small to show (issue 44).
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "render/camera.h"
#include "render/image.h"
#include "render/rasterize.h"
#include "render/render_mesh.h"

namespace unfold {

/// One close-up: the ball (centre, radius) of a mesh, seen through `view`.
struct CloseUp {
  std::string caption;  ///< written under the tile ('\n' starts a new line)
  Eigen::MatrixX3d V;
  Eigen::MatrixX3i F;       ///< triangles
  Eigen::MatrixX3f colors;  ///< per-vertex RGB in [0, 1] (V.rows() x 3), or empty: neutral
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();  ///< drawn at the tile's centre
  double radius = 1;  ///< the ball's projection fills the tile, less a margin
  View view{"facing", Eigen::Matrix3d::Identity()};  ///< e.g. view_facing(the region's normal)
};

/// Pixels per unit at which a ball of `radius` just fills a width x height
/// panel with `margin` pixels to spare: its projected diameter is
/// min(width, height) - 2 margin.
/// @throws UsageError if radius is not positive and finite, or the panel leaves no room
double ball_scale(double radius, int width, int height, int margin);

/// Draws a close-up into `canvas`: tile.centre at the canvas centre, at
/// ball_scale(tile.radius, ..., margin); triangles outside the canvas are
/// clipped, and whatever lies nearer the viewer than the ball is cut away
/// (canvas->near_depth is set), so that another part in front does not hide
/// the region.
/// @throws UsageError for a bad radius or colours of the wrong size
void render_close_up(const CloseUp& tile, Shading shading, int margin, Canvas* canvas);

struct CloseUpSheetOptions {
  int tile_size = 240;  ///< pixels per side of each square tile
  int columns = 6;      ///< tiles per row
  Shading shading = Shading::kGouraud;
  int supersample = 2;  ///< drawn this many times larger, then averaged (anti-aliasing)
  /// when not empty, a colour bar (color_map) with this label, bottom right
  std::string legend;
};

/// The tiles in rows of options.columns, each a tile_size square with its
/// caption under it, `title` in a band above them all.
/// @throws UsageError for no tiles, tile_size < 16, columns or supersample < 1,
///         or a bad tile (see render_close_up)
Image render_close_ups(const std::vector<CloseUp>& tiles, const std::string& title,
                       const CloseUpSheetOptions& options);

}  // namespace unfold
