// Batch evaluation over a dataset: every mesh of a directory with every
// config, one forked child process per shape (in parallel up to `jobs`, so a
// crash or an abort in one shape cannot take the run down), per-shape outputs,
// then results.csv, retrieval and pose invariance over the whole dataset
// (docs/evaluation.md).
//
// Output layout in output_dir:
//   <method>/<shape>.off           canonical surface (method = config stem)
//   <method>/<shape>.on_input.off  the same carried to the input's vertices (simplified runs)
//   <method>/<shape>.json          metrics JSON
//   <method>/<shape>.row           this shape's results.csv row
//   logs/<shape>.log               the child's log
//   descriptors/<method>/<shape>.txt  retrieval descriptors (raw = the inputs), cached
//   descriptors/<method>.cmbof_vocabulary.txt  the method's CMBOF visual vocabulary
//   similarity_blocks/<method>_<framework>.<i>-of-<N>.csv  a shard's rows of a matrix
//   results.csv, retrieval.csv, pose_invariance.csv, similarity_<method>.csv (ICP),
//   similarity_<method>_ort.csv (ORT), similarity_<method>_cmbof.csv (CMBOF)
#pragma once

#include <limits>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "metrics/shape_retrieval.h"

namespace unfold {

struct BatchOptions {
  std::string input_dir;
  std::string output_dir;                        ///< created if missing
  std::vector<std::string> configs;              ///< YAML paths; method = file stem
  std::map<std::string, std::string> overrides;  ///< YAML path -> value, for every config
  int jobs = 1;                                  ///< shapes run at once
  int shard_index = 0;                           ///< run shapes k with k % shard_count == index
  int shard_count = 1;         ///< > 1: no dataset-wide files (collect later); once every
                               ///< shape is done, the shard's block of the similarity matrices
  bool skip_existing = false;  ///< keep each shape's configs whose rows exist with status ok
  bool progress = false;       ///< a progress line on stderr (the caller knows it is a terminal)
  RetrievalOptions retrieval;
};

struct BatchRow {
  std::string shape, shape_class, method;
  double E_rig = 0, E_str = 0, E_geo = 0;  ///< NaN: not computed (metrics.compute)
  double seconds = 0;  ///< the solve and metrics (unfold_prepared), not the shared preparation
  std::string status;  ///< "ok" or the error
  /// The damage measure (metrics/surface_damage.h, UnfoldMetrics::damage) and
  /// the inverted tets; NaN: unknown (a failed run, or a results.csv written
  /// before these columns).
  double damaged_edges_percent = std::numeric_limits<double>::quiet_NaN();
  double surface_edge_ratio_p999 = std::numeric_limits<double>::quiet_NaN();
  double surface_edge_ratio_max = std::numeric_limits<double>::quiet_NaN();
  double inverted_tets = std::numeric_limits<double>::quiet_NaN();
  /// The fold measure (metrics/surface_folds.h, UnfoldMetrics::folds): the share of
  /// surface edges whose bend sharpened by more than 90 degrees, and the
  /// 99.9th percentile of the change in degrees; NaN: unknown (as above).
  double folded_edges_percent = std::numeric_limits<double>::quiet_NaN();
  double dihedral_change_p999 = std::numeric_limits<double>::quiet_NaN();
  /// E_geo over the surface alone (UnfoldMetrics::E_geo_surface); NaN: not computed
  /// or unknown (as above).
  double E_geo_surface = std::numeric_limits<double>::quiet_NaN();
};

/// The class of a shape: its name without trailing digits and then without
/// trailing '_' or '-' ("cat3" -> "cat", "tr_reg_000" -> "tr_reg").
std::string shape_class(const std::string& shape);

/// "i/N" with 0 <= i < N. @throws UsageError otherwise
std::pair<int, int> parse_shard(const std::string& text);

/// The mesh files (known extensions) in dir, sorted by name.
/// @throws InputError if dir cannot be read or holds no mesh
std::vector<std::string> list_meshes(const std::string& dir);

/// Runs the batch (see the file comment); failures are recorded as rows with
/// their error and the run goes on.
/// @return the rows of the shapes of this shard, in shape then config order
/// @throws UsageError for bad options or configs (before any work),
///         InputError for an unreadable input_dir, OutputError for output_dir
std::vector<BatchRow> run_batch(const BatchOptions& options);

/// Writes shape,class,method,E_rig,E_str,E_geo,damaged_edges_percent,
/// surface_edge_ratio_p999,surface_edge_ratio_max,inverted_tets,folded_edges_percent,
/// dihedral_change_p999_degrees,E_geo_surface,seconds,status
/// (atomically); a metric not computed (NaN) is an empty field, and reads back
/// as NaN.
/// @throws OutputError
void write_results_csv(const std::string& path, const std::vector<BatchRow>& rows);

/// Reads a file written by write_results_csv, or by an earlier version without
/// E_geo_surface, the fold columns or the damage columns
/// (shape,class,method,E_rig,E_str,E_geo,seconds,status): those read as NaN.
/// @throws InputError
std::vector<BatchRow> read_results_csv(const std::string& path);

/// Retrieval (retrieval.csv: method,framework,queries,nn,first_tier,
/// second_tier,e_measure,dcg,precision_0.05..precision_1.00 as
/// metrics/retrieval_measures.h; the matrices similarity_<method>.csv,
/// similarity_<method>_ort.csv and similarity_<method>_cmbof.csv, assembled
/// from the block files of sharded runs and computed where none is found) and
/// pose invariance (pose_invariance.csv: class,method,pose_distance) for the
/// raw input poses and each method's canonical forms found in output_dir;
/// descriptors are read from their cache or computed and cached, and so is
/// each method's CMBOF vocabulary (descriptors/<method>.cmbof_vocabulary.txt).
/// @param meshes input mesh paths; methods the config stems
/// Unreadable input meshes are left out. @throws OutputError
void write_dataset_evaluation(const std::string& output_dir, const std::vector<std::string>& meshes,
                              const std::vector<std::string>& methods,
                              const RetrievalOptions& options);

}  // namespace unfold
