#include "render/plot_cdf.h"

#include <algorithm>
#include <cmath>

#include "core/errors.h"
#include "render/draw_2d.h"
#include "render/plot_axes.h"

namespace unfold {

Image plot_cdf(const std::vector<CdfSeries>& series, const std::string& xlabel, int width,
               int height) {
  if (series.empty()) throw UsageError("plot_cdf: no series");
  if (width < 200 || height < 200)
    throw UsageError("plot_cdf: the plot needs at least 200 x 200 pixels");
  double xmax = 0;
  for (const auto& [name, values] : series) {
    if (values.empty()) throw UsageError("plot_cdf: series '" + name + "' has no values");
    for (double v : values) {
      if (!std::isfinite(v))
        throw UsageError("plot_cdf: series '" + name + "' has a non-finite value");
      xmax = std::max(xmax, v);
    }
  }
  if (xmax <= 0) xmax = 1;
  Image image(width, height);
  const int left = 60, right = width - 20, top = 36, bottom = height - 44;
  const PlotAxes a = draw_plot_axes(left, top, right, bottom, 0, xmax * 1.02, 0, 1,
                                    "cumulative fraction of shapes", false, &image);
  const Rgb ink{40, 40, 40};
  for (size_t s = 0; s < series.size(); ++s) {
    const Rgb color = series_color(s);
    std::vector<double> v = series[s].second;
    std::sort(v.begin(), v.end());
    double x = 0, y = 0;
    for (size_t k = 0; k < v.size(); ++k) {
      const double next_y = double(k + 1) / double(v.size());
      draw_line(a.px(x), a.py(y), a.px(v[k]), a.py(y), color, 2, &image);
      draw_line(a.px(v[k]), a.py(y), a.px(v[k]), a.py(next_y), color, 2, &image);
      x = v[k];
      y = next_y;
    }
    draw_line(a.px(x), a.py(y), a.x1, a.py(y), color, 2, &image);
  }
  std::vector<std::string> names;
  for (const auto& s : series) names.push_back(s.first);
  draw_legend(names, right, top, &image);
  draw_text(xlabel, (left + right - text_size(xlabel, 1).first) / 2, height - 18, ink, 1, &image);
  return image;
}

}  // namespace unfold
