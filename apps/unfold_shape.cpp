// Writes the built-in articulated demo shape in a chosen pose:
//   unfold_shape --pose rest|0|1|2|contact0|contact1|mouth|mouth_open --resolution N --output
//   shape.off
#include "apps/app_main.h"
#include "mesh/write_surface_mesh.h"
#include "shapes/articulated_shape.h"

DEFINE_string(
    pose, "rest",
    "pose: rest, a preset index 0, 1, 2, contact0, contact1 (the body touching itself), or "
    "mouth, mouth_open (the head with a mouth: lips closed and touching, or open; another mesh)");
DEFINE_int32(resolution, unfold::kDefaultShapeResolution,
             "edges along the body length, in [16, 128] (about N^2 vertices)");
DEFINE_string(output, "", "output mesh (.off .obj .ply .stl), required");

int main(int argc, char** argv) {
  unfold::app::AppHelp help;
  help.usage =
      "unfold_shape --output shape.off [--pose rest|0|1|2|contact0|contact1|mouth|mouth_open] "
      "[--resolution N]";
  help.summary = "Writes the built-in demo shape, a four-legged animal, in a chosen pose.";
  help.groups = {{"Input and output", {"output"}}, {"Shape", {"pose", "resolution"}}};
  return unfold::app::run_main("unfold_shape", help, argc, argv, [] {
    if (FLAGS_output.empty()) throw unfold::UsageError("--output is required");
    unfold::check_surface_mesh_format(FLAGS_output);
    const unfold::ShapePose pose = unfold::ShapePose::named(FLAGS_pose);
    unfold::write_surface_mesh(FLAGS_output,
                               unfold::make_articulated_shape(pose, FLAGS_resolution));
    return 0;
  });
}
