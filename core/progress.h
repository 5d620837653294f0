// Progress of the long stages (tetrahedralization, the solves, the metrics)
// for a display an app may install, and the solvers' lines of detail (one per
// iteration). The library only reports; whether and how to show it is the
// listener's choice (apps/ knows whether stderr is a terminal and how verbose
// to be, core/terminal_progress.h draws the line, Python logs the details at
// DEBUG).
#pragma once

#include <functional>
#include <ostream>
#include <string>

namespace unfold {

/// Receives the progress reports of the whole process, on the thread that
/// reports (the library reports from its serial parts only).
class ProgressListener {
 public:
  virtual ~ProgressListener() = default;
  /// A stage begins, e.g. "tetrahedralizing", "cascade 2/4, beta 3.2e6".
  virtual void stage(const std::string& name) = 0;
  /// Within the current stage: `done` of at most `total` steps (iterations).
  virtual void step(int done, int total) = 0;
  /// Whether detail() is to be called: the lines are composed only then.
  virtual bool wants_details() const { return false; }
  /// A line of detail within the current stage: an iteration's figures, a
  /// solve's summary (without a newline).
  virtual void detail(const std::string& /*line*/) {}
};

/// Installs `listener` for the whole process (nullptr: none, the default). The
/// caller keeps it alive until it installs another one or nullptr.
void set_progress_listener(ProgressListener* listener);

/// A stage begins: tells the installed listener, if any.
void report_stage(const std::string& name);

/// `done` of at most `total` steps of the current stage: tells the installed
/// listener, if any.
void report_step(int done, int total);

/// A line of detail (an iteration's figures, a solve's summary) for the
/// installed listener, if it wants details: only then does `write` compose it.
void report_detail(const std::function<void(std::ostream&)>& write);

}  // namespace unfold
