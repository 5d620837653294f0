#include "config/options.h"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <iomanip>
#include <limits>
#include <sstream>
#include <vector>

#include "config/config_keys.h"
#include "core/errors.h"
#include "solvers/backend_support.h"

namespace unfold {
namespace {

std::string describe(const YAML::Node& node) {
  std::ostringstream out;
  out << node;
  return out.str();
}

template <typename Integer>
void parse_integer(const YAML::Node& node, const std::string& key, Integer* value) {
  double number;
  if (!node.IsScalar() || !YAML::convert<double>::decode(node, number) ||
      number != std::floor(number) || std::abs(number) > double(std::numeric_limits<int>::max()))
    throw UsageError("config key '" + key + "' must be an integer, got '" + describe(node) + "'");
  *value = Integer(number);
}
void parse_into(const YAML::Node& node, const std::string& key, int* value) {
  parse_integer(node, key, value);
}
void parse_into(const YAML::Node& node, const std::string& key, int64_t* value) {
  parse_integer(node, key, value);
}

void parse_into(const YAML::Node& node, const std::string& key, double* value) {
  if (!node.IsScalar() || !YAML::convert<double>::decode(node, *value))
    throw UsageError("config key '" + key + "' must be a number, got '" + describe(node) + "'");
}

void parse_into(const YAML::Node& node, const std::string& key, bool* value) {
  if (!node.IsScalar() || !YAML::convert<bool>::decode(node, *value))
    throw UsageError("config key '" + key + "' must be true or false, got '" + describe(node) +
                     "'");
}

void parse_into(const YAML::Node& node, const std::string& key, std::string* value) {
  if (!node.IsScalar())
    throw UsageError("config key '" + key + "' must be a string, got '" + describe(node) + "'");
  *value = node.Scalar();
}

void parse_into(const YAML::Node& node, const std::string& key, std::array<double, 2>* value) {
  if (!node.IsSequence() || node.size() != 2)
    throw UsageError("config key '" + key + "' must be a list of two numbers, got '" +
                     describe(node) + "'");
  for (size_t k = 0; k < 2; ++k) parse_into(node[k], key, &(*value)[k]);
}

// A list of names; one name alone is a list of one, and "all" and "none"
// stand for every metric and none.
void parse_into(const YAML::Node& node, const std::string& key, std::vector<std::string>* value) {
  value->clear();
  if (node.IsScalar() && node.Scalar() == "all") {
    *value = Options().metrics;
  } else if (node.IsScalar() && node.Scalar() != "none") {
    value->push_back(node.Scalar());
  } else if (node.IsSequence()) {
    for (const auto& item : node) {
      value->emplace_back();
      parse_into(item, key, &value->back());
    }
  } else if (!node.IsScalar()) {
    throw UsageError("config key '" + key + "' must be a list of names, got '" + describe(node) +
                     "'");
  }
}

YAML::Node to_node(bool value) { return YAML::Node(value); }
YAML::Node to_node(int value) { return YAML::Node(value); }
YAML::Node to_node(int64_t value) { return YAML::Node(value); }
YAML::Node to_node(const std::string& value) { return YAML::Node(value); }
// 15 significant digits: 0.95 reads back as 0.95 and prints as 0.95.
YAML::Node to_node(double value) {
  std::ostringstream out;
  out << std::setprecision(15) << value;
  return YAML::Node(out.str());
}
YAML::Node to_node(const std::vector<std::string>& value) {
  YAML::Node node(YAML::NodeType::Sequence);
  node.SetStyle(YAML::EmitterStyle::Flow);
  for (const std::string& item : value) node.push_back(item);
  return node;
}
YAML::Node to_node(const std::array<double, 2>& value) {
  YAML::Node node;
  node.SetStyle(YAML::EmitterStyle::Flow);
  node.push_back(to_node(value[0]));
  node.push_back(to_node(value[1]));
  return node;
}

struct KeyBinding {
  std::string path;
  std::function<void(const YAML::Node&, Options*)> parse;
  std::function<YAML::Node(const Options&)> emit;
};

const std::vector<KeyBinding>& bindings() {
#define UNFOLD_BIND(flag, path, member, help)                                                \
  KeyBinding{path, [](const YAML::Node& n, Options* o) { parse_into(n, path, &o->member); }, \
             [](const Options& o) { return to_node(o.member); }},
  static const std::vector<KeyBinding> table = {UNFOLD_CONFIG_KEYS(UNFOLD_BIND)};
#undef UNFOLD_BIND
  return table;
}

const KeyBinding* find_binding(const std::string& path) {
  for (const auto& b : bindings())
    if (b.path == path) return &b;
  return nullptr;
}

// Visits every leaf of a YAML mapping with its dotted path.
void for_each_leaf(const YAML::Node& node, const std::string& prefix,
                   const std::function<void(const std::string&, const YAML::Node&)>& visit) {
  for (const auto& item : node) {
    if (!item.first.IsScalar())
      throw UsageError("config key '" + describe(item.first) + "'" +
                       (prefix.empty() ? "" : " under '" + prefix + "'") + " is not a plain name");
    const std::string path =
        prefix.empty() ? item.first.as<std::string>() : prefix + "." + item.first.as<std::string>();
    if (item.second.IsMap())
      for_each_leaf(item.second, path, visit);
    else
      visit(path, item.second);
  }
}

YAML::Node override_value(const std::string& text) {
  // "0.95,1.05" on a command line means the list [0.95, 1.05].
  const bool bare_list = text.find(',') != std::string::npos && text.find('[') == std::string::npos;
  return YAML::Load(bare_list ? "[" + text + "]" : text);
}

void require(bool ok, const std::string& key, const std::string& what) {
  if (!ok) throw UsageError("config key '" + key + "' " + what);
}

// The terms `options` enable, built on one tetrahedron: what tells, before any
// mesh is read, whether the method can run them. The pairs file is read when
// the run builds its problem, where make_backend checks the terms again.
EnergyTerms probe_terms(EnergyOptions options) {
  options.user_pairs_file.clear();
  TetMesh tet;
  tet.V = (Eigen::MatrixX3d(4, 3) << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1).finished();
  tet.T = (Eigen::MatrixX4i(1, 4) << 0, 1, 2, 3).finished();
  tet.num_surface_vertices = 4;
  return make_energy_terms(
      tet, std::make_shared<const EdgeGraph>(build_edge_graph(4, Eigen::MatrixXi(tet.T))), options);
}

}  // namespace

Options::Options() {
  domain = "surface";
  surface_solve_vertices = 60000;
  tet_shape = "auto";
  beta_value = 1.25;
  cascade.num_cascades = 1;  // one beta, solved to convergence
  cascade.k_iter = 300;
  cascade.epsilon = 1e-7;
  cascade.break_in_band = false;
  cascade.anderson = 5;
  integrate.iterations = 60;
  integrate.lbfgs = 5;
  integrate.weights = "inverse_length";
  integrate.anchor_weights = "stiffness";
  integrate.surface_edges = 0.25;
  soften.scale = 2.0;
  soften.filter = 0.03;
  soften.filter_stretch = 0.09;
  soften.epsilon = 1e-6;
  integrate.pose_pull = 0.1;
  untangle.sweeps = 30;
  energy.stretch_masses = "lumped";
  // Most of the spread by distances between clusters, the squared one kept for
  // its bound (docs/method.md, spread by distances).
  energy.stretch_weight = 0.03;
  energy.stretch_distance = 16;
  energy.stretch_mass_power = 0.7;
}

Options paper_options() { return Options(Options::PapersParameters{}); }

Options load_options(const std::string& config_path,
                     const std::map<std::string, std::string>& overrides) {
  Options options;
  auto apply = [&](const std::string& path, const YAML::Node& value, const std::string& where) {
    const KeyBinding* binding = find_binding(path);
    if (!binding) throw UsageError("unknown config key '" + path + "'" + where);
    binding->parse(value, &options);
  };
  if (!config_path.empty()) {
    YAML::Node root;
    try {
      root = YAML::LoadFile(config_path);
    } catch (const YAML::BadFile&) {
      throw UsageError("cannot read config file '" + config_path + "'");
    } catch (const YAML::Exception& e) {
      throw UsageError("invalid YAML in '" + config_path + "' at line " +
                       std::to_string(e.mark.line + 1) + ": " + e.msg);
    }
    if (!root.IsNull()) {
      if (!root.IsMap()) throw UsageError("config file '" + config_path + "' is not a mapping");
      if (const YAML::Node base = root["base"]) {
        const std::string name = base.IsScalar() ? base.as<std::string>() : describe(base);
        if (name != "default" && name != "paper")
          throw UsageError("config key 'base' in '" + config_path +
                           "' must be default or paper, got '" + name + "'");
        if (name == "paper") options = paper_options();
        root.remove("base");
      }
      for_each_leaf(root, "", [&](const std::string& path, const YAML::Node& value) {
        apply(path, value, " in '" + config_path + "'");
      });
    }
    // A file named in a config is relative to the config's folder.
    std::string& pairs = options.energy.user_pairs_file;
    const size_t slash = config_path.find_last_of('/');
    if (!pairs.empty() && pairs[0] != '/' && slash != std::string::npos)
      pairs = config_path.substr(0, slash + 1) + pairs;
  }
  for (const auto& [path, text] : overrides) {
    YAML::Node value;
    try {
      value = override_value(text);
    } catch (const YAML::Exception&) {
      throw UsageError("config key '" + path + "' has an unparsable value '" + text + "'");
    }
    apply(path, value, "");
  }
  validate_options(options);
  return options;
}

namespace {

// Whether the method solves on the surface first, whose unfolded shape a tet mesh can be made of.
bool solves_surface_first(const Options& options) {
  return options.domain == "surface" && options.method != "lsmds" && options.method != "scf";
}

}  // namespace

void validate_options(const Options& o) {
  require(o.method == "local_global" || o.method == "ceres" || o.method == "dpmu" ||
              o.method == "lsmds" || o.method == "scf",
          "method", "must be local_global, ceres, dpmu, lsmds or scf, got '" + o.method + "'");
  require(o.target_vertices == 0 || o.target_vertices >= 4, "simplify.target_vertices",
          "must be 0 (keep all) or at least 4");
  require(o.surface_solve_hops >= 0, "simplify.surface_solve_hops",
          "must be 0 (the whole surface) or a positive number of edges");
  require(o.surface_solve_vertices == 0 || o.surface_solve_vertices >= 100,
          "simplify.surface_solve_vertices", "must be 0 (no limit) or at least 100");
  require(o.tet.route == "auto" || o.tet.route == "conforming" || o.tet.route == "robust",
          "tetrahedralize.route", "must be auto, conforming or robust, got '" + o.tet.route + "'");
  require(o.tet.quality == 0 || (o.tet.quality >= 1.0 && std::isfinite(o.tet.quality)),
          "tetrahedralize.quality", "must be 0 (off) or a finite number >= 1");
  require(std::isfinite(o.tet.max_volume) && o.tet.max_volume >= 0, "tetrahedralize.max_volume",
          "must be 0 (no bound) or a positive finite number");
  require(o.components == "refuse" || o.components == "separately", "components",
          "must be refuse or separately, got '" + o.components + "'");
  require(o.domain == "volume" || o.domain == "surface", "domain",
          "must be volume or surface, got '" + o.domain + "'");
  require(o.tet_shape == "input" || o.tet_shape == "unfolded" || o.tet_shape == "auto" ||
              o.tet_shape == "contact",
          "tetrahedralize.shape",
          "must be input, unfolded, auto or contact, got '" + o.tet_shape + "'");
  require(
      o.tet_shape != "unfolded" || solves_surface_first(o), "tetrahedralize.shape",
      "unfolded needs domain: surface (the surface solve it tetrahedralizes) and a method other "
      "than lsmds and scf (auto and contact fall back to the input's tets there)");
  require(o.tet.unfolded_min_quality >= 0 && o.tet.unfolded_min_quality < 1,
          "tetrahedralize.unfolded_min_quality", "must be in [0, 1) (0: drop only inverted tets)");
  require(o.contact_geodesic > 0 && std::isfinite(o.contact_geodesic),
          "tetrahedralize.contact_geodesic", "must be a positive finite number");
  require(o.integrate.iterations >= 0, "integrate.iterations", "must be >= 0 (0 = off)");
  require(o.integrate.lbfgs >= 0, "integrate.lbfgs", "must be >= 0 (0 = local-global steps)");
  require(o.integrate.multigrid_vertices >= 0, "integrate.multigrid_vertices", "must be >= 0");
  require(o.integrate.weights == "uniform" || o.integrate.weights == "inverse_length",
          "integrate.weights",
          "must be uniform or inverse_length, got '" + o.integrate.weights + "'");
  require(o.integrate.anchor_weights == "uniform" || o.integrate.anchor_weights == "stiffness",
          "integrate.anchor_weights",
          "must be uniform or stiffness, got '" + o.integrate.anchor_weights + "'");
  require(std::isfinite(o.soften.scale) && o.soften.scale >= 0, "soften.scale",
          "must be >= 0 (0 = off)");
  require(o.soften.floor > 0 && o.soften.floor <= 1, "soften.floor", "must be in (0, 1]");
  require(std::isfinite(o.soften.filter) && o.soften.filter >= 0, "soften.filter",
          "must be a finite number >= 0 (0 = kept whole)");
  require(std::isfinite(o.soften.filter_stretch) && o.soften.filter_stretch >= 0,
          "soften.filter_stretch", "must be a finite number >= 0 (0 = kept whole)");
  require(std::isfinite(o.soften.epsilon) && o.soften.epsilon >= 0, "soften.epsilon",
          "must be a finite number >= 0 (0 = cascade.epsilon)");
  require(std::isfinite(o.integrate.anchor) && o.integrate.anchor >= 0, "integrate.anchor",
          "must be a finite number >= 0");
  require(std::isfinite(o.integrate.surface_edges) && o.integrate.surface_edges >= 0,
          "integrate.surface_edges", "must be a finite number >= 0 (0 = the tets' edges alone)");
  require(std::isfinite(o.integrate.tolerance) && o.integrate.tolerance >= 0, "integrate.tolerance",
          "must be a finite number >= 0");
  require(o.integrate.pose_pull >= 0 && o.integrate.pose_pull <= 1, "integrate.pose_pull",
          "must be in [0, 1] (0 = off)");
  require(o.untangle.sweeps >= 0, "untangle.sweeps", "must be >= 0 (0 = off)");
  require(std::isfinite(o.untangle.max_move) && o.untangle.max_move >= 0, "untangle.max_move",
          "must be a finite number >= 0");
  require(o.beta_mode == "relative" || o.beta_mode == "absolute", "beta.mode",
          "must be relative or absolute, got '" + o.beta_mode + "'");
  require(std::isfinite(o.beta_value) && o.beta_value > 0, "beta.value",
          "must be a positive finite number");
  const CascadeOptions& c = o.cascade;
  require(c.k_iter >= 1, "cascade.k_iter", "must be at least 1");
  require(c.anderson >= 0 && c.anderson <= 50, "cascade.anderson", "must be in [0, 50]");
  require(std::isfinite(c.epsilon) && c.epsilon >= 0, "cascade.epsilon",
          "must be a finite number >= 0");
  require(c.num_cascades >= 1, "cascade.num", "must be at least 1");
  require(std::isfinite(c.growth) && c.growth >= 1, "cascade.growth",
          "must be a finite number >= 1");
  require(std::isfinite(c.edge_ratio_band[0]) && std::isfinite(c.edge_ratio_band[1]) &&
              c.edge_ratio_band[0] <= c.edge_ratio_band[1],
          "cascade.edge_ratio_band", "must be two finite numbers, low <= high");
  const std::vector<std::string> known = Options().metrics;
  for (size_t k = 0; k < o.metrics.size(); ++k) {
    require(std::find(known.begin(), known.end(), o.metrics[k]) != known.end(), "metrics.compute",
            "lists '" + o.metrics[k] + "'; known: E_rig, E_str, E_geo (or all, none)");
    require(
        std::find(o.metrics.begin(), o.metrics.begin() + k, o.metrics[k]) == o.metrics.begin() + k,
        "metrics.compute", "lists '" + o.metrics[k] + "' twice");
  }
  require(o.stretch_metric.exact_limit >= 0, "metrics.stretch_exact_limit", "must be >= 0");
  require(o.stretch_metric.sample_pairs >= 2, "metrics.stretch_samples", "must be at least 2");
  require(o.geodesic_metric.exact_limit >= 0, "metrics.geodesic_exact_limit", "must be >= 0");
  require(o.geodesic_metric.sources >= 1, "metrics.geodesic_landmarks", "must be at least 1");
  require(o.geodesic_max_vertices >= 0, "metrics.geodesic_max_vertices", "must be >= 0");
  require(o.threads >= 0, "threads", "must be >= 0");
  const EnergyOptions& e = o.energy;
  require(std::isfinite(e.stretch_weight) && e.stretch_weight > 0, "stretch.weight",
          "must be a positive finite number");
  require(std::isfinite(e.arap_weight) && e.arap_weight >= 0, "arap.weight",
          "must be a finite number >= 0 (0 = off)");
  require(std::isfinite(e.edge_length_weight) && e.edge_length_weight >= 0, "edge_length.weight",
          "must be a finite number >= 0");
  require(e.arap_weight > 0 || e.edge_length_weight > 0, "arap.weight",
          "is 0 and so is edge_length.weight: nothing bounds the stretch term");
  require(o.method != "dpmu" || (e.arap_weight == 0 && e.edge_length_weight > 0), "method",
          "dpmu needs arap.weight: 0 and edge_length.weight > 0 (see configs/dpmu.yaml)");
  require(e.stretch_masses == "uniform" || e.stretch_masses == "lumped", "stretch.masses",
          "must be uniform or lumped, got '" + e.stretch_masses + "'");
  require(e.stretch_mass_power >= 0 && e.stretch_mass_power <= 1, "stretch.mass_power",
          "must be a number in [0, 1]");
  require(e.stretch_mass_power == 1 || e.stretch_masses == "lumped", "stretch.mass_power",
          "is not 1, but stretch.masses is uniform: it raises the lumped masses");
  require(e.stretch_local >= 0 && e.stretch_local < 1, "stretch.local",
          "must be a number in [0, 1)");
  require(std::isfinite(e.stretch_local_radius) && e.stretch_local_radius > 0,
          "stretch.local_radius", "must be a finite number > 0");
  require(e.stretch_local_regions >= 1, "stretch.local_regions", "must be at least 1");
  require(std::isfinite(e.stretch_distance) && e.stretch_distance >= 0, "stretch.distance",
          "must be a finite number >= 0");
  require(e.stretch_distance_clusters >= 2, "stretch.distance_clusters", "must be at least 2");
  require(e.arap_weights == "uniform" || e.arap_weights == "cotangent", "arap.weights",
          "must be uniform or cotangent, got '" + e.arap_weights + "'");
  // The surface domain's energy lives on the triangles' edges: no tets to take
  // cotangent weights or volumes from.
  require(o.domain != "surface" || e.arap_weights == "uniform", "arap.weights",
          "is cotangent, but domain: surface has no tets to take cotangent weights from (use "
          "uniform)");
  require(std::isfinite(e.user_pairs_gamma) && e.user_pairs_gamma > 0, "user_pairs.gamma",
          "must be a positive finite number");
  // The pairs name surface vertices, which a coarse surface solve does not have.
  require(o.surface_solve_hops == 0 || e.user_pairs_file.empty(), "simplify.surface_solve_hops",
          "must be 0 with user_pairs.file (the pairs name "
          "vertices of the whole surface)");
  require(std::isfinite(e.volume_weight) && e.volume_weight >= 0, "volume.weight",
          "must be a finite number >= 0");
  require(o.domain != "surface" || e.volume_weight == 0, "volume.weight",
          "must be 0 with domain: surface, which has no tets to keep the volume of");
  if (o.method != "lsmds" && o.method != "scf") {
    const std::string refused = why_backend_cannot_run(o.method, probe_terms(e));
    require(refused.empty(), "method", "is " + o.method + ", but " + refused);
  }
  validate_linear_solver_options(o.linear_solver);
  validate_ceres_options(o.ceres);
  validate_lsmds_options(o.lsmds);
  validate_scf_options(o.scf);
  validate_match_options(o.match);
}

// Route conforming with shape auto asks for TetGen's own tets of the input.
bool tets_from_unfolded(const Options& options) {
  return (options.tet_shape == "unfolded" ||
          (options.tet_shape == "auto" && options.tet.route != "conforming")) &&
         solves_surface_first(options);
}

bool tets_from_unfolded_on_contact(const Options& options) {
  return options.tet_shape == "contact" && solves_surface_first(options);
}

bool computes_metric(const Options& options, const std::string& name) {
  return std::find(options.metrics.begin(), options.metrics.end(), name) != options.metrics.end();
}

std::string options_to_yaml(const Options& options) {
  // Keys of one section are contiguous in UNFOLD_CONFIG_KEYS, and paths have at
  // most two levels, so one pass emits the nested document in table order.
  YAML::Emitter out;
  out << YAML::BeginMap;
  std::string open_section;
  for (const auto& b : bindings()) {
    const size_t dot = b.path.find('.');
    const std::string section = dot == std::string::npos ? "" : b.path.substr(0, dot);
    if (section != open_section) {
      if (!open_section.empty()) out << YAML::EndMap;
      if (!section.empty()) out << YAML::Key << section << YAML::Value << YAML::BeginMap;
      open_section = section;
    }
    out << YAML::Key << b.path.substr(dot + 1) << YAML::Value << b.emit(options);
  }
  if (!open_section.empty()) out << YAML::EndMap;
  out << YAML::EndMap;
  return std::string(out.c_str()) + "\n";
}

}  // namespace unfold
