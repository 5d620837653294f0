#include "render/plot_axes.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "render/draw_2d.h"

namespace unfold {
namespace {
const Rgb kGrid{225, 225, 225};
}  // namespace

std::vector<double> plot_ticks(double lo, double hi, int count) {
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

std::string tick_label(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", x);
  return text;
}

PlotAxes draw_plot_axes(int x0, int y0, int x1, int y1, double xmin, double xmax, double ymin,
                        double ymax, const std::string& title, bool integer_x, Image* image) {
  if (!(ymax > ymin)) {
    const double pad = std::max(1e-9, std::abs(ymin) * 0.05);
    ymin -= pad;
    ymax += pad;
  }
  const double pad = 0.05 * (ymax - ymin);
  PlotAxes a{x0, y0, x1, y1, xmin, xmax, ymin - pad, ymax + pad};
  for (double t : plot_ticks(a.ymin, a.ymax, 5)) {
    draw_line(x0, a.py(t), x1, a.py(t), kGrid, 1, image);
    const std::string label = tick_label(t);
    const auto [w, h] = text_size(label, 1);
    draw_text(label, x0 - w - 6, int(a.py(t)) - h / 2, kPlotInk, 1, image);
  }
  for (double t : plot_ticks(xmin, xmax, 8)) {
    if (integer_x && t != std::round(t)) continue;
    draw_line(a.px(t), y1, a.px(t), y1 + 4, kPlotInk, 1, image);
    const std::string label = tick_label(t);
    draw_text(label, int(a.px(t)) - text_size(label, 1).first / 2, y1 + 7, kPlotInk, 1, image);
  }
  draw_line(x0, y0, x0, y1, kPlotInk, 1, image);
  draw_line(x0, y1, x1, y1, kPlotInk, 1, image);
  draw_text(title, x0, y0 - 16, kPlotInk, 1, image);
  return a;
}

Rgb series_color(size_t k) {
  static const Rgb colors[] = {{31, 119, 180}, {214, 39, 40},   {44, 160, 44},
                               {255, 127, 14}, {148, 103, 189}, {140, 86, 75}};
  return colors[k % (sizeof colors / sizeof colors[0])];
}

void draw_legend(const std::vector<std::string>& names, int right, int top, Image* image) {
  for (size_t s = 0; s < names.size(); ++s) {
    const int y = top + 8 + 14 * int(s);
    fill_rect(right - 150, y + 2, right - 136, y + 6, series_color(s), image);
    draw_text(names[s], right - 130, y, kPlotInk, 1, image);
  }
}

}  // namespace unfold
