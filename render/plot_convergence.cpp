#include "render/plot_convergence.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <string>

#include "core/errors.h"
#include "render/draw_2d.h"
#include "render/plot_axes.h"

namespace unfold {
namespace {

const Rgb kCascade{150, 150, 150};

using Axes = PlotAxes;

void draw_series(const Axes& a, const std::vector<IterationRecord>& history,
                 const std::function<double(const IterationRecord&)>& value, Rgb color,
                 Image* image) {
  for (size_t k = 0; k < history.size(); ++k) {
    const double x = a.px(history[k].iteration), y = a.py(value(history[k]));
    if (k > 0)
      draw_line(a.px(history[k - 1].iteration), a.py(value(history[k - 1])), x, y, color, 2, image);
    fill_rect(int(x) - 2, int(y) - 2, int(x) + 3, int(y) + 3, color, image);
  }
}

// Dashed verticals halfway between the last iteration of a cascade and the first of the next.
void draw_cascade_boundaries(const Axes& a, const std::vector<IterationRecord>& history,
                             Image* image) {
  for (size_t k = 1; k < history.size(); ++k) {
    if (history[k].cascade == history[k - 1].cascade) continue;
    const double x = a.px(history[k].iteration - 0.5);
    for (int y = a.y0; y < a.y1; y += 8)
      draw_line(x, y, x, std::min(y + 4, a.y1), kCascade, 1, image);
  }
}

}  // namespace

Image plot_convergence(const std::vector<IterationRecord>& history,
                       const std::array<double, 2>& band, int width, int height) {
  if (width < 200 || height < 200)
    throw UsageError("plot_convergence: the plot needs at least 200 x 200 pixels");
  Image image(width, height);
  if (history.empty()) {  // e.g. Ceres starting at its minimum: a picture saying so
    draw_text("convergence: no iterations (the start already met the stopping rule)", 78, 8,
              kPlotInk, 1, &image);
    return image;
  }
  const double xmin = std::min(0, history.front().iteration - 1);
  const double xmax = history.back().iteration + 1;  // room right of the last point
  const int left = 78, right = width - 20, gap = 46;
  const int top = 44, bottom = height - 42, middle = (top + bottom) / 2;
  draw_text("convergence: " + std::to_string(history.size()) + " iterations, " +
                std::to_string(history.back().cascade) + " cascades (dashed: beta grows)",
            left, 8, kPlotInk, 1, &image);

  double emin = history.front().energy, emax = emin;
  for (const auto& r : history) {
    emin = std::min(emin, r.energy);
    emax = std::max(emax, r.energy);
  }
  const Axes energy = draw_plot_axes(left, top, right, middle - gap / 2, xmin, xmax, emin, emax,
                                     "energy (Eq. 3)", true, &image);
  draw_cascade_boundaries(energy, history, &image);
  draw_series(
      energy, history, [](const IterationRecord& r) { return r.energy; }, {31, 119, 180}, &image);

  double rmin = std::min(band[0], history.front().edge_ratio), rmax = std::max(band[1], rmin);
  for (const auto& r : history) {
    rmin = std::min(rmin, r.edge_ratio);
    rmax = std::max(rmax, r.edge_ratio);
  }
  const Axes ratio = draw_plot_axes(left, middle + gap / 2, right, bottom, xmin, xmax, rmin, rmax,
                                    "mean edge-length ratio (shaded: stopping band)", true, &image);
  fill_rect(ratio.x0 + 1, int(ratio.py(band[1])), ratio.x1, int(ratio.py(band[0])) + 1,
            {222, 240, 222}, &image);
  draw_cascade_boundaries(ratio, history, &image);
  draw_series(
      ratio, history, [](const IterationRecord& r) { return r.edge_ratio; }, {214, 39, 40}, &image);
  const std::string xlabel = "iteration";
  draw_text(xlabel, (left + right - text_size(xlabel, 1).first) / 2, height - 16, kPlotInk, 1,
            &image);
  return image;
}

}  // namespace unfold
