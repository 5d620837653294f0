#include "pipeline/match_pairs.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <set>
#include <sstream>

#include "core/atomic_file.h"
#include "core/errors.h"
#include "core/seconds_since.h"
#include "mesh/read_surface_mesh.h"
#include "mesh/read_vts.h"
#include "mesh/text_lines.h"
#include "mesh/write_surface_mesh.h"
#include "metrics/correspondence_error.h"
#include "pipeline/match_surfaces.h"
#include "render/plot_cdf.h"
#include "render/write_png.h"
#include "solvers/synchronize_rotations.h"

namespace unfold {

const char* const kMatchStepNames[kMatchSteps] = {"rigid", "mirror decision", "ZoomOut"};

namespace {

struct CachedShape {
  std::string path;
  std::unique_ptr<MatchShape> shape;
  std::string error;
  int exit_code = 0;
};

// Prepares a shape once: its mesh found, unfolded (or its canonical form read
// back from the cache directory), its basis computed; or the error, kept.
class ShapeCache {
 public:
  ShapeCache(const MatchBatchOptions& batch, const Options& options)
      : batch_(batch), options_(options) {}

  const CachedShape& get(const std::string& name) {
    auto found = shapes_.find(name);
    if (found != shapes_.end()) return found->second;
    CachedShape& entry = shapes_[name];
    const auto start = std::chrono::steady_clock::now();
    try {
      entry.path = find_shape_file(batch_.input_dir, name);
      const SurfaceMesh surface = read_surface_mesh(entry.path);
      const std::string cached =
          batch_.canonical_dir.empty() ? "" : batch_.canonical_dir + "/" + name + ".off";
      SurfaceMesh canonical;
      if (!cached.empty() && std::filesystem::exists(cached)) canonical = read_surface_mesh(cached);
      if (canonical.V.rows() == surface.V.rows()) {
        entry.shape =
            std::make_unique<MatchShape>(match_shape_from_canonical(surface, canonical, options_));
      } else {
        entry.shape = std::make_unique<MatchShape>(unfold_for_matching(surface, options_));
        if (!cached.empty()) {
          canonical = surface;
          canonical.V = entry.shape->canonical;
          write_surface_mesh(cached, canonical);
        }
      }
      ++count_;
    } catch (const Error& e) {
      entry.shape.reset();
      const std::string what = e.what();  // named once
      entry.error =
          what.find("'" + name + "'") != std::string::npos ? what : "shape '" + name + "': " + what;
      entry.exit_code = e.exit_code();
    }
    seconds_ += seconds_since(start);
    return entry;
  }

  int count() const { return count_; }
  double seconds() const { return seconds_; }

