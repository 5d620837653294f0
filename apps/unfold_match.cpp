// unfold_match: a dense point-to-point map between two shapes from their
// canonical forms, one pair or a list of pairs (issue 46).
// Flags and config only; the work is pipeline/match_surfaces.h and match_pairs.h.
#include <omp.h>

#include <cstdio>
#include <filesystem>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "apps/app_main.h"
#include "apps/config_flags.h"
#include "config/options.h"
#include "core/atomic_file.h"
#include "core/output_transaction.h"
#include "mesh/read_surface_mesh.h"
#include "pipeline/batch_run.h"
#include "pipeline/match_pairs.h"
#include "pipeline/match_surfaces.h"
#include "render/camera.h"
#include "render/render_map_transfer.h"
#include "render/write_png.h"

DEFINE_string(source, "", "one pair: the source surface (.off .obj .ply .stl)");
DEFINE_string(target, "", "one pair: the target surface");
DEFINE_string(output, "",
              "one pair: the map file, one line per source vertex: its 0-based target vertex");
DEFINE_string(render, "",
              "one pair: a picture (.png) of the source coloured by position beside the target "
              "coloured through the map");
DEFINE_string(render_up, "z", "the shapes' up axis for --render: x, y or z (TOSCA: z, FAUST: y)");
DEFINE_string(pairs, "",
              "batch: a file of two shape names per line (as test_pairs.txt), matched with "
              "the shapes of --input_dir into --output_dir/<source>__<target>.map");
DEFINE_string(input_dir, "", "batch: the shapes' meshes, <name>.off (or .obj .ply .stl)");
DEFINE_string(output_dir, "", "batch: where the maps go (created if missing)");
DEFINE_string(canonical_dir, "",
              "batch: canonical forms read from <dir>/<name>.off when there, else unfolded and "
              "written there (reused by later runs)");
DEFINE_bool(evaluate, false,
            "batch: score the maps against the shapes' .vts (strict) and the target's .sym.vts "
            "(flip-forgiving) and print the table");
DEFINE_string(evaluation_csv, "", "batch with --evaluate: per pair, each step's errors as CSV");
DEFINE_string(cdf_png, "", "batch with --evaluate: cumulative error curves of each step (.png)");
DEFINE_string(shard, "0/1",
              "batch: i/N: match only the pairs k (in file order) with k % N == i, e.g. one "
              "Slurm array task (each pair is decided on its own; with match.synchronize the "
              "collection's check sees the shard's pairs)");
DEFINE_string(config, "", "YAML config; empty: the built-in defaults (= configs/default.yaml)");
DEFINE_bool(progress, true, "a line per pair (batch) on stderr");

