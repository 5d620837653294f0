#include "render/plot_convergence.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <string>

#include "core/errors.h"
#include "render/draw_2d.h"

namespace unfold {
namespace {

const Rgb kInk{40, 40, 40}, kGrid{225, 225, 225}, kCascade{150, 150, 150};

std::string format(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", x);
  return text;
}

// Tick positions at 1, 2 or 5 times a power of ten, about `count` of them in [lo, hi].
std::vector<double> ticks(double lo, double hi, int count) {
  const double raw = (hi - lo) / count;
  const double power = std::pow(10.0, std::floor(std::log10(raw)));
  double step = power;  // the 1-2-5 step nearest `raw` on a log scale
  for (double m : {2.0, 5.0, 10.0})
    if (std::abs(std::log(m * power / raw)) < std::abs(std::log(step / raw))) step = m * power;
  std::vector<double> result;
  for (double t = std::ceil(lo / step) * step; t <= hi + 1e-9 * step; t += step)
    result.push_back(std::abs(t) < 1e-12 * step ? 0.0 : t);
  return result;
}

struct Axes {
  int x0, y0, x1, y1;  // plot area in pixels
  double xmin, xmax, ymin, ymax;
  double px(double x) const { return x0 + (x - xmin) / (xmax - xmin) * (x1 - x0); }
  double py(double y) const { return y1 - (y - ymin) / (ymax - ymin) * (y1 - y0); }
};

// Frame, grid, tick labels and title of one subplot; y range padded by 5%.
Axes draw_axes(int x0, int y0, int x1, int y1, double xmin, double xmax, double ymin, double ymax,
               const std::string& title, Image* image) {
  if (!(ymax > ymin)) {
    const double pad = std::max(1e-9, std::abs(ymin) * 0.05);
    ymin -= pad;
    ymax += pad;
  }
  const double pad = 0.05 * (ymax - ymin);
  Axes a{x0, y0, x1, y1, xmin, xmax, ymin - pad, ymax + pad};
  for (double t : ticks(a.ymin, a.ymax, 5)) {
    draw_line(x0, a.py(t), x1, a.py(t), kGrid, 1, image);
    const std::string label = format(t);
    const auto [w, h] = text_size(label, 1);
    draw_text(label, x0 - w - 6, int(a.py(t)) - h / 2, kInk, 1, image);
  }
  for (double t : ticks(xmin, xmax, 8)) {
    if (t != std::round(t)) continue;  // iterations are whole numbers
    draw_line(a.px(t), y1, a.px(t), y1 + 4, kInk, 1, image);
    const std::string label = format(t);
    draw_text(label, int(a.px(t)) - text_size(label, 1).first / 2, y1 + 7, kInk, 1, image);
  }
  draw_line(x0, y0, x0, y1, kInk, 1, image);
  draw_line(x0, y1, x1, y1, kInk, 1, image);
  draw_text(title, x0, y0 - 16, kInk, 1, image);
  return a;
}

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
  if (history.empty()) throw UsageError("plot_convergence: empty iteration history");
  if (width < 200 || height < 200)
    throw UsageError("plot_convergence: the plot needs at least 200 x 200 pixels");
  Image image(width, height);
  const double xmin = std::min(0, history.front().iteration - 1);
  const double xmax = history.back().iteration + 1;  // room right of the last point
  const int left = 78, right = width - 20, gap = 46;
  const int top = 44, bottom = height - 42, middle = (top + bottom) / 2;
  draw_text("convergence: " + std::to_string(history.size()) + " iterations, " +
                std::to_string(history.back().cascade) + " cascades (dashed: beta grows)",
            left, 8, kInk, 1, &image);

  double emin = history.front().energy, emax = emin;
  for (const auto& r : history) {
    emin = std::min(emin, r.energy);
    emax = std::max(emax, r.energy);
  }
  const Axes energy = draw_axes(left, top, right, middle - gap / 2, xmin, xmax, emin, emax,
                                "energy (Eq. 3)", &image);
  draw_cascade_boundaries(energy, history, &image);
  draw_series(
      energy, history, [](const IterationRecord& r) { return r.energy; }, {31, 119, 180}, &image);

  double rmin = std::min(band[0], history.front().edge_ratio), rmax = std::max(band[1], rmin);
  for (const auto& r : history) {
    rmin = std::min(rmin, r.edge_ratio);
    rmax = std::max(rmax, r.edge_ratio);
  }
  const Axes ratio = draw_axes(left, middle + gap / 2, right, bottom, xmin, xmax, rmin, rmax,
                               "mean edge-length ratio (shaded: stopping band)", &image);
  fill_rect(ratio.x0 + 1, int(ratio.py(band[1])), ratio.x1, int(ratio.py(band[0])) + 1,
            {222, 240, 222}, &image);
  draw_cascade_boundaries(ratio, history, &image);
  draw_series(
      ratio, history, [](const IterationRecord& r) { return r.edge_ratio; }, {214, 39, 40}, &image);
  const std::string xlabel = "iteration";
  draw_text(xlabel, (left + right - text_size(xlabel, 1).first) / 2, height - 16, kInk, 1, &image);
  return image;
}

}  // namespace unfold