 private:
  const MatchBatchOptions& batch_;
  const Options& options_;
  std::map<std::string, CachedShape> shapes_;
  int count_ = 0;
  double seconds_ = 0;
};

// An unsure pair whose rotation is farther than this (degrees) from the one
// the sure pairs imply is placed from it...
constexpr double kReseatDegrees = 45;
// ... when both its shapes are anchored: each in at least this many sure
// pairs whose rotation agrees with the collection within kAgreeDegrees (in a
// lone triangle a wrong pair cannot be told from the other two).
constexpr int kAnchoringPairs = 3;
constexpr double kAgreeDegrees = 15;

double degrees_between(const Eigen::Matrix3d& A, const Eigen::Matrix3d& B) {
  const double c = std::clamp(((A.transpose() * B).trace() - 1) / 2, -1.0, 1.0);
  return std::acos(c) * 180 / M_PI;
}

// match.synchronize: the sure pairs' rotations synchronized over the
// collection (solvers/synchronize_rotations.h); an unsure pair that
// disagrees with the rotation they imply is matched again from it. A sure
// pair is never changed, so the collection can only help.
void place_unsure_pairs(ShapeCache& cache, const MatchOptions& options, bool progress,
                        std::vector<PairOutcome>* outcomes) {
  std::map<std::string, int> member;
  std::vector<RelativeRotation> measured;
  std::set<std::pair<int, int>> measurement;  // (from, to), each pair once
  const auto index = [&](const std::string& name) {
    return member.emplace(name, int(member.size())).first->second;
  };
  for (const PairOutcome& p : *outcomes) {
    if (!p.error.empty() || p.match.mirrored || !p.match.sure || p.source == p.target) continue;
    const int from = index(p.source), to = index(p.target);
    if (measurement.count({from, to}) || measurement.count({to, from})) continue;
    measurement.insert({from, to});
    measured.push_back({from, to, p.match.rotation});
  }
  if (measured.size() < 3) return;
  const SynchronizedRotations sync = synchronize_rotations(int(member.size()), measured);
  std::vector<int> agreeing(member.size(), 0);
  for (size_t e = 0; e < measured.size(); ++e)
    if (sync.disagreement_degrees[e] < kAgreeDegrees) {
      ++agreeing[measured[e].from];
      ++agreeing[measured[e].to];
    }
  for (PairOutcome& p : *outcomes) {
    if (!p.error.empty() || p.match.mirrored || p.match.sure) continue;
    const auto from = member.find(p.source), to = member.find(p.target);
    if (from == member.end() || to == member.end() || agreeing[from->second] < kAnchoringPairs ||
        agreeing[to->second] < kAnchoringPairs)
      continue;
    const Eigen::Matrix3d implied = sync.global[to->second].transpose() * sync.global[from->second];
    const double degrees = degrees_between(implied, p.match.rotation);
    if (degrees < kReseatDegrees) continue;
    try {
      const auto start = std::chrono::steady_clock::now();
      p.match =
          match_shapes(*cache.get(p.source).shape, *cache.get(p.target).shape, options, &implied);
      p.seconds += seconds_since(start);
    } catch (const Error& e) {
      p.error = e.what();
      p.exit_code = e.exit_code();
      continue;
    }
    if (progress)
      std::fprintf(stderr,
                   "unfold_match: %s -> %s: an unsure placement %.0f degrees from the one the "
                   "sure pairs imply; placed from theirs\n",
                   p.source.c_str(), p.target.c_str(), degrees);
  }
}

std::string sym_vts_path(const std::string& mesh_path) {
  return std::filesystem::path(mesh_path).replace_extension(".sym.vts").string();
}

// Scores every matched pair against the .vts truth, one target at a time (its
// geodesic table is the largest thing kept).
void evaluate(ShapeCache& cache, MatchBatch* batch) {
  std::map<std::string, std::vector<PairOutcome*>> by_target;
  for (PairOutcome& p : batch->pairs)
    if (p.error.empty()) by_target[p.target].push_back(&p);
  for (auto& [target, pairs] : by_target) {
    const CachedShape& t = cache.get(target);
    Eigen::VectorXi truth, mirrored;
    GeodesicTable table;
    try {
      const int n = int(t.shape->V.rows());
      truth = read_vts(vts_path(t.path), n);
      mirrored = read_vts(sym_vts_path(t.path), n, int(truth.size()));
      std::vector<int> sources(truth.data(), truth.data() + truth.size());
      sources.insert(sources.end(), mirrored.data(), mirrored.data() + mirrored.size());
      table = geodesic_table(t.shape->V, t.shape->F, sources);
    } catch (const Error& e) {
      for (PairOutcome* p : pairs) p->evaluation_error = e.what();
      continue;
    }
    for (PairOutcome* p : pairs) {
      try {
        const CachedShape& s = cache.get(p->source);
        const Eigen::VectorXi points =
            read_vts(vts_path(s.path), int(s.shape->V.rows()), int(truth.size()));
        for (const Eigen::VectorXi* map : {&p->match.rigid, &p->match.oriented, &p->match.map}) {
          p->strict.push_back(correspondence_errors(table, *map, points, truth));
          p->forgiving.push_back(correspondence_errors(table, *map, points, truth, mirrored));
        }
      } catch (const Error& e) {
        p->strict.clear();
        p->forgiving.clear();
        p->evaluation_error = e.what();
      }
    }
  }
}

// Mean over every template point of every scored pair, x100.
double pooled_mean(const MatchBatch& batch, int step, bool forgiving) {
  double sum = 0;
  long count = 0;
  for (const PairOutcome& p : batch.pairs) {
    if (p.strict.empty()) continue;
    const Eigen::VectorXd& e = forgiving ? p.forgiving[step] : p.strict[step];
    sum += e.sum();
    count += e.size();
  }
  return count ? 100 * sum / double(count) : std::nan("");
}

}  // namespace

std::vector<std::pair<std::string, std::string>> read_shape_pairs(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) fail_reading(path, "it is a directory");
  std::ifstream in(path, std::ios::binary);
  if (!in) fail_reading(path, "no such file or not readable");
  TextLines lines(in, path);
  std::vector<std::pair<std::string, std::string>> pairs;
  Tokens t;
  while (lines.next(&t)) {
    if (t.size() != 2)
      lines.fail("expected two shape names, found '" + std::string(lines.text()) + "'");
    pairs.emplace_back(std::string(t[0]), std::string(t[1]));
  }
  if (pairs.empty()) fail_reading(path, "it names no pair");
  return pairs;
}

