#include <pybind11/stl.h>

#include "arrays.h"
#include "functions.h"
#include "mesh/read_surface_mesh.h"
#include "mesh/read_vts.h"
#include "mesh/write_surface_mesh.h"
#include "shapes/articulated_shape.h"

namespace py = pybind11;

namespace unfold::python {

void def_mesh_functions(py::module_& m) {
  using release = py::call_guard<py::gil_scoped_release>;
  m.def(
      "read_mesh", [](const std::string& path) { return to_arrays(read_surface_mesh(path)); },
      py::arg("path"), release());
  m.def(
      "write_mesh",
      [](const std::string& path, const Vertices& V, const Elements& F) {
        write_surface_mesh(path, make_surface(V, F));
      },
      py::arg("path"), py::arg("V"), py::arg("F"), release());
  m.def(
      "read_vts",
      [](const std::string& path, int vertex_count, int rows) {
        return read_vts(path, vertex_count, rows);
      },
      py::arg("path"), py::arg("vertex_count"), py::arg("rows") = -1, release());
  m.def(
      "demo_shape",
      [](const std::string& pose, int resolution) {
        return to_arrays(make_articulated_shape(ShapePose::named(pose), resolution));
      },
      py::arg("pose"), py::arg("resolution") = kDefaultShapeResolution, release());
}

}  // namespace unfold::python
