// The progress line: its text, when it is redrawn, what reaches a terminal and
// what a file gets, and that the library's reports reach the installed listener.
#include "core/progress.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "core/progress_line.h"
#include "core/terminal_progress.h"

namespace unfold {
namespace {

TEST(ProgressLine, ElapsedInSecondsThenMinutes) {
  EXPECT_EQ(format_elapsed(0.04), "0.0 s");
  EXPECT_EQ(format_elapsed(12.36), "12.4 s");
  EXPECT_EQ(format_elapsed(59.9), "59.9 s");
  EXPECT_EQ(format_elapsed(60.0), "1m00s");
  EXPECT_EQ(format_elapsed(185.7), "3m05s");
}

TEST(ProgressLine, StageStepsAndElapsed) {
  EXPECT_EQ(
      format_progress_line("unfold", {"cascade 1/4, beta 1.3e+06", "iteration", 15, 300}, 2.31),
      "unfold: cascade 1/4, beta 1.3e+06: iteration 15/300, 2.3 s");
  EXPECT_EQ(format_progress_line("unfold", {"tetrahedralizing 7938 faces", "iteration", 0, 0}, 0.5),
            "unfold: tetrahedralizing 7938 faces, 0.5 s");
  EXPECT_EQ(format_progress_line("unfold_batch", {"", "shapes", 3, 40}, 65),
            "unfold_batch: shapes 3/40, 1m05s");
  EXPECT_EQ(format_progress_line("unfold", {"", "", 0, 0}, 1), "unfold: 1.0 s");
}

TEST(ProgressLine, NarrowTerminalShortensTheStageNotTheCounts) {
  const std::string line =
      format_progress_line("unfold", {std::string(200, 's'), "iteration", 15, 300}, 2.31, 60);
  EXPECT_EQ(line.size(), 60u);
  EXPECT_EQ(line.substr(0, 10), "unfold: ss");
  const std::string tail = "...: iteration 15/300, 2.3 s";
  EXPECT_EQ(line.substr(line.size() - tail.size()), tail);
}

TEST(ProgressLine, ThrottleDrawsFirstForcedAndThenOncePerInterval) {
  RedrawThrottle throttle(0.1);
  EXPECT_TRUE(throttle.due(5.0, false));    // the first draw
  EXPECT_FALSE(throttle.due(5.05, false));  // too soon
  EXPECT_TRUE(throttle.due(5.06, true));    // a new stage: at once
  EXPECT_FALSE(throttle.due(5.15, false));  // 0.09 s after the forced one
  EXPECT_TRUE(throttle.due(5.17, false));
  EXPECT_FALSE(throttle.due(5.17, false));
}

// What a TerminalProgress wrote to a temporary file.
std::string written(std::FILE* file) {
  std::fflush(file);
  std::rewind(file);
  std::string text;
  for (int c; (c = std::fgetc(file)) != EOF;) text += char(c);
  return text;
}

TEST(TerminalProgress, OnATerminalTheLineIsRewrittenAndLinesGoAboveIt) {
  std::FILE* out = std::tmpfile();
  ASSERT_NE(out, nullptr);
  {
    TerminalProgress progress("unfold", out, true);
    progress.print_line("before any stage", out);  // nothing drawn yet: nothing to erase
    progress.stage("tetrahedralizing 12 faces");
    progress.print_line("unfold: tetrahedralized", out);
  }
  const std::string text = written(out);
  std::fclose(out);
  const std::string erase = "\r\033[K";
  ASSERT_EQ(text.rfind("before any stage\n" + erase + "unfold: tetrahedralizing 12 faces, ", 0), 0u)
      << text;
  // The log line erases the progress line, which is drawn again below it;
  // the end erases it for good.
  const size_t log = text.find(erase + "unfold: tetrahedralized\n" + erase +
                               "unfold: tetrahedralizing 12 faces, ");
  EXPECT_NE(log, std::string::npos) << text;
  EXPECT_EQ(text.substr(text.size() - erase.size()), erase);
}

TEST(TerminalProgress, ElsewhereOnlyTheLines) {
  std::FILE* out = std::tmpfile();
  ASSERT_NE(out, nullptr);
  {
    TerminalProgress progress("unfold", out, false);
    progress.stage("tetrahedralizing 12 faces");
    progress.step(3, 10);
    progress.set({"unfolding (2 running)", "shapes", 1, 4});
    progress.redraw_if_due();
    progress.print_line("unfold: tetrahedralized", out);
  }
  EXPECT_EQ(written(out), "unfold: tetrahedralized\n");
  std::fclose(out);
}

// Records what the library reports.
class Recorder : public ProgressListener {
 public:
  void stage(const std::string& name) override { events.push_back(name); }
  void step(int done, int total) override {
    events.push_back(std::to_string(done) + "/" + std::to_string(total));
  }
  std::vector<std::string> events;
};

TEST(Progress, ReportsReachTheInstalledListenerOnly) {
  Recorder recorder;
  report_stage("unheard");
  set_progress_listener(&recorder);
  report_stage("cascade 1/1");
  report_step(1, 300);
  set_progress_listener(nullptr);
  report_step(2, 300);
  EXPECT_EQ(recorder.events, (std::vector<std::string>{"cascade 1/1", "1/300"}));
}

// Records the lines of detail when it wants them.
class DetailRecorder : public Recorder {
 public:
  bool wants_details() const override { return wanted; }
  void detail(const std::string& line) override { events.push_back(line); }
  bool wanted = false;
};

TEST(Progress, DetailsAreComposedOnlyForAListenerThatWantsThem) {
  int composed = 0;
  const auto iteration = [&composed](std::ostream& line) {
    ++composed;
    line << "iteration " << 3 << " energy " << 1.5;
  };
  report_detail(iteration);  // none installed
  DetailRecorder recorder;
  set_progress_listener(&recorder);
  report_detail(iteration);  // not wanted
  recorder.wanted = true;
  report_detail(iteration);
  set_progress_listener(nullptr);
  EXPECT_EQ(composed, 1);
  EXPECT_EQ(recorder.events, (std::vector<std::string>{"iteration 3 energy 1.5"}));
}

}  // namespace
}  // namespace unfold
