#include "core/terminal_progress.h"

#include <utility>

namespace unfold {

TerminalProgress::TerminalProgress(std::string app, std::FILE* out, bool active, double tick)
    : app_(std::move(app)), out_(out), active_(active) {
  state_.unit = "iteration";
  if (!active_ || !(tick > 0)) return;
  ticker_ = std::thread([this, tick] {
    std::unique_lock<std::mutex> lock(mutex_);
    while (!wake_.wait_for(lock, std::chrono::duration<double>(tick), [this] { return stopping_; }))
      draw_locked(true);
  });
}

TerminalProgress::~TerminalProgress() { finish(); }

double TerminalProgress::elapsed() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

void TerminalProgress::draw_locked(bool forced) {
  const bool nothing_yet = state_.stage.empty() && state_.total == 0;
  if (!active_ || nothing_yet || !throttle_.due(elapsed(), forced)) return;
  std::fprintf(out_, "\r\033[K%s", format_progress_line(app_, state_, elapsed()).c_str());
  std::fflush(out_);
  shown_ = true;
}

void TerminalProgress::erase_locked() {
  if (!shown_) return;
  std::fputs("\r\033[K", out_);
  std::fflush(out_);
  shown_ = false;
}

void TerminalProgress::stage(const std::string& name) {
  std::lock_guard<std::mutex> lock(mutex_);
  state_.stage = name;
  state_.done = state_.total = 0;
  draw_locked(true);
}

void TerminalProgress::step(int done, int total) {
  std::lock_guard<std::mutex> lock(mutex_);
  state_.done = done;
  state_.total = total;
  draw_locked(false);
}

void TerminalProgress::set(const ProgressState& state) {
  std::lock_guard<std::mutex> lock(mutex_);
  state_ = state;
  draw_locked(true);
}

void TerminalProgress::redraw_if_due() {
  std::lock_guard<std::mutex> lock(mutex_);
  draw_locked(false);
}

void TerminalProgress::print_line(const std::string& line, std::FILE* to) {
  std::lock_guard<std::mutex> lock(mutex_);
  const bool was_shown = shown_;
  erase_locked();
  std::fprintf(to, "%s\n", line.c_str());
  std::fflush(to);
  if (was_shown) draw_locked(true);
}

void TerminalProgress::finish() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
    erase_locked();
    active_ = false;
  }
  wake_.notify_all();
  if (ticker_.joinable()) ticker_.join();
}

}  // namespace unfold
