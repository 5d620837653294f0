#include "core/progress.h"

#include <atomic>
#include <sstream>

namespace unfold {
namespace {

std::atomic<ProgressListener*> installed{nullptr};

}  // namespace

void set_progress_listener(ProgressListener* listener) { installed.store(listener); }

void report_stage(const std::string& name) {
  if (ProgressListener* listener = installed.load()) listener->stage(name);
}

void report_step(int done, int total) {
  if (ProgressListener* listener = installed.load()) listener->step(done, total);
}

void report_detail(const std::function<void(std::ostream&)>& write) {
  ProgressListener* listener = installed.load();
  if (!listener || !listener->wants_details()) return;
  std::ostringstream line;
  write(line);
  listener->detail(line.str());
}

}  // namespace unfold
