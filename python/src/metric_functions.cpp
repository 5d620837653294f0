#include <pybind11/stl.h>

#include "arrays.h"
#include "functions.h"
#include "mesh/edge_graph.h"
#include "metrics/geodesic_error.h"
#include "metrics/ort_dissimilarity.h"
#include "metrics/pose_invariance.h"
#include "metrics/retrieval_measures.h"
#include "metrics/rigidity_error.h"
#include "metrics/shape_retrieval.h"
#include "metrics/stretch_error.h"
#include "metrics/surface_damage.h"
#include "metrics/surface_folds.h"
#include "pipeline/cmbof_matrix.h"

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
      "surface_damage",
      [](const Vertices& rest, const Vertices& deformed, const Elements& F, double bound) {
        SurfaceDamage d;
        {
          py::gil_scoped_release unlocked;
          d = surface_damage(rest, deformed, Eigen::MatrixXi(F), bound);
        }
        py::dict r;  // the metrics JSON's keys (pipeline/metrics_json.cpp)
        r["damaged_edges_percent"] = d.damaged_edges_percent;
        r["surface_edge_ratio_p999"] = d.ratio_p999;
        r["surface_edge_ratio_max"] = d.ratio_max;
        r["surface_edge_ratio_min"] = d.ratio_min;
        r["damaged_surface_edges"] = d.damaged_edges;
        r["surface_edges_measured"] = d.edges;
        r["zero_length_surface_edges"] = d.zero_length_edges;
        r["scale"] = d.scale;
        r["per_vertex"] = Eigen::VectorXd(d.per_vertex);
        return r;
      },
      py::arg("rest"), py::arg("deformed"), py::arg("F"), py::arg("bound") = kDamagedEdgeRatio);
  m.def(
      "surface_folds",
      [](const Vertices& rest, const Vertices& deformed, const Elements& F, double bound) {
        SurfaceFolds f;
        {
          py::gil_scoped_release unlocked;
          f = surface_folds(rest, deformed, triangulate_faces(make_surface(rest, F)), bound);
        }
        py::dict r;  // the metrics JSON's keys (pipeline/metrics_json.cpp)
        r["folded_edges_percent"] = f.folded_edges_percent;
        r["folded_surface_edges"] = f.folded_edges;
        r["dihedral_change_p999_degrees"] = f.dihedral_change_p999;
        r["dihedral_change_max_degrees"] = f.dihedral_change_max;
        r["surface_edges_measured"] = f.edges;
        r["per_vertex"] = Eigen::VectorXd(f.per_vertex);
        return r;
      },
      py::arg("rest"), py::arg("deformed"), py::arg("F"),
      py::arg("bound") = kFoldedDihedralChange);
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
  m.def(
      "ort_distance",
      [](const Vertices& A, const Elements& FA, const Vertices& B, const Elements& FB,
         int sample_points, int icp_iterations) {
        const SurfaceMesh a = make_surface(A, FA), b = make_surface(B, FB);
        return ort_dissimilarity(ort_sample(a.V, triangulate_faces(a), sample_points),
                                 ort_sample(b.V, triangulate_faces(b), sample_points),
                                 icp_iterations);
      },
      py::arg("A"), py::arg("FA"), py::arg("B"), py::arg("FB"),
      py::arg("sample_points") = RetrievalOptions().sample_points,
      py::arg("icp_iterations") = RetrievalOptions().icp_iterations, release());
  m.def(
      "cmbof_matrix",
      [](const std::vector<std::pair<Vertices, Elements>>& shapes, int view_subdivisions,
         int image_size, int words) {
        std::vector<SurfaceMesh> meshes;
        for (const auto& [V, F] : shapes) meshes.push_back(make_surface(V, F));
        CmbofOptions options;
        options.view_subdivisions = view_subdivisions, options.image_size = image_size;
        options.words = words;
        return cmbof_matrix(meshes, options);
      },
      py::arg("shapes"), py::arg("view_subdivisions") = CmbofOptions().view_subdivisions,
      py::arg("image_size") = CmbofOptions().image_size, py::arg("words") = CmbofOptions().words,
      release());
  m.def(
      "retrieval_measures",
      [](const Eigen::MatrixXd& D, const std::vector<std::string>& classes) {
        RetrievalMeasures r;
        {
          py::gil_scoped_release unlocked;
          r = retrieval_measures(D, classes);
        }
        std::vector<double> recall;
        for (int k = 1; k <= kRecallLevels; ++k) recall.push_back(double(k) / kRecallLevels);
        py::dict d;
        d["nn"] = r.nn, d["first_tier"] = r.first_tier, d["second_tier"] = r.second_tier;
        d["e_measure"] = r.e_measure, d["dcg"] = r.dcg, d["queries"] = r.queries;
        d["recall"] = recall, d["precision"] = r.precision;
        return d;
      },
      py::arg("D"), py::arg("classes"));
}

}  // namespace unfold::python
