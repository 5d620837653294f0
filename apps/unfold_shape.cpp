// Writes the built-in articulated demo shape in a chosen pose as an OFF file:
//   unfold_shape --pose rest|0|1|2 --resolution N --output shape.off
// Exit codes: 0 ok, 2 bad flags, 5 output not writable.
#include <gflags/gflags.h>

#include <cstdio>
#include <fstream>
#include <iostream>
#include <limits>
#include <string>

#include "core/errors.h"
#include "shapes/articulated_shape.h"

DEFINE_string(pose, "rest", "pose: rest, or a preset index 0, 1, 2");
DEFINE_int32(resolution, unfold::kDefaultShapeResolution,
             "edges along the body length, in [16, 128] (about N^2 vertices)");
DEFINE_string(output, "", "output OFF file (required)");

namespace {

// Stand-in until the project's mesh writer lands: plain OFF, full precision.
void write_off(const unfold::SurfaceMesh& mesh, const std::string& path) {
  std::ofstream out(path);
  out.precision(std::numeric_limits<double>::max_digits10);
  out << "OFF\n" << mesh.V.rows() << ' ' << mesh.faces.size() << " 0\n";
  for (Eigen::Index i = 0; i < mesh.V.rows(); ++i)
    out << mesh.V(i, 0) << ' ' << mesh.V(i, 1) << ' ' << mesh.V(i, 2) << '\n';
  for (const auto& f : mesh.faces) {
    out << f.size();
    for (const int v : f) out << ' ' << v;
    out << '\n';
  }
  if (!out.flush()) throw unfold::OutputError("cannot write " + path);
}

unfold::ShapePose parse_pose(const std::string& name) {
  if (name == "rest") return unfold::ShapePose::rest();
  for (int k = 0; k < unfold::ShapePose::num_presets(); ++k)
    if (name == std::to_string(k)) return unfold::ShapePose::preset(k);
  throw unfold::UsageError("--pose must be rest or a preset index 0.." +
                           std::to_string(unfold::ShapePose::num_presets() - 1) + ", got '" + name +
                           "'");
}

// gflags exits with 1 on an unknown flag or a bad value; check each flag
// first so those cases exit with the project's usage code 2 instead.
void check_flags(int argc, char** argv) {
  for (int i = 1; i < argc; ++i) {
    std::string arg = argv[i];
    if (arg == "--") break;
    if (arg.size() < 2 || arg[0] != '-') continue;
    arg.erase(0, arg.find_first_not_of('-'));
    const size_t eq = arg.find('=');
    const std::string name = arg.substr(0, eq);
    gflags::CommandLineFlagInfo info;
    if (!gflags::GetCommandLineFlagInfo(name.c_str(), &info)) {
      const bool negated_bool = name.rfind("no", 0) == 0 &&
                                gflags::GetCommandLineFlagInfo(name.c_str() + 2, &info) &&
                                info.type == "bool";
      if (!negated_bool) throw unfold::UsageError("unknown flag --" + name);
      continue;
    }
    if (info.type == "bool" && eq == std::string::npos) continue;
    const std::string value = eq != std::string::npos ? arg.substr(eq + 1)
                              : i + 1 < argc          ? argv[++i]
                                                      : "";
    if (gflags::SetCommandLineOption(name.c_str(), value.c_str()).empty())
      throw unfold::UsageError("bad value '" + value + "' for --" + name);
  }
}

}  // namespace

int main(int argc, char** argv) {
  gflags::SetUsageMessage("unfold_shape --pose rest|0|1|2 --resolution N --output shape.off");
  try {
    check_flags(argc, argv);
    gflags::ParseCommandLineFlags(&argc, &argv, true);
    if (argc > 1) throw unfold::UsageError(std::string("unexpected argument '") + argv[1] + "'");
    if (FLAGS_output.empty()) throw unfold::UsageError("--output is required");
    const unfold::ShapePose pose = parse_pose(FLAGS_pose);
    write_off(unfold::make_articulated_shape(pose, FLAGS_resolution), FLAGS_output);
  } catch (const unfold::Error& e) {
    std::cerr << "unfold_shape: " << e.what() << '\n';
    return e.exit_code();
  }
  return 0;
}
