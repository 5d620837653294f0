// unfold_batch: every mesh of a directory with every config, in parallel over
// shapes; results.csv, retrieval and pose invariance (docs/evaluation.md).
//   unfold_batch --input_dir D --output_dir O --configs a.yaml,b.yaml [--jobs N] [--shard i/N]
#include <sstream>

#include "apps/app_main.h"
#include "pipeline/batch_run.h"

DEFINE_string(input_dir, "", "directory of input meshes (required)");
DEFINE_string(output_dir, "", "output directory, created if missing (required)");
DEFINE_string(configs, "", "comma-separated YAML configs; method name = file stem (required)");
DEFINE_int32(jobs, 1, "shapes run at once, each in its own process");
DEFINE_int32(threads, 0,
             "if >= 1: threads per shape (overrides threads of every config); 0: the configs' "
             "threads, and where those are 0 the cores divided by --jobs");
DEFINE_string(shard, "0/1",
              "i/N: run only the shapes k (sorted by name) with k % N == i, e.g. one Slurm "
              "array task; then collect with one run without --shard and --skip_existing");
DEFINE_bool(skip_existing, false,
            "keep each shape's results of the configs that have one with status ok");
DEFINE_int32(target_vertices, -1, "if >= 0: overrides simplify.target_vertices of every config");
DEFINE_string(metrics, "",
              "if set: overrides metrics.compute of every config, e.g. E_rig,E_str skips E_geo "
              "(its column is then empty)");
DEFINE_int32(retrieval_points, 1000, "points sampled per shape for retrieval");
DEFINE_int32(cmbof_words, 1500, "CMBOF retrieval: visual vocabulary size (k-means centres)");
DEFINE_int32(cmbof_image_size, 256, "CMBOF retrieval: depth image width and height, pixels");
DEFINE_int32(cmbof_view_subdivisions, 2,
             "CMBOF retrieval: octahedron subdivisions of the view sphere, 0-3 (6, 18, 66, 258 "
             "views)");
DEFINE_bool(progress, true,
            "on a terminal: a progress line (shapes done, elapsed time) rewritten in place on "
            "stderr; when stderr is a file or a pipe, the per-shape lines alone");

int main(int argc, char** argv) {
  unfold::app::AppHelp help;
  help.usage =
      "unfold_batch --input_dir D --output_dir O --configs a.yaml,b.yaml [--jobs N] [--shard i/N]";
  help.summary =
      "Unfolds every mesh of a directory with every config; writes results.csv, retrieval and "
      "pose-invariance tables (docs/evaluation.md).";
  help.groups = {
      {"Input and output", {"input_dir", "output_dir", "skip_existing"}},
      {"Method and config", {"configs", "target_vertices"}},
      {"Metrics and pictures",
       {"metrics", "retrieval_points", "cmbof_words", "cmbof_image_size",
        "cmbof_view_subdivisions"}},
      {"Batch", {"jobs", "shard", "progress"}},
  };
  return unfold::app::run_main("unfold_batch", help, argc, argv, [] {
    if (FLAGS_input_dir.empty() || FLAGS_output_dir.empty())
      throw unfold::UsageError("--input_dir and --output_dir are required");
    unfold::BatchOptions options;
    options.input_dir = FLAGS_input_dir;
    options.output_dir = FLAGS_output_dir;
    std::istringstream list(FLAGS_configs);
    for (std::string item; std::getline(list, item, ',');)
      if (!item.empty()) options.configs.push_back(item);
    options.jobs = FLAGS_jobs;
    std::tie(options.shard_index, options.shard_count) = unfold::parse_shard(FLAGS_shard);
    options.skip_existing = FLAGS_skip_existing;
    if (FLAGS_threads < 0) throw unfold::UsageError("--threads must be >= 0");
    if (FLAGS_threads > 0) options.overrides["threads"] = std::to_string(FLAGS_threads);
    if (FLAGS_target_vertices >= 0)
      options.overrides["simplify.target_vertices"] = std::to_string(FLAGS_target_vertices);
    if (!FLAGS_metrics.empty()) options.overrides["metrics.compute"] = FLAGS_metrics;
    if (FLAGS_retrieval_points < 4) throw unfold::UsageError("--retrieval_points must be >= 4");
    options.retrieval.sample_points = FLAGS_retrieval_points;
    if (FLAGS_cmbof_words < 1) throw unfold::UsageError("--cmbof_words must be >= 1");
    if (FLAGS_cmbof_image_size < 8) throw unfold::UsageError("--cmbof_image_size must be >= 8");
    options.retrieval.cmbof.words = FLAGS_cmbof_words;
    options.retrieval.cmbof.image_size = FLAGS_cmbof_image_size;
    if (FLAGS_cmbof_view_subdivisions < 0 || FLAGS_cmbof_view_subdivisions > 3)
      throw unfold::UsageError("--cmbof_view_subdivisions must be in [0, 3]");
    options.retrieval.cmbof.view_subdivisions = FLAGS_cmbof_view_subdivisions;
    options.progress = FLAGS_progress && unfold::app::stderr_is_terminal();
    int failed = 0;
    for (const auto& row : unfold::run_batch(options)) failed += row.status != "ok";
    if (failed > 0)
      std::fprintf(stderr, "unfold_batch: %d runs failed (see results.csv)\n", failed);
    return 0;
  });
}
