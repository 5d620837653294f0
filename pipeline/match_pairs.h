// unfold_match's batch: the pairs of a list matched, each shape unfolded once
// and its canonical form reused; a failing pair is reported and skipped; the
// maps optionally scored against .vts truth (docs/results/correspondence.md).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "config/options.h"
#include "solvers/match_canonical_forms.h"

namespace unfold {

/// Two shape names per content line, white-space separated (as the BCICP
/// dataset's test_pairs.txt); blank lines and '#' comments skipped.
/// @throws InputError naming the file and line for a line of another shape, or no pair
std::vector<std::pair<std::string, std::string>> read_shape_pairs(const std::string& path);

/// The mesh of shape `name` in `dir`: name.off, .obj, .ply or .stl (the first
/// that exists), or `name` itself when it names a file there.
/// @throws InputError "shape '<name>' not found in <dir> ..." when none exists
std::string find_shape_file(const std::string& dir, const std::string& name);

struct MatchBatchOptions {
  std::string input_dir;   ///< where the shapes' meshes are (and their .vts files)
  std::string output_dir;  ///< OUT/<source>__<target>.map (must exist)
  /// if not empty: canonical forms are read from <dir>/<name>.off when there
  /// (and of the shape's vertex count), else unfolded and written there
  std::string canonical_dir;
  bool evaluate = false;  ///< score each map against the shapes' .vts (and target .sym.vts)
  bool progress = false;  ///< one line per pair on stderr
};

/// The steps whose maps are scored: nearest points after the best-fitting
/// placement, after the mirror decision, after the refinement.
constexpr int kMatchSteps = 3;
extern const char* const kMatchStepNames[kMatchSteps];

struct PairOutcome {
  std::string source, target;
  std::string map_path;  ///< written when error is empty
  std::string error;     ///< one line; empty on success
  int exit_code = 0;     ///< the error's class (core/errors.h), 0 on success
  ShapeMatch match;
  double seconds = 0;  ///< matching alone (alignment, decision, refinement)
  /// evaluate: per step, per template point the error (strict / flip-forgiving)
  std::vector<Eigen::VectorXd> strict, forgiving;
  std::string evaluation_error;  ///< evaluate: why this pair was not scored
};

struct MatchBatch {
  std::vector<PairOutcome> pairs;  ///< in file order
  int shapes = 0;                  ///< shapes prepared (unfolded or read back)
  double seconds_shapes = 0;       ///< unfolding (or reading) and spectral bases, all shapes
  double seconds_pairs = 0;        ///< matching, all pairs
  double seconds_synchronize = 0;  ///< match.synchronize: the pairs' rotations compared
};

/// Matches every pair, writing OUT/<source>__<target>.map atomically. A pair
/// whose shape is missing or cannot be unfolded, or whose map cannot be
/// written, gets its error and no map; the others go on.
/// @throws UsageError for options out of range; OutputError if output_dir is not writable
MatchBatch run_match_batch(const std::vector<std::pair<std::string, std::string>>& pairs,
                           const MatchBatchOptions& batch, const Options& options);

/// The table of a scored batch: per step, the mean strict and flip-forgiving
/// errors (x100) over every template point of every scored pair, and the times.
std::string format_match_summary(const MatchBatch& batch);

/// Per pair: source, target, decision, seconds, and per step the strict and
/// flip-forgiving mean errors (x100), as CSV.
/// @throws OutputError naming the path
void write_match_csv(const std::string& path, const MatchBatch& batch);

/// Cumulative curves (share of template points under each error, errors up to
/// 0.25 drawn, larger ones at 0.25) of every step, strict, and the last step
/// flip-forgiving, as a PNG. @throws UsageError if nothing was scored
void write_match_cdf(const std::string& path, const MatchBatch& batch, const std::string& title);

}  // namespace unfold
