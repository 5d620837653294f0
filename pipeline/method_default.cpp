// The default method (configs/default.yaml; tetrahedralize.shape unfolded, or
// auto with a route other than conforming): the energy on the surface at low
// beta, solved to convergence and again with its joints softened, that change
// kept at the scale of limbs; that shape tetrahedralized, its interior put
// back into the input; the cascade's rotation field integrated on those tets
// (docs/method.md).
#include "core/fork_safety.h"
#include "pipeline/unfold_method.h"
#include "pipeline/unfold_steps.h"

namespace unfold {

Method default_method(const Options& options) {
  const CascadeDomain surface = CascadeDomain::surface;
  const bool integrate = integrates(options);
  StageList stages = {
      check_and_simplify(),
      // An open surface has no shape to tetrahedralize: its edge graph, or the fallback.
      tetrahedralize_the_input().when(surface_open),
      surface_geodesic_rows(),
  };
  // The anchor unit depends on the surface alone: beside the surface's
  // lambda_2 (one thread: a factorization and a Lanczos run), out of the way
  // of the solves' threads and of the soft joints' filter (its three
  // factorizations on two threads).
  if (integrate) stages.push_back(anchor_unit().on_the_side(kForkAlongsideThreads));
  append(&stages, {lambda2_and_beta(surface), cascade(surface)});
  if (softens(options))
    append(&stages, {soft_joints_lambda2(surface), soft_joints_cascade(surface),
                     soft_joints_filter(surface)});
  stages.push_back(full_resolution().when(coarse_surface_solve));
  // Given tets: as the run that made them on its unfolded shape did, when
  // they say where (--rest_tet_output's .vtu), else the interior placed.
  append(&stages, {
                      tets_of_unfolded().unless(keeps_input_tets),
                      given_unfolded_shape().when(given_tets_made_unfolded),
                      solve_edges(),
                      interior_placement().when(keeps_input_tets).unless(given_tets_made_unfolded),
                  });
  if (integrate) append(&stages, {integration(), anchored()});
  append(&stages, finish(options));
  return {"default", stages};
}

}  // namespace unfold