namespace {

int run_one(const unfold::Options& options) {
  if (FLAGS_shard != "0/1") throw unfold::UsageError("--shard needs --pairs");
  if (FLAGS_source.empty() || FLAGS_target.empty() || FLAGS_output.empty())
    throw unfold::UsageError("--source, --target and --output are required (or --pairs)");
  if (!FLAGS_render.empty()) unfold::check_png_format(FLAGS_render);
  const int up = unfold::axis_index(FLAGS_render_up, "--render_up");
  for (const std::string& path : {FLAGS_output, FLAGS_render})
    if (!path.empty()) unfold::check_writable_destination(path);
  const unfold::SurfaceMesh source = unfold::read_surface_mesh(FLAGS_source);
  const unfold::SurfaceMesh target = unfold::read_surface_mesh(FLAGS_target);
  unfold::ShapeMatch match;
  {
    unfold::app::ProgressScope progress("unfold_match", FLAGS_progress);
    match = unfold::match_surfaces(source, target, options);
    unfold::OutputTransaction outputs;  // all files or none
    unfold::write_map(FLAGS_output, match.map);
    if (!FLAGS_render.empty())
      unfold::write_png(FLAGS_render, unfold::render_map_transfer(source, target, match.map, up));
    outputs.commit();
  }
  std::printf(
      "mapped %d source vertices to %d target vertices: %s; %.2f s alignment, %.2f s "
      "refinement\n",
      int(source.V.rows()), int(target.V.rows()), match.decision.c_str(), match.seconds_align,
      match.seconds_refine);
  return 0;
}

int run_batch(const unfold::Options& options) {
  if (FLAGS_input_dir.empty() || FLAGS_output_dir.empty())
    throw unfold::UsageError("--pairs needs --input_dir and --output_dir");
  if (!FLAGS_source.empty() || !FLAGS_target.empty() || !FLAGS_output.empty() ||
      !FLAGS_render.empty())
    throw unfold::UsageError("--pairs does not take --source, --target, --output or --render");
  if (!FLAGS_evaluate && (!FLAGS_evaluation_csv.empty() || !FLAGS_cdf_png.empty()))
    throw unfold::UsageError("--evaluation_csv and --cdf_png need --evaluate");
  if (!FLAGS_cdf_png.empty()) unfold::check_png_format(FLAGS_cdf_png);
  for (const std::string& dir : {FLAGS_output_dir, FLAGS_canonical_dir}) {
    std::error_code ec;
    if (!dir.empty()) std::filesystem::create_directories(dir, ec);
  }
  for (const std::string& path : {FLAGS_evaluation_csv, FLAGS_cdf_png})
    if (!path.empty()) unfold::check_writable_destination(path);
  const auto [shard, shards] = unfold::parse_shard(FLAGS_shard);
  std::vector<std::pair<std::string, std::string>> pairs;
  {
    const auto all = unfold::read_shape_pairs(FLAGS_pairs);
    for (size_t k = 0; k < all.size(); ++k)
      if (int(k % size_t(shards)) == shard) pairs.push_back(all[k]);
    if (pairs.empty())
      throw unfold::UsageError("--shard " + FLAGS_shard + " leaves no pair of " + FLAGS_pairs);
  }
  unfold::MatchBatchOptions batch;
  batch.input_dir = FLAGS_input_dir;
  batch.output_dir = FLAGS_output_dir;
  batch.canonical_dir = FLAGS_canonical_dir;
  batch.evaluate = FLAGS_evaluate;
  batch.progress = FLAGS_progress;
  unfold::MatchBatch result;
  {
    // No progress line: the lines per pair are the progress.
    unfold::app::ProgressScope progress("unfold_match", false);
    result = unfold::run_match_batch(pairs, batch, options);
  }
  int failed = 0, first_code = 0;
  for (const auto& p : result.pairs) {
    if (p.error.empty()) continue;
    if (!FLAGS_progress)
      std::fprintf(stderr, "unfold_match: error: pair %s %s: %s\n", p.source.c_str(),
                   p.target.c_str(), p.error.c_str());
    if (failed++ == 0) first_code = p.exit_code;
  }
  for (const auto& p : result.pairs)
    if (FLAGS_evaluate && p.error.empty() && !p.evaluation_error.empty())
      std::fprintf(stderr, "unfold_match: warning: pair %s %s not scored: %s\n", p.source.c_str(),
                   p.target.c_str(), p.evaluation_error.c_str());
  std::fputs(unfold::format_match_summary(result).c_str(), stdout);
  if (!FLAGS_evaluation_csv.empty()) unfold::write_match_csv(FLAGS_evaluation_csv, result);
  if (!FLAGS_cdf_png.empty())
    unfold::write_match_cdf(FLAGS_cdf_png, result,
                            std::filesystem::path(FLAGS_input_dir).filename().string());
  if (failed > 0) {
    std::fprintf(stderr, "unfold_match: %d of %zu pairs failed\n", failed, result.pairs.size());
    return first_code ? first_code : 1;
  }
  return 0;
}

int run() {
  const unfold::Options options = unfold::load_options(FLAGS_config, config_flag_overrides());
  if (options.threads > 0) omp_set_num_threads(options.threads);
  return FLAGS_pairs.empty() ? run_one(options) : run_batch(options);
}

}  // namespace

int main(int argc, char** argv) {
  gflags::SetVersionString("0.1.0");
  unfold::app::AppHelp help;
  help.usage =
      "unfold_match --source A.off --target B.off --output A__B.map [flags], or "
      "unfold_match --pairs FILE --input_dir DIR --output_dir OUT [flags]";
  help.summary =
      "Maps every vertex of one shape to a vertex of another through their canonical forms "
      "(rigid alignment, mirror decision, ZoomOut). Every config key is also a flag.";
  help.groups = {
      {"One pair", {"source", "target", "output", "render", "render_up"}},
      {"Batch", {"pairs", "input_dir", "output_dir", "canonical_dir", "shard", "progress"}},
      {"Evaluation", {"evaluate", "evaluation_csv", "cdf_png"}},
      {"Method and config", {"config"}},
  };
  help.config_key_flags = true;
  return unfold::app::run_main("unfold_match", help, argc, argv, run);
}
