// tetrahedralize.shape contact: the default's tets of the unfolded shape where
// parts of the surface are in contact (faces passing through each other, or
// an input tet bridging them), else the input's, its interior placed by ARAP.
#include "core/fork_safety.h"
#include "pipeline/unfold_method.h"
#include "pipeline/unfold_steps.h"

namespace unfold {

Method contact_method(const Options& options) {
  const CascadeDomain surface = CascadeDomain::surface;
  const bool integrate = integrates(options);
  StageList stages = {
      check_and_simplify(),
      find_contact(),
      // The surface solve needs no tets: it runs while TetGen (a process of
      // its own) makes the input's.
      tetrahedralize_the_input().unless(contact_faces_found).on_the_side(kForkAlongsideThreads),
      surface_geodesic_rows(),
      lambda2_and_beta(surface),
      cascade(surface),
  };
  if (softens(options))
    append(&stages, {soft_joints_lambda2(surface), soft_joints_cascade(surface),
                     soft_joints_filter(surface)});
  stages.push_back(full_resolution().when(coarse_surface_solve));
  append(&stages,
         {
             // a preparation shared with a method that tetrahedralizes the unfolded shape
             tetrahedralize_deferred().joining().when(tets_deferred).unless(contact_faces_found),
             check_contact_bridges(),
         });
  if (integrate) stages.push_back(anchor_unit().when(contact).on_the_side(kForkAlongsideThreads));
  append(&stages, {
                      tets_of_unfolded().when(contact),
                      solve_edges(),
                      interior_placement().unless(contact),
                  });
  if (integrate) append(&stages, {anchor_unit().unless(contact), integration(), anchored()});
  append(&stages, finish(options));
  return {"contact", stages};
}

}  // namespace unfold
