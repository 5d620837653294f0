// The small inputs and quick configs the option-matrix tests run the apps on:
// one mesh per input class, and the four methods' shipped configs with short
// cascades, so that a run takes a fraction of a second.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "config/options.h"
#include "mesh/read_surface_mesh.h"
#include "mesh/write_surface_mesh.h"
#include "shapes/articulated_shape.h"
#include "test_meshes.h"

namespace unfold::test {

/// The input classes: a clean closed surface, a self-intersecting one (the
/// auto route's robust fallback), two components, an open surface, and the
/// generated demo animal at a small resolution (the full-size built-in demo,
/// 8 s a run, is Cli.DemoRunWritesEveryOutput's).
enum MatrixInput { kClean, kSelfIntersecting, kTwoComponents, kOpenSurface, kDemo, kNumInputs };

inline const char* input_name(int input) {
  static const char* const names[] = {"clean", "self_intersecting", "two_components",
                                      "open_surface", "demo"};
  return names[input];
}

/// The method configs: configs/<name>.yaml (default is method local_global).
inline const char* const kMatrixConfigs[] = {"default", "ceres", "lsmds", "dpmu"};
constexpr int kNumMatrixConfigs = 4;

/// A directory for this process's matrix inputs, made once.
inline std::string matrix_dir() {
  static const std::string dir = [] {
    const std::string d = ::testing::TempDir() + "unfold_matrix_inputs_" + std::to_string(getpid());
    std::filesystem::create_directories(d);
    return d;
  }();
  return dir;
}

/// The mesh file of an input class (written on first use).
inline std::string matrix_input(int input) {
  const std::string corpus = UNFOLD_SOURCE_DIR "/tests/bad_inputs/";
  switch (input) {
    case kClean: {
      const std::string path = matrix_dir() + "/clean.off";
      if (!std::filesystem::exists(path)) write_surface_mesh(path, uv_sphere(8, 12));
      return path;
    }
    case kSelfIntersecting:
      return corpus + "self_intersecting.off";
    case kTwoComponents:
      return corpus + "two_components.off";
    case kOpenSurface:
      return corpus + "open_surface.off";
    default: {
      const std::string path = matrix_dir() + "/demo.ply";
      // Resolution 20 (321 vertices, stored): at 24 DPMU's run at a fixed beta
      // (unfold_compare --fixed_beta) took all of its 20,000 iterations, 14 s.
      if (!std::filesystem::exists(path))
        write_surface_mesh(path, make_articulated_shape(ShapePose::preset(1), 20));
      return path;
    }
  }
}

/// Vertices of an input class's mesh.
inline long matrix_input_vertices(int input) {
  return long(read_surface_mesh(matrix_input(input)).V.rows());
}

/// A quick copy of configs/<name>.yaml (short cascades, few iterations, one
/// thread) in the matrix directory, named <name>.yaml (the method name
/// unfold_batch derives from it).
inline std::string quick_config(const std::string& name) {
  const std::string path = matrix_dir() + "/" + name + ".yaml";
  if (std::filesystem::exists(path)) return path;
  Options options = load_options(UNFOLD_SOURCE_DIR "/configs/" + name + ".yaml");
  options.cascade.k_iter = 4;
  options.cascade.num_cascades = 2;
  options.ceres.max_num_iterations = 8;
  options.lsmds.max_iterations = 20;
  options.threads = 1;
  std::ofstream(path) << options_to_yaml(options);
  return path;
}

}  // namespace unfold::test