std::string find_shape_file(const std::string& dir, const std::string& name) {
  const std::filesystem::path base = std::filesystem::path(dir) / name;
  std::error_code ec;
  for (const char* extension : {".off", ".obj", ".ply", ".stl"}) {
    const std::string candidate = base.string() + extension;
    if (std::filesystem::is_regular_file(candidate, ec)) return candidate;
  }
  if (base.has_extension() && std::filesystem::is_regular_file(base, ec)) return base.string();
  throw InputError("shape '" + name + "' not found in " + dir + " (no " + name +
                   ".off, .obj, .ply or .stl)");
}

MatchBatch run_match_batch(const std::vector<std::pair<std::string, std::string>>& pairs,
                           const MatchBatchOptions& batch_options, const Options& options) {
  validate_match_options(options.match);
  check_writable_destination(batch_options.output_dir + "/.unfold_match_check");
  if (!batch_options.canonical_dir.empty())
    check_writable_destination(batch_options.canonical_dir + "/.unfold_match_check");
  ShapeCache cache(batch_options, options);
  MatchBatch batch;
  int done = 0;
  for (const auto& [source, target] : pairs) {
    PairOutcome p;
    p.source = source;
    p.target = target;
    p.map_path = batch_options.output_dir + "/" + source + "__" + target + ".map";
    try {
      const CachedShape& a = cache.get(source);
      if (!a.shape) throw InputError(a.error);  // the shape's own class is kept below
      const CachedShape& b = cache.get(target);
      if (!b.shape) throw InputError(b.error);
      const auto start = std::chrono::steady_clock::now();
      p.match = match_shapes(*a.shape, *b.shape, options.match);
      p.seconds = seconds_since(start);
    } catch (const Error& e) {
      p.error = e.what();
      p.exit_code = e.exit_code();
      for (const std::string* name : {&source, &target}) {
        const CachedShape& c = cache.get(*name);
        if (!c.shape) {
          p.exit_code = c.exit_code;
          break;
        }
      }
    }
    ++done;
    if (batch_options.progress) {
      if (p.error.empty())
        std::fprintf(stderr, "unfold_match: [%d/%zu] %s -> %s: %s; %.2f s (%.2f s alignment)\n",
                     done, pairs.size(), source.c_str(), target.c_str(), p.match.decision.c_str(),
                     p.seconds, p.match.seconds_align);
      else
        std::fprintf(stderr, "unfold_match: error: pair %s %s: %s\n", source.c_str(),
                     target.c_str(), p.error.c_str());
    }
    batch.pairs.push_back(std::move(p));
  }
  if (options.match.synchronize) {
    const auto start = std::chrono::steady_clock::now();
    place_unsure_pairs(cache, options.match, batch_options.progress, &batch.pairs);
    batch.seconds_synchronize = seconds_since(start);
  }
  for (PairOutcome& p : batch.pairs) {
    if (!p.error.empty()) continue;
    batch.seconds_pairs += p.seconds;
    try {
      write_map(p.map_path, p.match.map);
    } catch (const Error& e) {
      p.error = e.what();
      p.exit_code = e.exit_code();
      if (batch_options.progress)
        std::fprintf(stderr, "unfold_match: error: pair %s %s: %s\n", p.source.c_str(),
                     p.target.c_str(), p.error.c_str());
    }
  }
  if (batch_options.evaluate) evaluate(cache, &batch);
  batch.shapes = cache.count();
  batch.seconds_shapes = cache.seconds();
  return batch;
}

