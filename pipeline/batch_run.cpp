#include "pipeline/batch_run.h"

#include <fcntl.h>
#include <glog/logging.h>
#include <omp.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>
#include <optional>
#include <set>
#include <sstream>
#include <thread>

#include "config/options.h"
#include "core/atomic_file.h"
#include "core/errors.h"
#include "core/output_transaction.h"
#include "core/progress.h"
#include "core/seconds_since.h"
#include "core/terminal_progress.h"
#include "mesh/mesh_format.h"
#include "mesh/read_surface_mesh.h"
#include "mesh/write_surface_mesh.h"
#include "metrics/pose_invariance.h"
#include "metrics/retrieval_measures.h"
#include "pipeline/cmbof_vocabulary.h"
#include "pipeline/metrics_json.h"
#include "pipeline/pose_invariance_tables.h"
#include "pipeline/region_pictures.h"
#include "pipeline/retrieval_descriptors.h"
#include "pipeline/similarity_blocks.h"
#include "pipeline/unfold_surface.h"

namespace unfold {
namespace fs = std::filesystem;
namespace {

std::string stem(const std::string& path) { return fs::path(path).stem().string(); }

// One CSV field: quoted when it holds a comma, quote or line break.
std::string csv_field(std::string s) {
  for (char& c : s)
    if (c == '\n' || c == '\r') c = ' ';
  if (s.find_first_of(",\"") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

std::vector<std::string> split_csv_line(const std::string& line) {
  std::vector<std::string> fields(1);
  bool quoted = false;
  for (size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted && c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
      fields.back() += '"';
      ++i;
    } else if (c == '"') {
      quoted = !quoted;
    } else if (c == ',' && !quoted) {
      fields.emplace_back();
    } else {
      fields.back() += c;
    }
  }
  return fields;
}

// A metric not computed (NaN, metrics.compute) is an empty field.
std::string metric_field(double value) {
  if (std::isnan(value)) return "";
  std::ostringstream s;
  s << std::setprecision(10) << value;
  return s.str();
}

double parse_metric_field(const std::string& field) {
  return field.empty() ? std::numeric_limits<double>::quiet_NaN() : std::stod(field);
}

const char* const kResultsHeader =
    "shape,class,method,E_rig,E_str,E_geo,damaged_edges_percent,surface_edge_ratio_p999,"
    "surface_edge_ratio_max,inverted_tets,folded_edges_percent,dihedral_change_p999_degrees,"
    "E_geo_surface,seconds,status";
// results.csv before E_geo_surface, before the fold columns, and before the damage columns
// (issue 44): still read.
const char* const kResultsHeaderWithoutSurfaceGeo =
    "shape,class,method,E_rig,E_str,E_geo,damaged_edges_percent,surface_edge_ratio_p999,"
    "surface_edge_ratio_max,inverted_tets,folded_edges_percent,dihedral_change_p999_degrees,"
    "seconds,status";
const char* const kResultsHeaderWithoutFolds =
    "shape,class,method,E_rig,E_str,E_geo,damaged_edges_percent,surface_edge_ratio_p999,"
    "surface_edge_ratio_max,inverted_tets,seconds,status";
const char* const kResultsHeaderWithoutDamage =
    "shape,class,method,E_rig,E_str,E_geo,seconds,status";

std::string format_row(const BatchRow& r) {
  std::ostringstream s;
  s << std::setprecision(10) << csv_field(r.shape) << ',' << csv_field(r.shape_class) << ','
    << csv_field(r.method) << ',' << metric_field(r.E_rig) << ',' << metric_field(r.E_str) << ','
    << metric_field(r.E_geo) << ',' << metric_field(r.damaged_edges_percent) << ','
    << metric_field(r.surface_edge_ratio_p999) << ',' << metric_field(r.surface_edge_ratio_max)
    << ',' << metric_field(r.inverted_tets) << ',' << metric_field(r.folded_edges_percent) << ','
    << metric_field(r.dihedral_change_p999) << ',' << metric_field(r.E_geo_surface) << ','
    << r.seconds << ',' << csv_field(r.status);
  return s.str();
}

// A row of 15 fields, of 14 (written before E_geo_surface), of 12 (before the
// fold columns) or of 8 (before the damage columns).
BatchRow parse_row(const std::string& line, const std::string& where) {
  const std::vector<std::string> f = split_csv_line(line);
  if (f.size() != 15 && f.size() != 14 && f.size() != 12 && f.size() != 8)
    throw InputError(where + ": expected 15 fields, got " + std::to_string(f.size()));
  const bool damage = f.size() >= 12, folds = f.size() >= 14, surface_geo = f.size() == 15;
  BatchRow r{f[0], f[1], f[2], 0, 0, 0, 0, f.back()};
  try {
    r.E_rig = parse_metric_field(f[3]), r.E_str = parse_metric_field(f[4]);
    r.E_geo = parse_metric_field(f[5]);
    if (damage) {
      r.damaged_edges_percent = parse_metric_field(f[6]);
      r.surface_edge_ratio_p999 = parse_metric_field(f[7]);
      r.surface_edge_ratio_max = parse_metric_field(f[8]);
      r.inverted_tets = parse_metric_field(f[9]);
    }
    if (folds) {
      r.folded_edges_percent = parse_metric_field(f[10]);
      r.dihedral_change_p999 = parse_metric_field(f[11]);
    }
    if (surface_geo) r.E_geo_surface = parse_metric_field(f[12]);
    r.seconds = std::stod(f[f.size() - 2]);
  } catch (const std::exception&) {
    throw InputError(where + ": a number field is not a number");
  }
  return r;
}

struct Layout {
  std::string dir;
  std::string file(const std::string& method, const std::string& shape,
                   const std::string& suffix) const {
    return dir + "/" + method + "/" + shape + suffix;
  }
  std::string descriptor(const std::string& label, const std::string& shape) const {
    return dir + "/descriptors/" + label + "/" + shape + ".txt";
  }
  std::string vocabulary(const std::string& label) const {
    return dir + "/descriptors/" + label + ".cmbof_vocabulary.txt";
  }
  std::string blocks() const { return dir + "/similarity_blocks"; }
  std::string block_prefix(const std::string& label, RetrievalFramework f) const {
    return label + "_" + framework_name(f);
  }
};

std::optional<BatchRow> read_row_file(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  if (!in || !std::getline(in, line)) return std::nullopt;
  try {
    return parse_row(line, path);
  } catch (const InputError&) {
    return std::nullopt;
  }
}

// The preparation (simplify, tetrahedralize) depends on these keys only.
std::string preparation_key(const Options& o) {
  std::ostringstream s;
  s << o.target_vertices << '|' << o.tet.route << '|' << std::setprecision(17) << o.tet.quality
    << '|' << o.tet.max_volume << '|' << o.fallback_surface_graph << '|' << tets_from_unfolded(o);
  return s.str();
}

// Everything one child does for one shape: every config it is to run (run[k]),
// each failure in its row.
void run_shape(const std::string& mesh_path, const std::vector<Options>& options,
               const std::vector<std::string>& methods, const std::vector<char>& run,
               const Layout& out) {
  const std::string shape = stem(mesh_path);
  SurfaceMesh input;
  std::string read_error;
  try {
    input = read_surface_mesh(mesh_path);
  } catch (const std::exception& e) {
    read_error = e.what();
  }
  std::map<std::string, PreparedMesh> prepared;
  std::map<std::string, std::string> prepare_errors;
  for (size_t k = 0; k < options.size(); ++k) {
    if (!run[k]) continue;
    BatchRow row{shape, shape_class(shape), methods[k], 0, 0, 0, 0, "ok"};
    try {
      if (!read_error.empty()) throw InputError(read_error);
      const std::string key = preparation_key(options[k]);
      if (prepare_errors.count(key)) throw NumericalError(prepare_errors[key]);
      if (!prepared.count(key)) {
        try {
          prepared[key] = prepare_mesh(input, options[k]);
        } catch (const std::exception& e) {
          prepare_errors[key] = e.what();
          throw;
        }
      }
      const auto start = std::chrono::steady_clock::now();
      const UnfoldResult r = unfold_prepared(prepared[key], options[k]);
      OutputTransaction outputs;  // a config's files all or none; its row in any case
      row.seconds = seconds_since(start);
      row.E_rig = r.metrics.E_rig, row.E_str = r.metrics.E_str, row.E_geo = r.metrics.E_geo;
      row.E_geo_surface = r.metrics.E_geo_surface;
      row.damaged_edges_percent = r.metrics.damage.damaged_edges_percent;
      row.surface_edge_ratio_p999 = r.metrics.damage.ratio_p999;
      row.surface_edge_ratio_max = r.metrics.damage.ratio_max;
      row.inverted_tets = r.metrics.inverted_tets;
      row.folded_edges_percent = r.metrics.folds.folded_edges_percent;
      row.dihedral_change_p999 = r.metrics.folds.dihedral_change_p999;
      write_surface_mesh(out.file(methods[k], shape, ".off"), r.canonical);
      if (r.surface.V.rows() != input.V.rows())
        write_surface_mesh(
            out.file(methods[k], shape, ".on_input.off"),
            {transfer_by_nearest_point(r.surface.V, r.canonical.V, input.V), input.faces});
      write_metrics_json(out.file(methods[k], shape, ".json"), r, options[k]);
      outputs.commit();
    } catch (const std::exception& e) {
      row.status = e.what();
      LOG(ERROR) << shape << ", " << methods[k] << ": " << e.what();
    }
    write_file_atomically(out.file(methods[k], shape, ".row"),
                          [&](std::ostream& s) { s << format_row(row) << '\n'; });
  }
}

[[noreturn]] void run_child(const std::string& mesh_path, const std::vector<Options>& options,
                            const std::vector<std::string>& methods, const std::vector<char>& run,
                            const Layout& out, int threads) {
  const std::string log = out.dir + "/logs/" + stem(mesh_path) + ".log";
  // Configs kept from an earlier run keep their part of the log.
  const bool every = std::count(run.begin(), run.end(), 1) == std::ptrdiff_t(run.size());
  const int fd = ::open(log.c_str(), O_WRONLY | O_CREAT | (every ? O_TRUNC : O_APPEND), 0644);
  if (fd >= 0) {
    ::dup2(fd, STDOUT_FILENO);
    ::dup2(fd, STDERR_FILENO);
    ::close(fd);
  }
  omp_set_num_threads(threads);
  set_progress_listener(nullptr);  // the parent's terminal is not the child's
  // The log is the shape's record, not a console: its stages' lines (INFO)
  // whatever the app shows on its own stderr.
  FLAGS_minloglevel = google::GLOG_INFO;
  int code = 0;
  try {
    run_shape(mesh_path, options, methods, run, out);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    code = 1;
  }
  std::fflush(nullptr);
  ::_exit(code);
}

std::string describe_exit(int status) {
  if (WIFSIGNALED(status)) return "crashed (signal " + std::to_string(WTERMSIG(status)) + ")";
  return "exited with code " + std::to_string(WEXITSTATUS(status)) + " without a result";
}

// The forms retrieval compares: "raw" (the input poses), then each method.
std::vector<std::string> retrieval_labels(const std::vector<std::string>& methods) {
  std::vector<std::string> labels = {"raw"};
  labels.insert(labels.end(), methods.begin(), methods.end());
  return labels;
}

// The surface a label's descriptor comes from: the input, or the method's
// canonical surface if its run is ok; nothing for an unreadable one.
std::optional<SurfaceMesh> retrieval_form(const Layout& out, const std::string& label,
                                          const std::string& mesh) {
  try {
    if (label == "raw") return read_surface_mesh(mesh);
    const auto row = read_row_file(out.file(label, stem(mesh), ".row"));
    if (row && row->status == "ok") return read_surface_mesh(out.file(label, stem(mesh), ".off"));
  } catch (const InputError&) {
  }
  return std::nullopt;
}

// Per label, per mesh: the retrieval descriptor, read from its cache file or
// computed (in parallel, a few meshes in memory at a time) and cached; nothing
// where there is no form.
std::vector<std::vector<std::optional<RetrievalDescriptor>>> load_descriptors(
    const Layout& out, const std::vector<std::string>& meshes,
    const std::vector<std::string>& labels, const RetrievalOptions& options) {
  std::vector<std::vector<std::optional<RetrievalDescriptor>>> result(labels.size());
  for (size_t l = 0; l < labels.size(); ++l) {
    std::error_code ec;
    fs::create_directories(out.dir + "/descriptors/" + labels[l], ec);
    result[l].resize(meshes.size());
    std::vector<size_t> todo;
    for (size_t i = 0; i < meshes.size(); ++i) {
      result[l][i] = read_retrieval_descriptor(out.descriptor(labels[l], stem(meshes[i])), options);
      if (!result[l][i]) todo.push_back(i);
    }
    const size_t chunk = 16;
    for (size_t start = 0; start < todo.size(); start += chunk) {
      const size_t count = std::min(chunk, todo.size() - start);
      std::vector<std::optional<SurfaceMesh>> forms;
      for (size_t k = 0; k < count; ++k)
        forms.push_back(retrieval_form(out, labels[l], meshes[todo[start + k]]));
#pragma omp parallel for schedule(dynamic)
      for (size_t k = 0; k < count; ++k) {
        const size_t i = todo[start + k];
        if (!forms[k]) continue;
        try {
          result[l][i] = retrieval_descriptor(*forms[k], options);
        } catch (const UsageError& e) {  // a degenerate form is in no matrix
          LOG(WARNING) << stem(meshes[i]) << ", " << labels[l]
                       << ": no retrieval descriptor: " << e.what();
        }
      }
      for (size_t k = 0; k < count; ++k) {
        const size_t i = todo[start + k];
        if (result[l][i])
          write_retrieval_descriptor(out.descriptor(labels[l], stem(meshes[i])), *result[l][i],
                                     options);
      }
    }
  }
  return result;
}

// The shapes of one label that have a descriptor, as matrix rows.
struct RetrievalSet {
  std::vector<std::string> names;
  std::vector<RetrievalDescriptor> descriptors;
};
RetrievalSet retrieval_set(const std::vector<std::string>& meshes,
                           const std::vector<std::optional<RetrievalDescriptor>>& descriptors) {
  RetrievalSet set;
  for (size_t i = 0; i < meshes.size(); ++i)
    if (descriptors[i])
      set.names.push_back(stem(meshes[i])), set.descriptors.push_back(*descriptors[i]);
  return set;
}

// CM-BOF's vocabulary of one label's set (pipeline/cmbof_vocabulary.h): read
// from the output directory if learned there from these shapes with these
// options, else learned and stored, so that every shard of a split run uses
// the same (the key names the shapes and their features' fingerprints: a
// shape unfolded again with --skip_existing is learned from again); fills the
// set's word histograms.
// @return the vocabulary's fingerprint; empty (no CMBOF for the label) when no
//         view of any shape has a feature
std::string prepare_cmbof(const Layout& out, const std::string& label, RetrievalSet* set,
                          const RetrievalOptions& options) {
  std::string key = "cmbof=" + cmbof_options_key(options.cmbof) + " shapes=";
  for (size_t i = 0; i < set->names.size(); ++i)
    key += set->names[i] + ":" + features_fingerprint(set->descriptors[i].cmbof) + ",";
  std::optional<Eigen::MatrixXf> vocabulary = read_vocabulary(out.vocabulary(label), key);
  if (!vocabulary) {
    std::vector<const CmbofFeatures*> features;
    for (const auto& d : set->descriptors) features.push_back(&d.cmbof);
    try {
      vocabulary = cmbof_vocabulary(features, options.cmbof);
    } catch (const UsageError& e) {
      LOG(WARNING) << label << ", cmbof: " << e.what();
      return "";
    }
    write_vocabulary(out.vocabulary(label), *vocabulary, key);
  }
#pragma omp parallel for schedule(dynamic)
  for (size_t i = 0; i < set->descriptors.size(); ++i)
    set->descriptors[i].cmbof_histograms = cmbof_histograms(set->descriptors[i].cmbof, *vocabulary);
  return vocabulary_fingerprint(*vocabulary);
}

// This shard's block of every label's and framework's similarity matrix.
void write_similarity_blocks(const Layout& out, const std::vector<std::string>& meshes,
                             const std::vector<std::string>& methods, int index, int count,
                             const RetrievalOptions& options) {
  const std::vector<std::string> labels = retrieval_labels(methods);
  const auto descriptors = load_descriptors(out, meshes, labels, options);
  std::error_code ec;
  fs::create_directories(out.blocks(), ec);
  for (size_t l = 0; l < labels.size(); ++l) {
    RetrievalSet set = retrieval_set(meshes, descriptors[l]);
    const std::string vocabulary = prepare_cmbof(out, labels[l], &set, options);
    for (const RetrievalFramework f : kRetrievalFrameworks) {
      if (f == RetrievalFramework::cmbof && vocabulary.empty()) continue;
      write_similarity_block(out.blocks() + "/" + out.block_prefix(labels[l], f) + "." +
                                 std::to_string(index) + "-of-" + std::to_string(count) + ".csv",
                             similarity_block(set.descriptors, f, index, count, options), set.names,
                             index, count, similarity_key(f, options, vocabulary));
    }
  }
}
}  // namespace

std::string shape_class(const std::string& shape) {
  std::string c = shape;
  while (!c.empty() && std::isdigit(static_cast<unsigned char>(c.back()))) c.pop_back();
  while (!c.empty() && (c.back() == '_' || c.back() == '-')) c.pop_back();
  return c.empty() ? shape : c;
}

std::pair<int, int> parse_shard(const std::string& text) {
  const size_t slash = text.find('/');
  int i = -1, n = 0;
  try {
    if (slash != std::string::npos) {
      size_t used_i = 0, used_n = 0;
      i = std::stoi(text.substr(0, slash), &used_i);
      n = std::stoi(text.substr(slash + 1), &used_n);
      if (used_i != slash || used_n != text.size() - slash - 1) n = 0;
    }
  } catch (const std::exception&) {
    n = 0;
  }
  if (n < 1 || i < 0 || i >= n)
    throw UsageError("--shard must be i/N with 0 <= i < N, got '" + text + "'");
  return {i, n};
}

std::vector<std::string> list_meshes(const std::string& dir) {
  std::vector<std::string> meshes;
  std::error_code ec;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec))
    if (it->is_regular_file() && mesh_format_from_path(it->path().string()))
      meshes.push_back(it->path().string());
  if (ec) throw InputError("cannot read the input directory " + dir + ": " + ec.message());
  if (meshes.empty()) throw InputError("no mesh (.off, .obj, .ply, .stl) in " + dir);
  std::sort(meshes.begin(), meshes.end());
  return meshes;
}

