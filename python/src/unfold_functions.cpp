#include <omp.h>
#include <pybind11/stl.h>

#include <map>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include "arrays.h"
#include "config/config_keys.h"
#include "config/options.h"
#include "functions.h"
#include "json_to_python.h"
#include "pipeline/compare_configs.h"
#include "pipeline/metrics_json.h"
#include "pipeline/prepare_mesh_from_tets.h"
#include "pipeline/tet_fields.h"
#include "pipeline/unfold_surface.h"

namespace py = pybind11;

namespace unfold::python {
namespace {

using Overrides = std::map<std::string, std::string>;

py::dict named_fields(const std::vector<std::pair<std::string, Eigen::VectorXd>>& fields) {
  py::dict dict;
  for (const auto& [name, values] : fields) dict[py::str(name)] = values;
  return dict;
}

// The run as the arrays and dictionaries unfold.Result is made of.
py::dict result_dict(const UnfoldResult& r, const TetMeshFields& fields, const Options& options) {
  py::dict d;
  d["vertices"] = Vertices(r.canonical.V);
  d["faces"] = Elements(triangulate_faces(r.canonical));
  d["metrics"] = to_python(metrics_document(r, options));
  d["tet_vertices"] = Vertices(r.tet_canonical);
  d["tets"] = Elements(r.tets.T);
  d["rest_tet_vertices"] = Vertices(r.tets.V);
  d["unfolded_tet_vertices"] = Vertices(r.unfolded_tet_positions);
  d["tet_vertex_fields"] = named_fields(fields.per_vertex);
  d["tet_fields"] = named_fields(fields.per_tet);
  d["skeleton_nodes"] = Vertices(r.skeleton.nodes);
  d["skeleton_edges"] = Elements(r.skeleton.edges);
  d["canonical_skeleton_nodes"] = Vertices(r.skeleton_canonical);
  return d;
}

// As the CLI: the options' thread count for this thread's parallel regions.
void use_threads(const Options& options) {
  if (options.threads > 0) omp_set_num_threads(options.threads);
}

}  // namespace

void def_unfold_functions(py::module_& m) {
  m.def("config_keys", [] {
    std::vector<std::tuple<std::string, std::string, std::string>> keys;
#define UNFOLD_LIST_KEY(flag, path, member, help) keys.emplace_back(#flag, path, help);
    UNFOLD_CONFIG_KEYS(UNFOLD_LIST_KEY)
#undef UNFOLD_LIST_KEY
    return keys;
  });
  m.def("fixed_beta_overrides", &fixed_beta_overrides, py::arg("relative_beta"));
  m.def(
      "unfold",
      [](const Vertices& V, const Elements& F, const std::string& config_path,
         const Overrides& overrides, const std::optional<Elements>& tets,
         const std::optional<Vertices>& tet_vertices,
         const std::optional<Vertices>& unfolded_tet_vertices) {
        const Options options = load_options(config_path, overrides);
        const SurfaceMesh surface = make_surface(V, F);
        UnfoldResult result;
        TetMeshFields fields;
        {
          py::gil_scoped_release nogil;
          use_threads(options);
          // A given tet mesh (tets over tet_vertices) whose boundary is the surface.
          result = tets ? unfold_prepared(
                              prepare_mesh_from_tets(
                                  surface, *tet_vertices, Eigen::MatrixX4i(*tets), options,
                                  unfolded_tet_vertices ? Eigen::MatrixX3d(*unfolded_tet_vertices)
                                                        : Eigen::MatrixX3d()),
                              options)
                        : unfold_surface(surface, options);
          fields = canonical_tet_fields(result);
        }
        return result_dict(result, fields, options);
      },
      py::arg("V"), py::arg("F"), py::arg("config_path"), py::arg("overrides"),
      py::arg("tets") = std::nullopt, py::arg("tet_vertices") = std::nullopt,
      py::arg("unfolded_tet_vertices") = std::nullopt);
  m.def(
      "compare",
      [](const Vertices& V, const Elements& F,
         const std::vector<std::tuple<std::string, std::string, Overrides>>& configs) {
        std::vector<NamedOptions> options;
        for (const auto& [name, path, overrides] : configs)
          options.push_back({name, load_options(path, overrides)});
        const SurfaceMesh surface = make_surface(V, F);
        std::vector<ComparisonRow> rows;
        {
          py::gil_scoped_release nogil;
          if (!options.empty()) use_threads(options.front().options);
          rows = compare_options(surface, options);
        }
        py::list list;
        for (const ComparisonRow& row : rows) list.append(to_python(comparison_columns(row)));
        return list;
      },
      py::arg("V"), py::arg("F"), py::arg("configs"));
}

}  // namespace unfold::python
