// correspond: a dense map between two surfaces (pipeline/match_surfaces.h).
#include <omp.h>
#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include <map>
#include <string>

#include "arrays.h"
#include "config/options.h"
#include "functions.h"
#include "pipeline/match_surfaces.h"

namespace py = pybind11;

namespace unfold::python {

void def_match_functions(py::module_& m) {
  m.def(
      "correspond",
      [](const Vertices& VA, const Elements& FA, const Vertices& VB, const Elements& FB,
         const std::string& config_path, const std::map<std::string, std::string>& overrides) {
        const Options options = load_options(config_path, overrides);
        const SurfaceMesh a = make_surface(VA, FA), b = make_surface(VB, FB);
        ShapeMatch match;
        {
          py::gil_scoped_release nogil;
          if (options.threads > 0) omp_set_num_threads(options.threads);
          match = match_surfaces(a, b, options);
        }
        py::dict d;
        d["map"] = Eigen::VectorXi(match.map);
        d["mirrored"] = match.mirrored;
        d["ambiguous"] = match.ambiguous;
        d["decision"] = match.decision;
        d["margin"] = match.placement_margin;
        d["sure"] = match.sure;
        return d;
      },
      py::arg("VA"), py::arg("FA"), py::arg("VB"), py::arg("FB"), py::arg("config_path"),
      py::arg("overrides"));
}

}  // namespace unfold::python
