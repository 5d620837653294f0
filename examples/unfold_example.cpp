// Unfolding a mesh with the installed library: read, unfold, write, picture.
// Usage: unfold_example [input.off] [canonical.off] [picture.png]
// Without arguments it unfolds the built-in demo shape into example_*.
#include <cstdio>
#include <string>

#include "config/options.h"
#include "core/errors.h"
#include "mesh/read_surface_mesh.h"
#include "mesh/write_surface_mesh.h"
#include "pipeline/result_pictures.h"
#include "pipeline/unfold_surface.h"
#include "render/write_png.h"
#include "shapes/articulated_shape.h"

int main(int argc, char** argv) {
  try {
    const unfold::SurfaceMesh input =
        argc > 1 ? unfold::read_surface_mesh(argv[1])
                 : unfold::make_articulated_shape(unfold::ShapePose::named("1"));
    const unfold::UnfoldResult result = unfold::unfold_surface(input, unfold::Options());
    unfold::write_surface_mesh(argc > 2 ? argv[2] : "example_canonical.off", result.canonical);
    unfold::write_png(argc > 3 ? argv[3] : "example.png",
                      unfold::render_before_after(result, unfold::RenderOptions()));
    std::printf("E_rig %.3f, edge ratio %.3f after %d iterations\n", result.metrics.E_rig,
                result.cascade.edge_ratio, result.cascade.iterations);
  } catch (const unfold::Error& e) {
    std::fprintf(stderr, "unfold_example: %s\n", e.what());
    return e.exit_code();
  }
  return 0;
}
