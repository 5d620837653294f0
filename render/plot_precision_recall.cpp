#include "render/plot_precision_recall.h"

#include "core/errors.h"
#include "render/draw_2d.h"
#include "render/plot_axes.h"

namespace unfold {

Image plot_precision_recall(const std::vector<PrecisionRecallSeries>& series,
                            const std::string& title, int width, int height) {
  if (series.empty()) throw UsageError("plot_precision_recall: no series");
  if (width < 200 || height < 200)
    throw UsageError("plot_precision_recall: the plot needs at least 200 x 200 pixels");
  for (const auto& [name, precision] : series) {
    if (precision.size() < 2)
      throw UsageError("plot_precision_recall: series '" + name + "' has fewer than 2 values");
    for (double p : precision)
      if (!(p >= 0 && p <= 1))
        throw UsageError("plot_precision_recall: series '" + name + "' has a value outside [0, 1]");
  }
  Image image(width, height);
  const int left = 60, right = width - 20, top = 36, bottom = height - 44;
  const PlotAxes a = draw_plot_axes(left, top, right, bottom, 0, 1, 0, 1, title, false, &image);
  std::vector<std::string> names;
  for (size_t s = 0; s < series.size(); ++s) {
    const std::vector<double>& p = series[s].second;
    const double levels = double(p.size());
    for (size_t k = 1; k < p.size(); ++k)
      draw_line(a.px(double(k) / levels), a.py(p[k - 1]), a.px(double(k + 1) / levels), a.py(p[k]),
                series_color(s), 2, &image);
    names.push_back(series[s].first);
  }
  draw_legend(names, right, top, &image);
  const std::string xlabel = "recall";
  draw_text(xlabel, (left + right - text_size(xlabel, 1).first) / 2, height - 18, {40, 40, 40}, 1,
            &image);
  return image;
}

}  // namespace unfold
