#include "core/progress_line.h"

#include <cstdio>

namespace unfold {

std::string format_elapsed(double seconds) {
  char text[32];
  if (seconds < 60) {
    std::snprintf(text, sizeof text, "%.1f s", seconds);
  } else {
    const long total = long(seconds);
    std::snprintf(text, sizeof text, "%ldm%02lds", total / 60, total % 60);
  }
  return text;
}

std::string format_progress_line(const std::string& app, const ProgressState& state,
                                 double elapsed_seconds, size_t width) {
  std::string steps;
  if (state.total > 0)
    steps = state.unit + (state.unit.empty() ? "" : " ") + std::to_string(state.done) + "/" +
            std::to_string(state.total);
  std::string tail = (steps.empty() ? "" : steps + ", ") + format_elapsed(elapsed_seconds);
  std::string stage = state.stage;
  // The stage is what gives way to a narrow terminal; the counts and the time stay.
  const size_t fixed = app.size() + 2 + tail.size() + (stage.empty() ? 0 : 2);
  if (!stage.empty() && fixed + stage.size() > width)
    stage.resize(fixed + 3 < width ? width - fixed - 3 : 0), stage += "...";
  std::string line =
      app + ": " + (stage.empty() ? "" : stage + (steps.empty() ? ", " : ": ")) + tail;
  if (line.size() > width) line.resize(width);
  return line;
}

bool RedrawThrottle::due(double now, bool forced) {
  if (drawn_ && !forced && now - last_ < interval_) return false;
  drawn_ = true;
  last_ = now;
  return true;
}

}  // namespace unfold
