// _core: the C++ half of the Python package unfold (python/unfold/ is the
// other half: argument checks, config dictionaries, the Result class).
#include "errors.h"
#include "functions.h"
#include "python_logging.h"

PYBIND11_MODULE(_core, m) {
  m.doc() = "unfold's library functions; use the package unfold, which checks the arguments";
  unfold::python::register_errors(m);
  unfold::python::route_glog_to_python_logging();
  unfold::python::route_details_to_python_logging();
  unfold::python::def_mesh_functions(m);
  unfold::python::def_unfold_functions(m);
  unfold::python::def_metric_functions(m);
  unfold::python::def_match_functions(m);
}
