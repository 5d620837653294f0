// The text of a progress line and when to redraw it: the parts of
// core/terminal_progress.h that do not touch a terminal or a clock.
#pragma once

#include <cstddef>
#include <string>

namespace unfold {

/// What a progress line shows.
struct ProgressState {
  std::string stage;  ///< e.g. "cascade 1/4, beta 1.3e+06"; "" before the first
  std::string unit;   ///< what the steps count, e.g. "iteration", "shapes"
  int done = 0;       ///< steps done of the stage
  int total = 0;      ///< steps at most; 0: the stage has no steps to show
};

/// "1.5 s" below a minute, "3m05s" from there.
std::string format_elapsed(double seconds);

/// "<app>: <stage>: <unit> <done>/<total>, <elapsed>", the step part only when
/// total > 0, the stage only when not empty; cut to `width` characters (a
/// line longer than the terminal would wrap, and "\r" then rewrites only its
/// last row).
std::string format_progress_line(const std::string& app, const ProgressState& state,
                                 double elapsed_seconds, size_t width = 79);

/// When to redraw: the first time, when forced (a new stage), and otherwise
/// at most once per `interval` seconds (a solver may report hundreds of
/// iterations a second; the terminal need not show them all).
class RedrawThrottle {
 public:
  explicit RedrawThrottle(double interval) : interval_(interval) {}
  /// Whether to draw at `now` (seconds on a steady clock); records the draw if so.
  bool due(double now, bool forced);

 private:
  double interval_;
  double last_ = 0;
  bool drawn_ = false;
};

}  // namespace unfold
