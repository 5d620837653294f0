// Dense point-to-point correspondence between two shapes from their canonical
// forms (issue 46): rigid alignment of the forms, a decision between the map
// and its mirror image, then ZoomOut on the original surfaces' spectra.
#pragma once

#include <Eigen/Core>
#include <string>

#include "solvers/align_canonical_forms.h"
#include "solvers/laplace_beltrami_basis.h"
#include "solvers/zoomout.h"

namespace unfold {

/// The matcher's settings (config keys match.*).
struct MatchOptions {
  /// auto: the mirrored placement only when it fits clearly better
  /// (mirror_margin), else the rotation's; off: the best fit whatever its
  /// orientation (the plain rigid matcher)
  std::string mirror = "auto";
  /// mirror auto: the mirrored placement wins when its residual is below
  /// (1 - margin) times the rotation's; within the margin either way the
  /// decision is reported as ambiguous
  double mirror_margin = 0.4;
  /// descriptor: among the rotations' placements (the best fit and its half
  /// turns), the one whose refined map best keeps the shapes' multi-scale mean
  /// curvature (what tells a body's front from its back); residual: the best
  /// fit alone
  std::string placement = "descriptor";
  /// placement descriptor: a decision whose runner-up disagrees less than this
  /// many times the chosen one's disagreement is reported unsure
  double sure_margin = 1.05;
  /// unfold_match's batch: an unsure pair's rotation replaced by the one its
  /// cycles through sure pairs imply where the two differ (pipeline/match_pairs.h)
  bool synchronize = true;
  std::string refine = "zoomout";  ///< zoomout or none
  int spectral_size = 80;          ///< ZoomOut's final basis size (refine zoomout)
  FormAlignmentOptions alignment;
  ZoomOutOptions zoomout;  ///< its final_size is spectral_size
};

/// @throws UsageError naming the config key (match.*) of a value out of range
void validate_match_options(const MatchOptions& options);

/// What the matcher keeps of one shape, computed once and reused for every
/// pair it is in: the surface, its canonical form, (refine zoomout) its
/// Laplace-Beltrami basis and (placement descriptor) its curvature descriptor.
struct MatchShape {
  Eigen::MatrixX3d V;          ///< the surface as given
  Eigen::MatrixX3d canonical;  ///< its canonical form, same vertices
  Eigen::MatrixX3i F;          ///< triangles of both
  LaplaceBeltramiBasis basis;  ///< refine zoomout: spectral_size eigenpairs, else empty
  Eigen::VectorXd masses;      ///< the surface's lumped masses
  /// placement descriptor: mean_curvature_scales of the surface, else empty
  Eigen::MatrixXd curvature;
  double seconds_basis = 0;  ///< the basis and the descriptor
};

/// @throws UsageError if the sizes differ; InputError if the surface has no
///         area at a vertex; NumericalError if the eigensolver fails
MatchShape prepare_match_shape(const Eigen::MatrixX3d& V, const Eigen::MatrixX3d& canonical,
                               const Eigen::MatrixX3i& F, const MatchOptions& options);

/// A map and each step's map before it (one target vertex per source vertex).
struct ShapeMatch {
  Eigen::VectorXi map;    ///< the result
  Eigen::VectorXi rigid;  ///< nearest points after the best-fitting placement (any orientation)
  Eigen::VectorXi
      oriented;        ///< nearest points after the choice of placement and the mirror decision
  int candidates = 0;  ///< placements compared (FormAlignments::candidates)
  double rotation_residual = 0;  ///< FormAlignments::proper.residual
  double mirrored_residual = 0;  ///< FormAlignments::improper.residual
  bool mirrored = false;         ///< the map chosen reverses orientation (a mirror image)
  bool ambiguous = false;        ///< the two placements fit within mirror_margin: no clear cue
  /// the chosen placement's linear map of the unit-area forms (a rotation
  /// unless mirrored)
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  int placements = 0;  ///< placements of the chosen orientation compared (placement descriptor)
  /// the runner-up placement's curvature disagreement over the chosen one's
  /// (>= 1; infinity when one placement was compared, when ZoomOut took both
  /// to one map, or when the collection chose)
  double placement_margin = 0;
  bool sure = true;  ///< placement_margin >= match.sure_margin (or no choice to make)
  /// the rotation's placement came from the rotation seed (a collection's
  /// synchronized rotations), not from the pair's own best fit
  bool from_collection = false;
  /// one line: "rotation (mirror fits 1.42x worse)", "mirrored (fits 0.61x ...)", "ambiguous ..."
  std::string decision;
  double seconds_align = 0;   ///< alignment and the mirror decision
  double seconds_refine = 0;  ///< ZoomOut
};

/// Maps every vertex of `source` to a vertex of `target`: the canonical forms
/// aligned (align_canonical_forms); the mirror decision by the best ICP
/// residual of each orientation (the forms' asymmetry decides; a rigid motion
/// cannot mirror, so the rotation unless the mirror image fits clearly
/// better); among the rotations' placements (placement descriptor) the one
/// whose map, refined, disagrees least with the two surfaces' curvature
/// descriptors on ZoomOut's samples (a body turned round maps a face onto the
/// back of a head, toes onto heels); then ZoomOut on the input surfaces'
/// Laplace-Beltrami bases, from the chosen placement's nearest points.
/// @param rotation_seed if given, the rotation placement is the one refined
///        from this rotation of the unit-area forms (align_canonical_forms),
///        whatever the pair's own best-fitting rotation
/// @param aligned if given, align_canonical_forms(source, target) made
///        already (without a seed; a collection's synchronization did): not again
ShapeMatch match_shapes(const MatchShape& source, const MatchShape& target,
                        const MatchOptions& options, const Eigen::Matrix3d* rotation_seed = nullptr,
                        FormAlignments aligned = {});

}  // namespace unfold