std::string format_match_summary(const MatchBatch& batch) {
  int ok = 0, scored = 0, mirrored = 0, ambiguous = 0, placed = 0, unsure = 0;
  for (const PairOutcome& p : batch.pairs) {
    ok += p.error.empty();
    scored += !p.strict.empty();
    mirrored += p.error.empty() && p.match.mirrored;
    ambiguous += p.error.empty() && p.match.ambiguous;
    placed += p.error.empty() && p.match.from_collection;
    unsure += p.error.empty() && !p.match.sure;
  }
  std::ostringstream out;
  char line[256];
  std::snprintf(
      line, sizeof line,
      "%d of %zu pairs matched (%d mirrored, %d ambiguous, %d unsure, %d placed by the "
      "collection); %d shapes prepared in %.1f s, rotations compared in %.1f s, "
      "matching %.2f s per pair; per pair with its shares %.2f s\n",
      ok, batch.pairs.size(), mirrored, ambiguous, unsure, placed, batch.shapes,
      batch.seconds_shapes, batch.seconds_synchronize, ok ? batch.seconds_pairs / ok : 0.0,
      ok ? (batch.seconds_shapes + batch.seconds_synchronize + batch.seconds_pairs) / ok : 0.0);
  out << line;
  if (scored == 0) return out.str();
  std::snprintf(line, sizeof line, "%d pairs scored; mean geodesic error x100 (over sqrt(area)):\n",
                scored);
  out << line << "| step | strict | flip-forgiving |\n|---|---|---|\n";
  for (int s = 0; s < kMatchSteps; ++s) {
    std::snprintf(line, sizeof line, "| %s | %.2f | %.2f |\n", kMatchStepNames[s],
                  pooled_mean(batch, s, false), pooled_mean(batch, s, true));
    out << line;
  }
  return out.str();
}

void write_match_csv(const std::string& path, const MatchBatch& batch) {
  write_file_atomically(path, [&](std::ostream& out) {
    out << "source,target,status,mirrored,ambiguous,rotation_residual,mirrored_residual,"
           "placement_margin,sure,from_collection,seconds";
    for (const char* step : {"rigid", "mirror", "zoomout"})
      out << ',' << step << "_strict," << step << "_forgiving";
    out << '\n';
    for (const PairOutcome& p : batch.pairs) {
      std::string status =
          p.error.empty() ? (p.evaluation_error.empty() ? "ok" : "not scored") : "failed";
      out << p.source << ',' << p.target << ',' << status << ',' << p.match.mirrored << ','
          << p.match.ambiguous << ',' << p.match.rotation_residual << ','
          << p.match.mirrored_residual << ',' << p.match.placement_margin << ',' << p.match.sure
          << ',' << p.match.from_collection << ',' << p.seconds;
      for (int s = 0; s < kMatchSteps; ++s) {
        if (p.strict.empty())
          out << ",,";
        else
          out << ',' << 100 * p.strict[s].mean() << ',' << 100 * p.forgiving[s].mean();
      }
      out << '\n';
    }
  });
}

void write_match_cdf(const std::string& path, const MatchBatch& batch, const std::string& title) {
  std::vector<CdfSeries> series;
  const auto collect = [&](const std::string& name, int step, bool forgiving) {
    std::vector<double> values;
    for (const PairOutcome& p : batch.pairs) {
      if (p.strict.empty()) continue;
      const Eigen::VectorXd& e = forgiving ? p.forgiving[step] : p.strict[step];
      for (Eigen::Index k = 0; k < e.size(); ++k) values.push_back(std::min(e(k), 0.25));
    }
    if (!values.empty()) series.emplace_back(name, std::move(values));
  };
  for (int s = 0; s < kMatchSteps; ++s) collect(kMatchStepNames[s], s, false);
  collect(std::string(kMatchStepNames[kMatchSteps - 1]) + ", flip-forgiving", kMatchSteps - 1,
          true);
  if (series.empty()) throw UsageError("write_match_cdf: no pair was scored");
  write_png(path, plot_cdf(series, title + ": geodesic error / sqrt(area)"));
}

}  // namespace unfold
