// The stages (stages/) as steps of a method: each applies one stage function
// to the state (pipeline/unfold_state.h), taking its inputs from there and
// putting its output back. Methods list them (pipeline/unfold_method.h).
#pragma once

#include "config/options.h"
#include "pipeline/run_stages.h"
#include "pipeline/unfold_state.h"

namespace unfold {

// The preparation (prepare_mesh).
Stage check_and_simplify();        ///< the checks, the simplification (options.target_vertices)
Stage find_contact();              ///< tetrahedralize.shape contact: intersecting faces far apart
Stage tetrahedralize_the_input();  ///< the input's tets, or the surface alone (fallback)

// The unfolding (unfold_prepared).
Stage tetrahedralize_deferred();  ///< the input's tets, which the preparation left to be made
Stage check_contact_bridges();    ///< some input tet bridges a contact (contact_bridge)
Stage solve_edges();              ///< the edges of the tets (E_geo's rows started beside)
enum class CascadeDomain { surface, tets };
Stage lambda2_and_beta(CascadeDomain domain);     ///< setup_cascade on the domain
Stage cascade(CascadeDomain domain);              ///< solve_cascade
Stage soft_joints_lambda2(CascadeDomain domain);  ///< setup_cascade again, the joints softened
Stage soft_joints_cascade(CascadeDomain domain);  ///< solve_cascade from the first solution
Stage soft_joints_filter(CascadeDomain domain);   ///< filter_change from the first solution
Stage full_resolution();       ///< a coarse surface solve carried to every surface vertex
Stage tets_of_unfolded();      ///< the tets of the surface solve's shape
Stage given_unfolded_shape();  ///< given tets' unfolded positions in place of tets_of_unfolded
Stage interior_placement();    ///< the input tets' interior by ARAP
Stage lsmds_solve();           ///< method lsmds
Stage scf_solve();             ///< method scf
Stage anchor_unit();           ///< lambda_2 of the surface: the integration's anchor unit
Stage integration();           ///< the rotation field integrated (one ARAP step)
Stage anchored();              ///< the anchored ARAP steps after it
Stage untangle();              ///< the canonical tets' inverted ones mended (untangle_tets)
Stage measure();               ///< the canonical pose placed, the metrics
/// E_geo_surface's rows of the rest surface, beside the solve on small meshes (the
/// measure stage joins it)
Stage surface_geodesic_rows();
/// Every method's last stages: untangle (untangle.sweeps > 0), then measure.
StageList finish(const Options& options);

// Conditions and choices of the options.
bool surface_open(const UnfoldState& state);
/// the surface stages solve on clusters (simplify.surface_solve_hops)
bool coarse_surface_solve(const UnfoldState& state);
bool contact_faces_found(const UnfoldState& state);  ///< by find_contact
bool has_tets(const UnfoldState& state);
bool given_tets(const UnfoldState& state);     ///< prepare_mesh_from_tets: the user's, kept
bool tets_deferred(const UnfoldState& state);  ///< the preparation made no tets
/// the unfolding keeps the input's tets though its method makes the unfolded
/// shape's: they are given, or there are none to make (an open surface's graph)
bool keeps_input_tets(const UnfoldState& state);
/// given tets that say where they were made (the point array "unfolded" of a
/// default run's --rest_tet_output): the default's route takes them as it did
bool given_tets_made_unfolded(const UnfoldState& state);
/// tets not given, and parts in contact: intersecting faces far apart, or an
/// input tet bridging them (check_contact_bridges)
bool contact(const UnfoldState& state);
/// soften.scale > 0 with an ARAP term: the surface solve again, the joints softened
bool softens(const Options& options);
/// soften.filter or soften.filter_stretch > 0: the soft joints' change filtered
bool filters_soft_joints(const UnfoldState& state);
/// integrate.iterations > 0 for a cascade method (LSMDS has no rotations to
/// integrate, SCF's ARAP refinement is its own)
bool integrates(const Options& options);
/// untangle.sweeps > 0
bool untangles(const Options& options);

}  // namespace unfold
