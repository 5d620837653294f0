// The paper's method (configs/paper.yaml; domain volume): the cascade of beta
// values on the input's tet mesh. The dpmu and ceres configs run the same
// list with another backend (options.method).
#include "pipeline/unfold_method.h"
#include "pipeline/unfold_steps.h"

namespace unfold {

Method paper_method(const Options& options) {
  const CascadeDomain tets = CascadeDomain::tets;
  StageList stages = {
      check_and_simplify(),
      tetrahedralize_the_input(),
      surface_geodesic_rows(),
      // a preparation shared with a method that tetrahedralizes the unfolded shape
      tetrahedralize_deferred().when(tets_deferred),
      solve_edges(),
      lambda2_and_beta(tets),
      cascade(tets),
  };
  if (softens(options))
    append(&stages,
           {soft_joints_lambda2(tets), soft_joints_cascade(tets), soft_joints_filter(tets)});
  if (integrates(options)) append(&stages, {anchor_unit(), integration(), anchored()});
  append(&stages, finish(options));
  return {"paper", stages};
}

}  // namespace unfold
