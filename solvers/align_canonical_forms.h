// Rigid alignment of two canonical forms, the first step of a dense map
// between two shapes: both scaled to unit area, every candidate frame from
// their principal axes tried by ICP, the best orientation-preserving one and
// the best orientation-reversing one (its mirror image) kept.
#pragma once

#include <Eigen/Core>
#include <vector>

namespace unfold {

struct FormAlignmentOptions {
  int coarse_points = 400;     ///< points per form while every candidate frame is tried
  int coarse_iterations = 12;  ///< ICP iterations per candidate frame
  int iterations = 30;         ///< ICP iterations of each kept candidate
  /// points per form while the kept candidates are refined (every vertex when
  /// fewer): a placement's residual is a mean, which samples estimate well
  int points = 2000;
  /// candidates kept per orientation: the distinct placements whose coarse
  /// residual is within `keep_ratio` times the best of their orientation, at most `keep`
  int keep = 1;
  double keep_ratio = 1.5;
  /// also the best rotation turned half round about each of the target's
  /// principal axes (a body's back placed onto its front fits about as well
  /// as its front: which of them is right only the shapes' detail tells)
  bool turns = true;
};

/// One rigid (or mirrored rigid) placement of the source form onto the target form.
struct FormAlignment {
  /// source vertex p (unit area, centred) goes to linear * p + translation;
  /// det(linear) = +1 for a rotation, -1 for a rotation composed with a reflection
  Eigen::Matrix3d linear = Eigen::Matrix3d::Identity();
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();
  /// after ICP: the mean of the mean nearest-point distances source -> target
  /// and target -> source, in units of sqrt(area) (0: the forms coincide)
  double residual = 0;
  Eigen::MatrixX3d moved;  ///< the source's vertices so placed (n_source x 3)
  bool mirrored = false;   ///< det(linear) = -1
  bool seeded = false;     ///< refined from the given rotation seed, not from a principal frame
};

struct FormAlignments {
  /// distinct placements, each a local optimum of ICP: rotations first, then
  /// mirrored ones, each group by increasing residual (at least one of each);
  /// then, with a rotation seed, the placement refined from it
  std::vector<FormAlignment> candidates;
  Eigen::MatrixX3d source;  ///< the source form centred, at unit area
  Eigen::MatrixX3d target;  ///< the target form centred, at unit area (what `moved` fits)
};

/// A form centred at its area-weighted centroid and scaled to unit area.
/// @throws InputError if the surface has no area
Eigen::MatrixX3d unit_area_form(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F);

/// Aligns the source form to the target form: each form centred and scaled to
/// unit area (unit_area_form), its principal axes (area-weighted covariance);
/// each of the 48 signed permutations between the two frames (24 rotations, 24
/// mirrored) refined by ICP on `coarse_points` points of each form; per
/// orientation the distinct ones that fit nearly as well as the best (`keep`,
/// `keep_ratio`: a body's front and back can fit about alike, which only
/// intrinsic cues tell apart) refined on `points` points of each form, ICP
/// with nearest points both ways (so neither form's extra parts are ignored),
/// in parallel; with `turns`, the
/// best rotation's three half turns about the target's axes refined the same
/// way, those that ICP does not take onto a placement kept already.
/// @param source_V, source_F the source's canonical form (n x 3, triangles)
/// @param target_V, target_F the target's canonical form
/// @param rotation_seed if given, a rotation of the unit-area forms from
///        elsewhere (a collection's synchronized rotations): one more
///        candidate, ICP from it, `seeded`
/// @throws UsageError for options out of range (coarse_points or points < 4, iterations < 1);
///         InputError if a form has no area
FormAlignments align_canonical_forms(const Eigen::MatrixX3d& source_V,
                                     const Eigen::MatrixX3i& source_F,
                                     const Eigen::MatrixX3d& target_V,
                                     const Eigen::MatrixX3i& target_F,
                                     const FormAlignmentOptions& options = {},
                                     const Eigen::Matrix3d* rotation_seed = nullptr);

/// Adds to `aligned` (of align_canonical_forms, whose forms it uses) the
/// placement refined by ICP (on `points` points) from `rotation_seed`, `seeded`:
/// what align_canonical_forms' rotation_seed adds, for alignments made before
/// the seed was known (a collection's synchronization).
/// @throws UsageError for options out of range or `aligned` without forms
void add_seeded_alignment(const Eigen::Matrix3d& rotation_seed, const FormAlignmentOptions& options,
                          FormAlignments* aligned);

}  // namespace unfold
