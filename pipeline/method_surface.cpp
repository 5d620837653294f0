// domain surface on the input's tets (configs/surface.yaml, invariant.yaml;
// tetrahedralize.shape input, or auto with route conforming): the energy on
// the surface, the interior placed by ARAP, the rotation field integrated.
#include "pipeline/unfold_method.h"
#include "pipeline/unfold_steps.h"

namespace unfold {

Method surface_method(const Options& options) {
  const CascadeDomain surface = CascadeDomain::surface;
  StageList stages = {
      check_and_simplify(),
      tetrahedralize_the_input(),
      surface_geodesic_rows(),
      // a preparation shared with a method that tetrahedralizes the unfolded shape
      tetrahedralize_deferred().when(tets_deferred),
      solve_edges(),
      lambda2_and_beta(surface),
      cascade(surface),
  };
  if (softens(options))
    append(&stages, {soft_joints_lambda2(surface), soft_joints_cascade(surface),
                     soft_joints_filter(surface)});
  stages.push_back(full_resolution().when(coarse_surface_solve));
  stages.push_back(interior_placement());
  if (integrates(options)) append(&stages, {anchor_unit(), integration(), anchored()});
  append(&stages, finish(options));
  return {"surface", stages};
}

}  // namespace unfold
