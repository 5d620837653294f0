// The one loop that runs a method's stages (pipeline/unfold_method.h): it alone
// times them, logs them and records their seconds in the result.
#pragma once

#include <chrono>
#include <deque>
#include <functional>
#include <future>
#include <string>
#include <utility>
#include <vector>

#include "pipeline/unfold_surface.h"

namespace unfold {

struct UnfoldState;  // pipeline/unfold_state.h

/// Which total of the result a stage's seconds count in.
enum class StagePart { prepare, unfold, metrics };

/// Which seconds_* field of UnfoldResult a stage's seconds add to, if any.
enum class StageTimer {
  none,
  contact,        ///< seconds_contact
  lambda2,        ///< seconds_lambda2
  cascade,        ///< seconds_cascade
  unfolded_tets,  ///< tet_report.seconds (the unfolded shape's tets)
  interior,       ///< seconds_interior
  integration,    ///< seconds_integration
  anchored,       ///< seconds_anchored
};

/// One step of a method: a stage function (stages/) applied to the state.
struct Stage {
  std::string name;
  std::function<void(UnfoldState&)> run;
  StagePart part = StagePart::unfold;
  StageTimer timer = StageTimer::none;
  /// run only when this holds of the state when the stage's turn comes (after
  /// the join, for a stage that joins); empty: always
  std::function<bool(const UnfoldState&)> condition;
  /// runs on another thread beside the stages after it, until one that joins
  /// (or the end): it must touch none of what they read or write
  bool beside = false;
  bool joins = false;  ///< waits for the stages running beside first

  /// this stage run only when `holds` too
  Stage when(std::function<bool(const UnfoldState&)> holds) const;
  /// this stage run only when `holds` does not
  Stage unless(std::function<bool(const UnfoldState&)> holds) const;
  Stage on_the_side(bool yes = true) const;
  Stage joining() const;
};

using StageList = std::vector<Stage>;

/// Runs stage lists on one state, in order, and records each stage's seconds.
class StageRunner {
 public:
  explicit StageRunner(UnfoldState* state) : state_(state) {}
  StageRunner(const StageRunner&) = delete;
  StageRunner& operator=(const StageRunner&) = delete;
  ~StageRunner();

  /// Runs the stages whose condition holds; a stage run beside may still run
  /// on return. @throws what a stage throws (a stage beside: when joined)
  void run(const StageList& stages);
  /// Waits for the stages running beside. @throws what they threw
  void join();

  /// The stages run, in list order, with their seconds.
  std::vector<StageTime> stage_seconds() const;
  /// Sums of the stages' seconds by part (unfold: wall seconds from its first
  /// stage's start to its last's end) and by timer, into `out`.
  void add_times(PreparedMesh* out) const;
  void add_times(UnfoldResult* out) const;

 private:
  using Clock = std::chrono::steady_clock;
  struct Record {
    std::string name;
    StagePart part;
    StageTimer timer;
    Clock::time_point start, end;
    double seconds() const { return std::chrono::duration<double>(end - start).count(); }
  };
  double sum(StagePart part) const;
  double sum(StageTimer timer) const;

  UnfoldState* state_;
  std::deque<Record> records_;  // a deque: the stages beside write their end meanwhile
  std::vector<std::pair<const Record*, std::future<void>>> beside_;
};

}  // namespace unfold
