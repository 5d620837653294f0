// The baselines without a cascade (configs/lsmds.yaml, scf.yaml, docs/baselines.md):
// one solve on the input's tets.
#include "pipeline/unfold_method.h"
#include "pipeline/unfold_steps.h"

namespace unfold {
namespace {

Method baseline(const char* name, const Stage& solve, const Options& options) {
  StageList stages = {
      check_and_simplify(),
      tetrahedralize_the_input(),
      surface_geodesic_rows(),
      // a preparation shared with a method that tetrahedralizes the unfolded shape
      tetrahedralize_deferred().when(tets_deferred),
      solve_edges(),
      solve,
  };
  append(&stages, finish(options));
  return {name, stages};
}

}  // namespace

Method lsmds_method(const Options& options) { return baseline("lsmds", lsmds_solve(), options); }

Method scf_method(const Options& options) { return baseline("scf", scf_solve(), options); }

}  // namespace unfold
