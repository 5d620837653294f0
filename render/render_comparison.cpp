#include "render/render_comparison.h"

#include <algorithm>
#include <cstdio>
#include <utility>
#include <vector>

#include "core/errors.h"
#include "render/camera.h"
#include "render/color_map.h"
#include "render/draw_2d.h"
#include "render/rasterize.h"

namespace unfold {

Image render_comparison(const std::vector<RenderPanel>& panels, const RenderOptions& options) {
  if (panels.empty()) throw UsageError("render_comparison: no panels");
  if (options.panel_width < 16 || options.panel_height < 16 || options.supersample < 1)
    throw UsageError("render_comparison: panels need at least 16 x 16 pixels, supersample >= 1");
  std::vector<double> values;
  for (const RenderPanel& p : panels) {
    if (p.values.size() != 0 && p.values.size() != p.V.rows())
      throw UsageError("render_comparison: panel '" + p.title + "' has " +
                       std::to_string(p.values.size()) + " values for " +
                       std::to_string(p.V.rows()) + " vertices");
    values.insert(values.end(), p.values.data(), p.values.data() + p.values.size());
    if (p.lines.size() > 0 &&
        (p.lines.minCoeff() < 0 || p.lines.maxCoeff() >= p.line_points.rows()))
      throw UsageError("render_comparison: panel '" + p.title + "' has a line to a point of " +
                       std::to_string(p.line_points.rows()) + " that does not exist");
  }
  const double value_max = color_scale_top(std::move(values));
  const std::vector<View> views = side_and_top_views(panels.front().V, options.up_axis);
  const int s = options.supersample;
  const int w = options.panel_width * s, h = options.panel_height * s;
  Image out(int(panels.size()) * options.panel_width,
            kCaptionHeight + int(views.size()) * options.panel_height);
  const Rgb ink{40, 40, 40};
  for (size_t row = 0; row < views.size(); ++row) {
    std::vector<const Eigen::MatrixX3d*> shapes;
    for (const RenderPanel& p : panels) shapes.push_back(&p.V);
    const double scale = common_scale(shapes, views[row], w, h, 8 * s);
    for (size_t col = 0; col < panels.size(); ++col) {
      const RenderPanel& p = panels[col];
      Canvas canvas(w, h, {255, 255, 255});
      const Eigen::MatrixX3f colors = p.colors.rows()   ? p.colors
                                      : p.values.size() ? color_map(p.values, 0, value_max)
                                                        : Eigen::MatrixX3f();
      render_mesh(p.V, p.F, colors, views[row], scale, options.shading, &canvas);
      if (p.lines.rows() > 0) {
        const Eigen::MatrixX3d ends = project_in_frame(p.line_points, p.V, views[row], scale, w, h);
        for (int k = 0; k < p.lines.rows(); ++k)
          draw_line(ends(p.lines(k, 0), 0), ends(p.lines(k, 0), 1), ends(p.lines(k, 1), 0),
                    ends(p.lines(k, 1), 1), {220, 30, 30}, 2 * s, &canvas.image);
      }
      const int x = int(col) * options.panel_width,
                y = kCaptionHeight + int(row) * options.panel_height;
      paste(downsample(canvas.image, s), x, y, &out);
      if (col == 0) draw_text(views[row].name, x + 4, y + 4, {120, 120, 120}, 1, &out);
      if (col > 0)  // a thin separator between columns
        fill_rect(x, y, x + 1, y + options.panel_height, {210, 210, 210}, &out);
    }
  }
  for (size_t col = 0; col < panels.size(); ++col) {
    const auto [tw, th] = text_size(panels[col].title, 2);
    draw_text(panels[col].title,
              int(col) * options.panel_width + std::max(2, (options.panel_width - tw) / 2),
              (kCaptionHeight - th) / 2 + 2, ink, 2, &out);
  }
  if (value_max > 0) {
    char label[64];
    std::snprintf(label, sizeof label, "0 .. %.3g+", value_max);
    draw_color_bar(label, &out);
  }
  return out;
}

}  // namespace unfold