std::vector<BatchRow> run_batch(const BatchOptions& o) {
  // Until the last shape is forked the parent runs OpenMP on one thread: a team
  // it started (a config probe's loop, say) would be copied into each child
  // without its threads, and the child's next parallel region would wait for
  // them forever (libgomp is not fork-safe). The children set their own count.
  struct SerialUntilForked {
    int threads = omp_get_max_threads();
    SerialUntilForked() { omp_set_num_threads(1); }
    ~SerialUntilForked() { restore(); }
    void restore() const { omp_set_num_threads(threads); }
  } serial;
  if (o.jobs < 1) throw UsageError("--jobs must be at least 1");
  if (o.shard_count < 1 || o.shard_index < 0 || o.shard_index >= o.shard_count)
    throw UsageError("the shard must be i/N with 0 <= i < N");
  if (o.configs.empty()) throw UsageError("--configs is required");
  std::vector<Options> options;
  std::vector<std::string> methods;
  for (const auto& path : o.configs) {
    options.push_back(load_options(path, o.overrides));
    methods.push_back(stem(path));
  }
  if (std::set<std::string>(methods.begin(), methods.end()).size() != methods.size())
    throw UsageError("two configs have the same file stem (the method name in results.csv)");
  const std::vector<std::string> all = list_meshes(o.input_dir);
  std::vector<std::string> meshes;
  for (size_t k = 0; k < all.size(); ++k)
    if (int(k % size_t(o.shard_count)) == o.shard_index) meshes.push_back(all[k]);

  const Layout out{o.output_dir};
  std::error_code ec;
  fs::create_directories(out.dir + "/logs", ec);
  for (const auto& m : methods) fs::create_directories(out.dir + "/" + m, ec);
  if (ec) throw OutputError("cannot create " + out.dir + ": " + ec.message());

  auto rows_of = [&](const std::string& mesh) {
    std::vector<std::optional<BatchRow>> rows;
    for (const auto& m : methods) rows.push_back(read_row_file(out.file(m, stem(mesh), ".row")));
    return rows;
  };
  // Per shape, the configs to run: all, or with --skip_existing those without
  // a row of status ok.
  std::vector<std::pair<std::string, std::vector<char>>> todo;
  size_t results_to_run = 0;
  for (const auto& mesh : meshes) {
    std::vector<char> configs;
    for (const auto& row : rows_of(mesh))
      configs.push_back(!(o.skip_existing && row && row->status == "ok"));
    const auto to_run = size_t(std::count(configs.begin(), configs.end(), 1));
    if (to_run == 0) continue;
    results_to_run += to_run;
    for (size_t k = 0; k < methods.size(); ++k) {
      if (!configs[k]) continue;
      for (const char* suffix : {".row", ".off", ".on_input.off", ".json"})
        fs::remove(out.file(methods[k], stem(mesh), suffix), ec);
      fs::remove(out.descriptor(methods[k], stem(mesh)), ec);
    }
    fs::remove(out.descriptor("raw", stem(mesh)), ec);
    todo.emplace_back(mesh, std::move(configs));
  }
  if (!todo.empty()) fs::remove_all(out.blocks(), ec);  // rows of shapes about to change

  const int cores = int(std::max(1u, std::thread::hardware_concurrency()));
  std::map<pid_t, std::pair<std::string, std::chrono::steady_clock::time_point>> running;
  std::map<std::string, std::string> exit_problems;
  TerminalProgress progress("unfold_batch", stderr, o.progress);
  const auto show = [&progress, &todo, &running](int finished) {
    progress.set({"unfolding (" + std::to_string(running.size()) + " running)", "shapes", finished,
                  int(todo.size())});
  };
  // "22 shapes to run (0 kept; 88 of their 110 results kept), ..." when
  // --skip_existing keeps some configs of the shapes it runs.
  std::string kept = std::to_string(meshes.size() - todo.size()) + " kept";
  if (results_to_run < todo.size() * methods.size())
    kept += "; " + std::to_string(todo.size() * methods.size() - results_to_run) + " of their " +
            std::to_string(todo.size() * methods.size()) + " results kept";
  progress.print_line("unfold_batch: " + std::to_string(todo.size()) + " shapes to run (" + kept +
                          "), " + std::to_string(methods.size()) + " configs, " +
                          std::to_string(o.jobs) + " jobs",
                      stdout);
  size_t next = 0;
  int finished = 0;
  while (next < todo.size() || !running.empty()) {
    while (next < todo.size() && int(running.size()) < o.jobs) {
      const auto& [mesh, configs] = todo[next++];
      const int threads =
          options.front().threads > 0 ? options.front().threads : std::max(1, cores / o.jobs);
      std::fflush(nullptr);
      const pid_t pid = ::fork();
      if (pid < 0) throw NumericalError("fork failed for " + mesh);
      if (pid == 0) run_child(mesh, options, methods, configs, out, threads);
      running[pid] = {mesh, std::chrono::steady_clock::now()};
    }
    show(finished);
    int status = 0;
    // On a terminal the elapsed time runs on while the shapes do.
    pid_t pid = ::waitpid(-1, &status, progress.active() ? WNOHANG : 0);
    for (; pid == 0; pid = ::waitpid(-1, &status, WNOHANG)) {
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
      progress.redraw_if_due();
    }
    if (pid < 0 || !running.count(pid)) continue;
    const auto [mesh, start] = running[pid];
    running.erase(pid);
    ++finished;
    if (!(WIFEXITED(status) && WEXITSTATUS(status) == 0))
      exit_problems[mesh] = describe_exit(status);
    std::ostringstream line;
    line << std::left << std::setw(16) << stem(mesh) << std::right << std::fixed
         << std::setprecision(1) << std::setw(7) << seconds_since(start) << " s ";
    const auto rows = rows_of(mesh);
    for (size_t k = 0; k < methods.size(); ++k)
      line << " | " << methods[k] << " "
           << (rows[k] ? std::to_string(int(rows[k]->seconds + 0.5)) + " s " +
                             (rows[k]->status == "ok" ? "ok" : "FAILED")
                       : "no result");
    progress.print_line(line.str(), stdout);
  }
  serial.restore();  // the tables below may use every core
  progress.finish();

  std::vector<BatchRow> rows;
  for (const auto& mesh : meshes) {
    const auto found = rows_of(mesh);
    for (size_t k = 0; k < methods.size(); ++k) {
      const std::string shape = stem(mesh);
      const auto problem = exit_problems.find(mesh);
      rows.push_back(found[k] ? *found[k]
                              : BatchRow{shape, shape_class(shape), methods[k], 0, 0, 0, 0,
                                         problem != exit_problems.end()
                                             ? "the shape's process " + problem->second
                                             : "no result"});
    }
  }
  load_descriptors(out, meshes, retrieval_labels(methods), o.retrieval);  // this shard's, cached
  if (o.shard_count == 1) {
    write_results_csv(out.dir + "/results.csv", rows);
    write_dataset_evaluation(out.dir, meshes, methods, o.retrieval);
  } else {
    bool all_done = true;
    for (const auto& mesh : all)
      for (const auto& row : rows_of(mesh)) all_done = all_done && row.has_value();
    if (all_done)
      write_similarity_blocks(out, all, methods, o.shard_index, o.shard_count, o.retrieval);
    // Beside the lines per shape: what this run left to do.
    progress.print_line("shard " + std::to_string(o.shard_index) + "/" +
                            std::to_string(o.shard_count) + ": " +
                            (all_done ? "wrote its block of the similarity matrices; "
                                      : "the similarity block waits for every shape (run the "
                                        "shard again with --skip_existing); ") +
                            "dataset-wide files are written by a final run without --shard "
                            "(with --skip_existing)",
                        stdout);
  }
  return rows;
}

