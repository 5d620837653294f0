#include "render/close_up.h"

#include <algorithm>
#include <cmath>

#include "core/errors.h"
#include "render/color_map.h"
#include "render/draw_2d.h"
#include "render/render_comparison.h"

namespace unfold {

double ball_scale(double radius, int width, int height, int margin) {
  if (!(radius > 0) || !std::isfinite(radius))
    throw UsageError("close-up: the radius must be positive and finite");
  const int room = std::min(width, height) - 2 * margin;
  if (room <= 0) throw UsageError("close-up: the panel leaves no room inside its margin");
  return room / (2 * radius);
}

void render_close_up(const CloseUp& tile, Shading shading, int margin, Canvas* canvas) {
  const double scale = ball_scale(tile.radius, canvas->image.width, canvas->image.height, margin);
  // Depth is minus the coordinate towards the viewer (project()): the ball's
  // front is at the centre's depth less the radius.
  canvas->near_depth = -tile.view.axes.row(2).dot(tile.centre.transpose()) - tile.radius;
  render_mesh_about(tile.V, tile.F, tile.colors, tile.view, tile.centre, scale, shading, canvas);
}

Image render_close_ups(const std::vector<CloseUp>& tiles, const std::string& title,
                       const CloseUpSheetOptions& options) {
  if (tiles.empty()) throw UsageError("render_close_ups: no tiles");
  if (options.tile_size < 16 || options.columns < 1 || options.supersample < 1)
    throw UsageError(
        "render_close_ups: tiles need at least 16 pixels, columns and supersample >= 1");
  const int size = options.tile_size, s = options.supersample;
  // A caption is drawn at font scale 2 when it fits the tile, else at 1.
  const auto font_scale = [&](const std::string& caption) {
    return text_size(caption, 2).first <= size - 8 ? 2 : 1;
  };
  int caption_height = 0;
  for (const CloseUp& t : tiles)
    caption_height =
        std::max(caption_height, text_size(t.caption, font_scale(t.caption)).second + 8);
  const int columns = std::min(options.columns, int(tiles.size()));
  const int rows = (int(tiles.size()) + columns - 1) / columns;
  const int legend_height = options.legend.empty() ? 0 : 20;
  Image out(columns * size, kCaptionHeight + rows * (size + caption_height) + legend_height);
  const Rgb ink{40, 40, 40};
  for (size_t k = 0; k < tiles.size(); ++k) {
    const int x = int(k) % columns * size,
              y = kCaptionHeight + int(k) / columns * (size + caption_height);
    Canvas canvas(size * s, size * s, {255, 255, 255});
    render_close_up(tiles[k], options.shading, 4 * s, &canvas);
    paste(downsample(canvas.image, s), x, y, &out);
    const int scale = font_scale(tiles[k].caption);
    const int tw = text_size(tiles[k].caption, scale).first;
    draw_text(tiles[k].caption, x + std::max(2, (size - tw) / 2), y + size + 4, ink, scale, &out);
    if (x > 0)  // a thin separator between columns
      fill_rect(x, y, x + 1, y + size + caption_height, {210, 210, 210}, &out);
  }
  const auto [tw, th] = text_size(title, 2);
  draw_text(title, std::max(2, (out.width - tw) / 2), (kCaptionHeight - th) / 2 + 2, ink, 2, &out);
  if (!options.legend.empty()) draw_color_bar(options.legend, &out);
  return out;
}

}  // namespace unfold
