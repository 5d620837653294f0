// An app's progress line on a terminal: one line rewritten in place ("\r",
// erase to the end of the line) with the current stage, its steps and the
// elapsed time, and whole lines (log lines, results) printed above it. Whether
// the stream is a terminal is the app's decision (apps/app_main.h): inactive,
// nothing is drawn and the lines are printed as they come.
#pragma once

#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <mutex>
#include <string>
#include <thread>

#include "core/progress.h"
#include "core/progress_line.h"

namespace unfold {

class TerminalProgress : public ProgressListener {
 public:
  /// @param app    name at the start of the line ("unfold")
  /// @param out    the stream the line is drawn on (stderr)
  /// @param active draw the line (`out` is a terminal); false: print_line only
  /// @param tick   seconds between redraws by a thread of its own, so that the
  ///               elapsed time runs on through a long stage that reports
  ///               nothing (TetGen); 0: no thread, redraws on reports and
  ///               redraw_if_due() only
  TerminalProgress(std::string app, std::FILE* out, bool active, double tick = 0);
  /// Stops the thread and erases the line (finish()).
  ~TerminalProgress() override;
  TerminalProgress(const TerminalProgress&) = delete;
  TerminalProgress& operator=(const TerminalProgress&) = delete;

  bool active() const { return active_; }
  /// A new stage, drawn at once; its steps count `unit` ("iteration" unless set).
  void stage(const std::string& name) override;
  /// Steps of the current stage, drawn at most every 0.1 s.
  void step(int done, int total) override;
  /// The whole state at once (a batch's shapes), drawn at once.
  void set(const ProgressState& state);
  /// Redraws if 0.1 s have passed since the last draw (the elapsed time), for
  /// callers that wait in a loop.
  void redraw_if_due();
  /// `line` (without its newline) printed to `to` above the progress line: the
  /// line is erased first and drawn again after.
  void print_line(const std::string& line, std::FILE* to);
  /// Erases the line and stops drawing (and the thread); print_line still prints.
  void finish();

 private:
  double elapsed() const;
  void draw_locked(bool forced);
  void erase_locked();

  const std::string app_;
  std::FILE* const out_;
  bool active_;
  const std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
  std::mutex mutex_;
  ProgressState state_;
  RedrawThrottle throttle_{0.1};
  bool shown_ = false;  ///< the line is on the terminal
  std::condition_variable wake_;
  bool stopping_ = false;
  std::thread ticker_;
};

}  // namespace unfold
