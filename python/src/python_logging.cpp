#include "python_logging.h"

#include <glog/logging.h>

#include <string>

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

}  // namespace unfold::python