void write_results_csv(const std::string& path, const std::vector<BatchRow>& rows) {
  write_file_atomically(path, [&](std::ostream& s) {
    s << kResultsHeader << '\n';
    for (const auto& r : rows) s << format_row(r) << '\n';
  });
}

std::vector<BatchRow> read_results_csv(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError("cannot read " + path);
  std::string line;
  std::getline(in, line);
  if (line.rfind(kResultsHeader, 0) != 0 && line.rfind(kResultsHeaderWithoutSurfaceGeo, 0) != 0 &&
      line.rfind(kResultsHeaderWithoutFolds, 0) != 0 &&
      line.rfind(kResultsHeaderWithoutDamage, 0) != 0)
    throw InputError(path + ": not a results.csv (header " + line + ")");
  std::vector<BatchRow> rows;
  for (int number = 2; std::getline(in, line); ++number)
    if (!line.empty()) rows.push_back(parse_row(line, path + ":" + std::to_string(number)));
  return rows;
}

void write_dataset_evaluation(const std::string& output_dir, const std::vector<std::string>& meshes,
                              const std::vector<std::string>& methods,
                              const RetrievalOptions& options) {
  const Layout out{output_dir};
  const size_t n = meshes.size();
  std::vector<std::string> names(n), classes(n);
  std::vector<SurfaceMesh> inputs(n);
  std::vector<Eigen::MatrixX3i> faces(n);
  std::vector<bool> readable(n, true);  // an unreadable input is in no table (its rows say why)
  for (size_t i = 0; i < n; ++i) {
    names[i] = stem(meshes[i]);
    classes[i] = shape_class(names[i]);
    try {
      inputs[i] = read_surface_mesh(meshes[i]);
      faces[i] = triangulate_faces(inputs[i]);
    } catch (const InputError&) {
      readable[i] = false;
    }
  }
  // Per method: the forms on the input vertices (pose).
  const std::vector<std::string> labels = retrieval_labels(methods);
  std::vector<std::vector<std::optional<Eigen::MatrixX3d>>> on_input(labels.size());
  for (size_t i = 0; i < n; ++i)
    on_input[0].emplace_back(readable[i] ? std::optional(inputs[i].V) : std::nullopt);
  for (size_t m = 1; m < labels.size(); ++m) {
    on_input[m].resize(n);
    for (size_t i = 0; i < n; ++i) {
      const auto row = read_row_file(out.file(labels[m], names[i], ".row"));
      if (!readable[i] || !row || row->status != "ok") continue;
      const std::string carried = out.file(labels[m], names[i], ".on_input.off");
      const SurfaceMesh form =
          read_surface_mesh(fs::exists(carried) ? carried : out.file(labels[m], names[i], ".off"));
      if (form.V.rows() == inputs[i].V.rows()) on_input[m][i] = form.V;
    }
  }

  // Retrieval: per label and framework, the matrix (from block files where a
  // sharded run left them) and its measures.
  const auto descriptors = load_descriptors(out, meshes, labels, options);
  std::ostringstream retrieval;
  retrieval << "method,framework,queries,nn,first_tier,second_tier,e_measure,dcg";
  for (int l = 1; l <= kRecallLevels; ++l)
    retrieval << ",precision_" << std::fixed << std::setprecision(2) << double(l) / kRecallLevels;
  retrieval << '\n' << std::defaultfloat << std::setprecision(10);
  for (size_t m = 0; m < labels.size(); ++m) {
    RetrievalSet set = retrieval_set(meshes, descriptors[m]);
    std::vector<std::string> set_classes;
    for (const auto& name : set.names) set_classes.push_back(shape_class(name));
    if (set.names.size() < 2) continue;
    const std::string vocabulary = prepare_cmbof(out, labels[m], &set, options);
    for (const RetrievalFramework f : kRetrievalFrameworks) {
      if (f == RetrievalFramework::cmbof && vocabulary.empty()) continue;
      const Eigen::MatrixXd D = assemble_similarity(
          set.descriptors, set.names, f, out.blocks(), out.block_prefix(labels[m], f),
          similarity_key(f, options, vocabulary), options);
      try {
        const RetrievalMeasures r = retrieval_measures(D, set_classes);
        retrieval << labels[m] << ',' << framework_name(f) << ',' << r.queries << ',' << r.nn << ','
                  << r.first_tier << ',' << r.second_tier << ',' << r.e_measure << ',' << r.dcg;
        for (double p : r.precision) retrieval << ',' << p;
        retrieval << '\n';
      } catch (const UsageError& e) {  // no class with two shapes: a matrix, no measures
        LOG(WARNING) << labels[m] << ", " << framework_name(f) << ": " << e.what();
      }
      const std::string suffix =
          f == RetrievalFramework::icp ? "" : std::string("_") + framework_name(f);
      write_file_atomically(
          output_dir + "/similarity_" + labels[m] + suffix + ".csv", [&](std::ostream& s) {
            s << "shape";
            for (const auto& name : set.names) s << ',' << name;
            s << '\n' << std::setprecision(std::numeric_limits<double>::max_digits10);
            for (size_t a = 0; a < set.names.size(); ++a) {
              s << set.names[a];
              for (size_t b = 0; b < set.names.size(); ++b)
                s << ',' << D(Eigen::Index(a), Eigen::Index(b));
              s << '\n';
            }
          });
    }
  }
  // Pose invariance per pair of poses of a class, on the class's correspondence,
  // and the ratio to the raw poses' distance: what a user of canonical forms gains.
  std::vector<PoseShape> poses;
  for (size_t i = 0; i < n; ++i)
    if (readable[i]) {
      poses.push_back({names[i], classes[i], meshes[i], faces[i], {}});
      for (const auto& method_forms : on_input) poses.back().forms.push_back(method_forms[i]);
    }
  write_pose_invariance_tables(output_dir, labels, poses);
  write_worst_region_pictures(output_dir, labels, poses);
  write_file_atomically(output_dir + "/retrieval.csv",
                        [&](std::ostream& s) { s << retrieval.str(); });
}

}  // namespace unfold
