// Algorithm 1 of the paper: iterations in cascades of growing beta, stopped
// when the mean edge-length ratio enters a band around 1. The driver is shared
// by the solver backends (local-global, Ceres); each runs the iterations of
// one cascade at a fixed beta.
#pragma once

#include <Eigen/Core>
#include <array>
#include <vector>

namespace unfold {

struct UnfoldProblem;

struct CascadeOptions {
  double beta = 0;        ///< starting beta (absolute), > 0
  int k_iter = 15;        ///< iterations per cascade at most (local-global)
  double epsilon = 1e-4;  ///< a cascade ends when |f_e / f_s - 1| < epsilon (local-global)
  int num_cascades = 4;   ///< cascades at most ("num")
  double growth = 2.0;    ///< beta factor between cascades
  std::array<double, 2> edge_ratio_band = {0.95, 1.05};  ///< stop once the edge ratio is inside
  /// true: stop at the first iterate inside the band (the paper's Algorithm 1);
  /// false: finish that cascade (epsilon or k_iter) and check the band at its end,
  /// so that the result is not a transient (local-global; Ceres always finishes)
  bool break_in_band = true;
  int anderson = 0;  ///< Anderson acceleration window of local-global; 0: plain iterations
};

/// Whether an edge ratio is inside a band (ends included): the stopping test
/// of Algorithm 1, shared by the backends and the pipeline's later stages.
inline bool in_band(double edge_ratio, const std::array<double, 2>& band) {
  return edge_ratio >= band[0] && edge_ratio <= band[1];
}

struct IterationRecord {
  int iteration;  ///< 1-based over the whole run
  int cascade;    ///< 1-based
  double beta;
  double energy;      ///< the energy after the iteration, at that iteration's rotations
                      ///< (with Anderson acceleration: at the new positions' best rotations)
  double edge_ratio;  ///< delta after the iteration
};

/// What one cascade (stage) of a backend is told.
struct StageOptions {
  int max_iterations;
  double epsilon;
  std::array<double, 2> edge_ratio_band;
  bool break_in_band;  ///< stop at the first iterate inside the band, else at the stage's end
  int anderson;        ///< Anderson acceleration window (backends that iterate); 0: none
};

/// A solver backend, as the cascade driver sees it.
class CascadeBackend {
 public:
  virtual ~CascadeBackend() = default;
  /// Prepares iterations at a new beta (e.g. a numeric factorization).
  virtual void set_beta(double beta) = 0;
  /// False if the energy is unbounded below at the current beta (asked after
  /// run_stage, so a backend may find out while iterating).
  virtual bool bounded() const = 0;
  /// Iterates at the current beta from *Q until the energy converges or
  /// max_iterations pass, or (break_in_band) the edge ratio is in the band.
  /// Returns whether the last iterate's edge ratio is in the band.
  /// @param previous_energy in: f_s; out: the last energy (Algorithm 1's f_e)
  /// @param history         one record appended per iteration
  virtual bool run_stage(const StageOptions& options, int cascade, Eigen::MatrixX3d* Q,
                         double* previous_energy, std::vector<IterationRecord>* history) = 0;
};

struct CascadeResult {
  Eigen::MatrixX3d positions;  ///< canonical pose, zero mean
  int iterations = 0;
  int cascades = 0;  ///< number of beta values used
  double final_beta = 0;
  double final_energy = 0;  ///< at the final positions and their best rotations
  double edge_ratio = 0;
  bool reached_band = false;  ///< false: stopped by the cascade limit instead
  bool bounded = true;        ///< false if some beta was below the boundedness bound
  std::vector<IterationRecord> history;
};

/// Runs Algorithm 1 from Q = P, or from `start` (a warm start, e.g. the solution
/// of a nearby problem), with the given backend (at most options.k_iter
/// iterations per cascade for backends that count them).
/// @throws NumericalError if the backend fails or a non-finite position appears
CascadeResult run_cascade(const UnfoldProblem& problem, CascadeBackend& backend,
                          const CascadeOptions& options, const Eigen::MatrixX3d* start = nullptr);

}  // namespace unfold
