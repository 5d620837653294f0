#include "arrays.h"
#include "functions.h"
#include "mesh/edge_graph.h"
#include "metrics/geodesic_error.h"
#include "metrics/pose_invariance.h"
#include "metrics/rigidity_error.h"
#include "metrics/shape_retrieval.h"
#include "metrics/stretch_error.h"

namespace py = pybind11;

namespace unfold::python {

void def_metric_functions(py::module_& m) {
  using release = py::call_guard<py::gil_scoped_release>;
  m.def(
      "e_rig",
      [](const Vertices& rest, const Vertices& deformed, const Elements& elements) {
        return rigidity_error(build_edge_graph(int(rest.rows()), elements), rest, deformed).mean;
      },
      py::arg("rest"), py::arg("deformed"), py::arg("elements"), release());
  m.def(
      "e_str",
      [](const Vertices& rest, const Vertices& deformed, int exact_limit, int64_t samples) {
        return stretch_error(rest, deformed, StretchErrorOptions{exact_limit, samples}).value;
      },
      py::arg("rest"), py::arg("deformed"),
      py::arg("exact_limit") = StretchErrorOptions().exact_limit,
      py::arg("samples") = StretchErrorOptions().sample_pairs, release());
  m.def(
      "e_geo",
      [](const Vertices& rest, const Vertices& deformed, const Elements& elements, int exact_limit,
         int landmarks) {
        return geodesic_error(build_edge_graph(int(rest.rows()), elements), rest, deformed,
                              GeodesicErrorOptions{exact_limit, landmarks})
            .value;
      },
      py::arg("rest"), py::arg("deformed"), py::arg("elements"),
      py::arg("exact_limit") = GeodesicErrorOptions().exact_limit,
      py::arg("landmarks") = GeodesicErrorOptions().sources, release());
  m.def(
      "surface_area",
      [](const Vertices& V, const Elements& F) { return surface_area(make_surface(V, F)); },
      py::arg("V"), py::arg("F"), release());
  m.def(
      "pose_distance",
      [](const Vertices& A, const Vertices& B, const Elements& F) {
        return pose_distance(A, B, triangulate_faces(make_surface(A, F)));
      },
      py::arg("A"), py::arg("B"), py::arg("F"), release());
  m.def(
      "pose_distance_on_rows",
      [](const Vertices& A, const Elements& F_A, const Eigen::VectorXi& rows_a, const Vertices& B,
         const Elements& F_B, const Eigen::VectorXi& rows_b) {
        return pose_distance(A, triangulate_faces(make_surface(A, F_A)), rows_a, B,
                             triangulate_faces(make_surface(B, F_B)), rows_b);
      },
      py::arg("A"), py::arg("F_A"), py::arg("rows_a"), py::arg("B"), py::arg("F_B"),
      py::arg("rows_b"), release());
  m.def(
      "retrieval_distance",
      [](const Vertices& A, const Vertices& B, int sample_points, int icp_iterations) {
        const RetrievalOptions options{sample_points, icp_iterations};
        return shape_dissimilarity(retrieval_sample(A, options), retrieval_sample(B, options),
                                   options);
      },
      py::arg("A"), py::arg("B"), py::arg("sample_points") = RetrievalOptions().sample_points,
      py::arg("icp_iterations") = RetrievalOptions().icp_iterations, release());
}

}  // namespace unfold::python
