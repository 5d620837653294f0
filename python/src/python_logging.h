// The library logs through glog (its stages' lines, warnings) and reports its
// solvers' lines of detail (one per iteration) to a progress listener
// (core/progress.h); in Python both go to the logging module's "unfold" logger
// instead of stderr, the stages' lines at INFO and the details at DEBUG (the
// command line's -v and -vv), so they are silent unless the program configures
// logging.
#pragma once

#include <pybind11/pybind11.h>

namespace unfold::python {

/// Routes every glog message to logging.getLogger("unfold") (INFO, WARNING,
/// ERROR) and nowhere else (no stderr, no log files). Call once at import.
/// Library calls that may log from worker threads must run with the GIL
/// released (the sink takes the GIL to call Python).
void route_glog_to_python_logging();

/// Installs the process's progress listener: the library's lines of detail to
/// logging.getLogger("unfold") at DEBUG, composed only while that logger is
/// enabled for DEBUG (asked at each stage's start, not at every line). Call
/// once at import.
void route_details_to_python_logging();

}  // namespace unfold::python
