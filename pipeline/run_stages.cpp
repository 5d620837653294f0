#include "pipeline/run_stages.h"

#include <glog/logging.h>

#include <algorithm>

namespace unfold {

Stage Stage::when(std::function<bool(const UnfoldState&)> holds) const {
  Stage s = *this;
  s.condition = condition ? [first = condition, holds](
                                const UnfoldState& state) { return first(state) && holds(state); }
                          : std::move(holds);
  return s;
}

Stage Stage::unless(std::function<bool(const UnfoldState&)> holds) const {
  return when([holds](const UnfoldState& state) { return !holds(state); });
}

Stage Stage::on_the_side(bool yes) const {
  Stage s = *this;
  s.beside = yes;
  return s;
}

Stage Stage::joining() const {
  Stage s = *this;
  s.joins = true;
  return s;
}

StageRunner::~StageRunner() {
  for (auto& [record, f] : beside_)
    if (f.valid()) f.wait();
}

void StageRunner::run(const StageList& stages) {
  for (const Stage& stage : stages) {
    if (stage.joins) join();
    if (stage.condition && !stage.condition(*state_)) continue;
    Record& record = records_.emplace_back(Record{stage.name, stage.part, stage.timer, {}, {}});
    record.start = Clock::now();
    if (stage.beside) {
      LOG(INFO) << "stage " << stage.name << ": started beside";
      beside_.emplace_back(&record,
                           std::async(std::launch::async, [this, &record, run = stage.run] {
                             run(*state_);
                             record.end = Clock::now();
                           }));
      continue;
    }
    stage.run(*state_);
    record.end = Clock::now();
    LOG(INFO) << "stage " << stage.name << ": " << record.seconds() << " s";
  }
}

void StageRunner::join() {
  auto pending = std::move(beside_);
  beside_.clear();
  for (auto& [record, f] : pending) {
    f.get();
    LOG(INFO) << "stage " << record->name << ": " << record->seconds() << " s (beside)";
  }
}

std::vector<StageTime> StageRunner::stage_seconds() const {
  std::vector<StageTime> out;
  for (const Record& r : records_) out.push_back({r.name, r.seconds()});
  return out;
}

double StageRunner::sum(StagePart part) const {
  double s = 0;
  for (const Record& r : records_)
    if (r.part == part) s += r.seconds();
  return s;
}

double StageRunner::sum(StageTimer timer) const {
  double s = 0;
  for (const Record& r : records_)
    if (r.timer == timer) s += r.seconds();
  return s;
}

void StageRunner::add_times(PreparedMesh* out) const {
  const std::vector<StageTime> times = stage_seconds();
  out->stage_seconds.insert(out->stage_seconds.end(), times.begin(), times.end());
  out->seconds += sum(StagePart::prepare);
  out->seconds_contact += sum(StageTimer::contact);
}

void StageRunner::add_times(UnfoldResult* out) const {
  const std::vector<StageTime> times = stage_seconds();
  out->stage_seconds.insert(out->stage_seconds.end(), times.begin(), times.end());
  out->seconds_prepare += sum(StagePart::prepare);
  out->seconds_contact += sum(StageTimer::contact);
  out->seconds_lambda2 += sum(StageTimer::lambda2);
  out->seconds_cascade += sum(StageTimer::cascade);
  out->seconds_interior += sum(StageTimer::interior);
  out->seconds_integration += sum(StageTimer::integration);
  out->seconds_anchored += sum(StageTimer::anchored);
  out->metrics.seconds += sum(StagePart::metrics);
  if (std::any_of(records_.begin(), records_.end(),
                  [](const Record& r) { return r.timer == StageTimer::unfolded_tets; }))
    out->tet_report.seconds = sum(StageTimer::unfolded_tets);
  Clock::time_point first = Clock::time_point::max(), last = Clock::time_point::min();
  for (const Record& r : records_)
    if (r.part == StagePart::unfold) {
      first = std::min(first, r.start);
      last = std::max(last, r.end);
    }
  if (first < last) out->seconds_unfold += std::chrono::duration<double>(last - first).count();
}

}  // namespace unfold
