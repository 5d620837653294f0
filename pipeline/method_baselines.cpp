// The baselines without a cascade (configs/lsmds.yaml, scf.yaml, docs/baselines.md):
// one solve on the input's tets.
#include "pipeline/unfold_method.h"
#include "pipeline/unfold_steps.h"

namespace unfold {
namespace {

Method baseline(const char* name, const Stage& solve) {
  return {name,
          {
              check_and_simplify(),
              tetrahedralize_the_input(),
              // a preparation shared with a method that tetrahedralizes the unfolded shape
              tetrahedralize_deferred().when(tets_deferred),
              solve_edges(),
              solve,
              measure(),
          }};
}

}  // namespace

Method lsmds_method(const Options&) { return baseline("lsmds", lsmds_solve()); }

Method scf_method(const Options&) { return baseline("scf", scf_solve()); }

}  // namespace unfold
