#include "pipeline/unfold_surface.h"

#include <utility>

#include "mesh/check_surface_mesh.h"
#include "pipeline/unfold_components.h"
#include "pipeline/unfold_method.h"
#include "pipeline/unfold_state.h"

namespace unfold {

PreparedMesh prepare_mesh(const SurfaceMesh& input, const Options& options) {
  UnfoldState state(options);
  state.input = &input;
  StageRunner runner(&state);
  runner.run(preparation(choose_method(options).stages));
  runner.join();
  runner.add_times(&state.mesh);
  return std::move(state.mesh);
}

// A prepared mesh serves every config of a batch or a comparison: the method's
// stages after the preparation, on a copy of it.
UnfoldResult unfold_prepared(const PreparedMesh& prepared, const Options& options) {
  validate_options(options);
  UnfoldState state(options);
  state.mesh = prepared;
  StageRunner runner(&state);
  runner.run(unfolding(choose_method(options).stages));
  runner.join();
  UnfoldResult& result = state.result;
  result.stage_seconds = prepared.stage_seconds;
  result.seconds_prepare = prepared.seconds;
  result.seconds_contact = prepared.seconds_contact;
  runner.add_times(&result);
  return std::move(result);
}

UnfoldResult unfold_surface(const SurfaceMesh& input, const Options& options) {
  if (options.components == "separately" && check_surface_mesh(input, false).num_components > 1)
    return unfold_components_separately(input, options);
  UnfoldState state(options);
  state.input = &input;
  StageRunner runner(&state);
  runner.run(choose_method(options).stages);
  runner.join();
  runner.add_times(&state.result);
  return std::move(state.result);
}

}  // namespace unfold
