#include "render/plot_scaling.h"

#include <algorithm>
#include <cmath>

#include "core/errors.h"
#include "render/draw_2d.h"
#include "render/plot_axes.h"

namespace unfold {
namespace {

const Rgb kColors[] = {{31, 119, 180}, {214, 39, 40}, {44, 160, 44}, {255, 127, 14}};

void check(const std::vector<double>& n, const std::vector<double>& values,
           const std::string& name) {
  if (values.size() != n.size())
    throw UsageError("plot_scaling: series '" + name + "' needs one value per size");
  for (double v : values)
    if (!std::isfinite(v) || v < 0)
      throw UsageError("plot_scaling: series '" + name + "' has a negative or non-finite value");
}

// Points joined by lines, and the dashed proportional line c n through the
// origin and the last point.
void draw_series(const PlotAxes& a, const std::vector<double>& n, const std::vector<double>& v,
                 Rgb color, Image* image) {
  const double slope = v.back() / n.back();
  for (double x = 0; x < a.xmax; x += a.xmax / 60) {
    const double x1 = std::min(a.xmax, x + a.xmax / 120);
    draw_line(a.px(x), a.py(slope * x), a.px(x1), a.py(slope * x1), color, 1, image);
  }
  for (size_t k = 0; k < n.size(); ++k) {
    const double x = a.px(n[k]), y = a.py(v[k]);
    if (k > 0) draw_line(a.px(n[k - 1]), a.py(v[k - 1]), x, y, color, 2, image);
    fill_rect(int(x) - 3, int(y) - 3, int(x) + 4, int(y) + 4, color, image);
  }
}

}  // namespace

Image plot_scaling(const std::vector<double>& n, const std::vector<ScalingSeries>& seconds,
                   const std::vector<double>& peak_mb, int width, int height) {
  if (n.size() < 2) throw UsageError("plot_scaling: needs at least two sizes");
  if (width < 400 || height < 240)
    throw UsageError("plot_scaling: the plot needs at least 400 x 240 pixels");
  for (size_t k = 0; k < n.size(); ++k)
    if (!(n[k] > 0) || (k > 0 && !(n[k] > n[k - 1])))
      throw UsageError("plot_scaling: sizes must be positive and ascending");
  double tmax = 0;
  for (const auto& [name, values] : seconds) {
    check(n, values, name);
    tmax = std::max(tmax, *std::max_element(values.begin(), values.end()));
  }
  check(n, peak_mb, "peak memory");
  // x in thousands of vertices: short tick labels.
  std::vector<double> k(n.size());
  for (size_t i = 0; i < n.size(); ++i) k[i] = n[i] / 1000;
  Image image(width, height);
  const int top = 36, bottom = height - 44, middle = width * 3 / 5;
  const double xmax = k.back() * 1.05;
  const PlotAxes time =
      draw_plot_axes(64, top, middle - 30, bottom, 0, xmax, 0, std::max(tmax, 1e-3),
                     "seconds (dashed: proportional to n)", true, &image);
  for (size_t s = 0; s < seconds.size(); ++s) {
    const Rgb color = kColors[s % (sizeof kColors / sizeof kColors[0])];
    draw_series(time, k, seconds[s].second, color, &image);
    const int y = top + 8 + 14 * int(s);
    fill_rect(time.x0 + 10, y + 2, time.x0 + 24, y + 6, color, &image);
    draw_text(seconds[s].first, time.x0 + 30, y, kPlotInk, 1, &image);
  }
  const PlotAxes memory =
      draw_plot_axes(middle + 40, top, width - 20, bottom, 0, xmax, 0,
                     std::max(*std::max_element(peak_mb.begin(), peak_mb.end()), 1.0),
                     "peak memory, MB", true, &image);
  draw_series(memory, k, peak_mb, {148, 103, 189}, &image);
  const std::string xlabel = "tet vertices n (thousands)";
  for (const PlotAxes* a : {&time, &memory})
    draw_text(xlabel, (a->x0 + a->x1 - text_size(xlabel, 1).first) / 2, height - 18, kPlotInk, 1,
              &image);
  return image;
}

}  // namespace unfold
