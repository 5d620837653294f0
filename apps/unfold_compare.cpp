// unfold_compare: several configs (solvers, energy terms) on one tet mesh.
//   unfold_compare --input X --configs a.yaml,b.yaml [--fixed_beta B] [--csv FILE]
#include <sstream>

#include "apps/app_main.h"
#include "core/atomic_file.h"
#include "mesh/read_surface_mesh.h"
#include "pipeline/compare_configs.h"
#include "shapes/articulated_shape.h"

DEFINE_string(input, "", "surface mesh; empty: the built-in demo shape (--demo_pose)");
DEFINE_string(demo_pose, "0", "pose of the built-in demo shape when --input is empty");
DEFINE_string(configs, "", "comma-separated YAML configs to compare (required)");
DEFINE_double(fixed_beta, 0,
              "if > 0: run every config at this one beta (relative to n/lambda_2) to "
              "convergence, without the cascade");
DEFINE_string(csv, "", "also write the table as CSV");

int main(int argc, char** argv) {
  unfold::app::AppHelp help;
  help.usage = "unfold_compare [--input X] --configs a.yaml,b.yaml [--fixed_beta B] [--csv FILE]";
  help.summary =
      "Compares configs (solvers, energy terms) on one mesh and one tet mesh; prints a table.";
  help.groups = {
      {"Input and output", {"input", "demo_pose", "csv"}},
      {"Method and config", {"configs", "fixed_beta"}},
  };
  return unfold::app::run_main("unfold_compare", help, argc, argv, [] {
    std::vector<std::string> configs;
    std::istringstream list(FLAGS_configs);
    for (std::string item; std::getline(list, item, ',');)
      if (!item.empty()) configs.push_back(item);
    if (configs.empty()) throw unfold::UsageError("--configs is required");
    if (FLAGS_fixed_beta < 0) throw unfold::UsageError("--fixed_beta must be > 0");
    if (!FLAGS_csv.empty()) unfold::check_writable_destination(FLAGS_csv);
    const unfold::SurfaceMesh surface =
        FLAGS_input.empty()
            ? unfold::make_articulated_shape(unfold::ShapePose::named(FLAGS_demo_pose))
            : unfold::read_surface_mesh(FLAGS_input);
    unfold::app::ProgressScope progress("unfold_compare", false);  // -vv's lines of detail
    const auto rows = unfold::compare_configs(
        surface, configs,
        FLAGS_fixed_beta > 0 ? std::optional<double>(FLAGS_fixed_beta) : std::nullopt);
    progress.finish();
    std::fputs(unfold::format_comparison(rows).c_str(), stdout);
    if (!FLAGS_csv.empty()) unfold::write_comparison_csv(FLAGS_csv, rows);
    return 0;
  });
}
