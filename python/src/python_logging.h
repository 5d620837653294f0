// The library logs through glog (progress per cascade, warnings); in Python
// those lines go to the logging module's "unfold" logger instead of stderr,
// so they are silent unless the program configures logging.
#pragma once

#include <pybind11/pybind11.h>

namespace unfold::python {

/// Routes every glog message to logging.getLogger("unfold") (INFO, WARNING,
/// ERROR) and nowhere else (no stderr, no log files). Call once at import.
/// Library calls that may log from worker threads must run with the GIL
/// released (the sink takes the GIL to call Python).
void route_glog_to_python_logging();

}  // namespace unfold::python
