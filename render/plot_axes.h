// Axes shared by the line plots (convergence, CDFs): 1-2-5 ticks, a frame
// with grid lines, tick labels and a title.
#pragma once

#include <string>
#include <vector>

#include "render/image.h"

namespace unfold {

/// The plots' text and frame colour.
inline constexpr Rgb kPlotInk{40, 40, 40};

/// A plot area in pixels and the data range it shows.
struct PlotAxes {
  int x0, y0, x1, y1;
  double xmin, xmax, ymin, ymax;
  double px(double x) const { return x0 + (x - xmin) / (xmax - xmin) * (x1 - x0); }
  double py(double y) const { return y1 - (y - ymin) / (ymax - ymin) * (y1 - y0); }
};

/// Tick positions at 1, 2 or 5 times a power of ten, about `count` of them in [lo, hi].
/// @pre hi > lo, count >= 1
std::vector<double> plot_ticks(double lo, double hi, int count);

/// A tick value as short text (%.4g).
std::string tick_label(double x);

/// Draws the frame, horizontal grid, tick labels and title of one plot area
/// and returns its axes; the y range is padded by 5% (and widened if empty).
/// @param integer_x label only whole-number x ticks (e.g. iterations)
PlotAxes draw_plot_axes(int x0, int y0, int x1, int y1, double xmin, double xmax, double ymin,
                        double ymax, const std::string& title, bool integer_x, Image* image);

/// The colour of the k-th series of a plot (cycling through six).
Rgb series_color(size_t k);

/// A legend in the top right of a plot whose right edge is `right` and top
/// edge `top`: a colour swatch and the name of each series.
void draw_legend(const std::vector<std::string>& names, int right, int top, Image* image);

}  // namespace unfold
