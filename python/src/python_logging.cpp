#include "python_logging.h"

#include <glog/logging.h>

#include <atomic>
#include <string>

#include "core/progress.h"

namespace py = pybind11;

namespace unfold::python {
namespace {

class PythonLogSink : public google::LogSink {
 public:
  void send(google::LogSeverity severity, const char*, const char*, int, const struct ::tm*,
            const char* message, size_t message_len) override {
    py::gil_scoped_acquire gil;
    try {
      // Python's levels: INFO 20, WARNING 30, ERROR 40, CRITICAL 50.
      py::module_::import("logging").attr("getLogger")("unfold").attr("log")(
          20 + 10 * severity, std::string(message, message_len));
    } catch (py::error_already_set& e) {
      e.discard_as_unraisable("unfold log message");
    }
  }
};

// Python's DEBUG level.
constexpr int kDebug = 10;

class PythonDetails : public ProgressListener {
 public:
  PythonDetails() { refresh(); }
  // Whether the logger listens at DEBUG is asked here, once per stage: asking
  // at every line would take the GIL every iteration of a solve.
  void stage(const std::string& /*name*/) override { refresh(); }
  void step(int /*done*/, int /*total*/) override {}
  bool wants_details() const override { return debug_.load(); }
  void detail(const std::string& line) override {
    py::gil_scoped_acquire gil;
    try {
      py::module_::import("logging").attr("getLogger")("unfold").attr("log")(kDebug, line);
    } catch (py::error_already_set& e) {
      e.discard_as_unraisable("unfold log message");
    }
  }

 private:
  void refresh() {
    py::gil_scoped_acquire gil;
    try {
      debug_.store(py::module_::import("logging")
                       .attr("getLogger")("unfold")
                       .attr("isEnabledFor")(kDebug)
                       .cast<bool>());
    } catch (py::error_already_set& e) {
      e.discard_as_unraisable("unfold log level");
    }
  }

  std::atomic<bool> debug_{false};
};

}  // namespace

void route_glog_to_python_logging() {
  static PythonLogSink sink;
  if (!google::IsGoogleLoggingInitialized()) google::InitGoogleLogging("unfold");
  FLAGS_logtostderr = false;
  FLAGS_alsologtostderr = false;
  FLAGS_stderrthreshold = google::NUM_SEVERITIES;
  for (int severity = 0; severity < google::NUM_SEVERITIES; ++severity)
    google::SetLogDestination(severity, "");  // "" = no log file
  google::AddLogSink(&sink);
  // After interpreter shutdown the sink must not call Python any more.
  py::module_::import("atexit").attr("register")(
      py::cpp_function([] { google::RemoveLogSink(&sink); }));
}

void route_details_to_python_logging() {
  static PythonDetails listener;
  set_progress_listener(&listener);
  py::module_::import("atexit").attr("register")(
      py::cpp_function([] { set_progress_listener(nullptr); }));
}

}  // namespace unfold::python
