// The bad-input corpus (tests/bad_inputs/ plus binary files written here):
// every case runs the unfold command line and checks its exit code, the key
// words of its one-line message and that no output file was left behind.
// Tolerated defects (non-manifold edges and vertices) and the graceful paths
// the config allows are in the table too, with exit 0 and their warning.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <functional>
#include <ostream>
#include <string>
#include <vector>

#include "run_app.h"
#include "test_files.h"

namespace unfold {
namespace {

std::string corpus(const std::string& name) {
  return UNFOLD_SOURCE_DIR "/tests/bad_inputs/" + name;
}

// Scratch path unique to this process (ctest runs cases in parallel).
std::string scratch(const std::string& name) {
  return ::testing::TempDir() + "bad_inputs_" + std::to_string(getpid()) + "_" + name;
}

template <typename T>
std::string bytes_of(T value) {
  return std::string(reinterpret_cast<const char*>(&value), sizeof(value));
}

std::string float_triple(float x, float y, float z) {
  return bytes_of(x) + bytes_of(y) + bytes_of(z);
}

// A binary file written at run time; returns "--input <path>".
std::string binary_input(const std::string& name, const std::string& bytes) {
  const std::string path = scratch(name);
  test::write_bytes(path, bytes);
  return "--input " + path;
}

const std::string kPlyHeader =
    "ply\nformat binary_little_endian 1.0\nelement vertex 4\nproperty float x\n"
    "property float y\nproperty float z\nelement face 4\n"
    "property list uchar int vertex_indices\nend_header\n";

// 4 vertices of a tetrahedron, then the first `faces` of its 4 faces.
std::string binary_ply_body(int faces) {
  std::string body =
      float_triple(0, 0, 0) + float_triple(1, 0, 0) + float_triple(0, 1, 0) + float_triple(0, 0, 1);
  const int32_t tris[4][3] = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  for (int f = 0; f < faces; ++f) {
    body += char(3);
    for (int k = 0; k < 3; ++k) body += bytes_of(tris[f][k]);
  }
  return body;
}

// Binary STL: 80-byte header, a triangle count, then `written` 50-byte records.
std::string binary_stl(const std::string& header, uint32_t declared, int written) {
  std::string bytes = header;
  bytes.resize(80, ' ');
  bytes += bytes_of(declared);
  for (int t = 0; t < written; ++t)
    bytes += float_triple(0, 0, 1) + float_triple(0, 0, 0) + float_triple(1, 0, 0) +
             float_triple(0, 1, float(t)) + std::string(2, '\0');
  return bytes;
}

struct BadInput {
  std::string name;
  std::function<std::string()> args;  ///< command-line arguments (files made on demand)
  int code;                           ///< expected exit code
  std::string words;                  ///< expected in stderr
};

// gtest prints the case by name instead of its bytes.
void PrintTo(const BadInput& c, std::ostream* out) { *out << c.name; }

std::function<std::string()> input(const std::string& file, const std::string& extra = "") {
  return [=] { return "--input " + corpus(file) + (extra.empty() ? "" : " " + extra); };
}
std::function<std::string()> config(const std::string& file) {
  return [=] { return "--config " + corpus(file); };
}
std::function<std::string()> flags(const std::string& text) {
  return [=] { return text; };
}

const std::vector<BadInput>& cases() {
  static const std::vector<BadInput> table = {
      // Missing, empty, unreadable or wrongly named files.
      {"missing_file", flags("--input /nonexistent/shape.off"), 3, "/nonexistent/shape.off"},
      {"empty_file", input("empty.off"), 3, "the file is empty"},
      {"comments_only", input("comments_only.off"), 3, "the file is empty"},
      {"wrong_extension", input("wrong_extension.xyz"), 3, "unsupported extension"},
      {"directory_as_input",
       [] {
         std::filesystem::create_directories(scratch("dir.off"));
         return "--input " + scratch("dir.off");
       },
       3, "it is a directory"},
      // Truncated and garbled text files.
      {"off_no_header", input("no_header.off"), 3, "no OFF header"},
      {"off_truncated_vertices", input("truncated_vertices.off"), 3, "truncated"},
      {"off_truncated_faces", input("truncated_faces.off"), 3, "truncated: 2 of 4 faces"},
      {"off_garbled_coordinate", input("garbled_coordinate.off"), 3,
       "bad coordinates for vertex 1"},
      {"off_garbled_face", input("garbled_face.off"), 3, "bad vertex index 'one' in face 1"},
      {"obj_garbled_vertex", input("garbled.obj"), 3, "bad vertex 2"},
      {"obj_bad_face_reference", input("bad_face_reference.obj"), 3, "bad vertex reference 'x'"},
      {"obj_no_faces", input("no_faces.obj"), 3, "no faces"},
      {"ply_ascii_truncated", input("truncated.ply"), 3, "truncated: 2 of 4 face elements"},
      {"ply_no_end_header", input("no_end_header.ply"), 3, "no end_header"},
      {"ply_unknown_format", input("unknown_format.ply"), 3, "unknown PLY format 'ebcdic'"},
      {"stl_ascii_truncated", input("truncated_ascii.stl"), 3, "no endsolid"},
      {"stl_garbage", input("garbage.stl"), 3, "neither ASCII STL"},
      // Truncated and garbled binary files.
      {"ply_binary_truncated_faces",
       [] { return binary_input("cut_faces.ply", kPlyHeader + binary_ply_body(2)); }, 3,
       "truncated"},
      {"ply_binary_truncated_vertices",
       [] {
         return binary_input("cut_vertices.ply", kPlyHeader + binary_ply_body(0).substr(0, 20));
       },
       3, "truncated"},
      {"ply_binary_garbled_list",
       [] {
         std::string body = binary_ply_body(4);
         body[48] = char(200);  // first face claims 200 corners
         return binary_input("garbled_list.ply", kPlyHeader + body);
       },
       3, "cannot read"},
      {"stl_binary_truncated", [] { return binary_input("cut.stl", binary_stl("mesh", 4, 2)); }, 3,
       "size does not match 4 triangles"},
      {"stl_binary_with_solid_header_truncated",
       [] { return binary_input("solid_cut.stl", binary_stl("solid mesh", 4, 2)); }, 3,
       "no endsolid"},
      {"off_binary_truncated",
       [] {
         return binary_input("cut_binary.off", "OFF BINARY\n" + bytes_of(int32_t(4)) +
                                                   bytes_of(int32_t(4)) + bytes_of(int32_t(0)) +
                                                   float_triple(0, 0, 0) + float_triple(1, 0, 0));
       },
       3, "truncated"},
      {"off_binary_corrupt_face_size", input("binary_bad_face_count.off"), 3,
       "bad vertex count"},  // found by fuzzing: OpenMesh allocated 8 GB
      {"ply_binary_header_garbage", input("binary_header_garbage.ply"), 3,
       "non-text byte in the PLY header"},  // found by fuzzing: OpenMesh looped forever
      {"off_binary_header_garbage", input("binary_header_garbage.off"), 3,
       "no OFF header (found 'OFF?OFF')"},  // found by fuzzing: OpenMesh allocated 3 GB
      {"ply_binary_header_hash", input("binary_header_hash.ply"), 3,
       "'#' in the PLY header"},  // found by fuzzing: OpenMesh looped forever
      {"off_binary_header_carriage_return", input("binary_header_cr.off"), 3,
       "bad header or vertex and face counts"},  // found by fuzzing: OpenMesh read it as text
      {"ply_binary_element_without_properties", input("binary_no_properties.ply"), 3,
       "has 500000000 records but no properties"},  // found by fuzzing: OpenMesh took minutes
      // Huge declared counts with little data: refused before allocating.
      {"off_huge_counts", input("huge_counts.off"), 3, "declares 2000000000 vertices"},
      {"ply_huge_counts", input("huge_counts.ply"), 3, "declares 1000000000 vertices"},
      {"stl_binary_huge_count",
       [] { return binary_input("huge.stl", binary_stl("mesh", 0xFFFFFFFFu, 1)); }, 3,
       "size does not match 4294967295 triangles"},
      // Meshes that read but cannot be unfolded.
      {"nan_coordinate", input("nan_coordinate.off"), 3, "vertex 2 has a non-finite coordinate"},
      {"inf_coordinate", input("inf_coordinate.obj"), 3,
       "vertex 3 has a non-finite coordinate (inf)"},
      {"index_out_of_range", input("index_out_of_range.off"), 3, "face 1 refers to vertex 7"},
      {"negative_index", input("negative_index.off"), 3, "face 1 refers to vertex -1"},
      {"repeated_vertex", input("repeated_vertex.off"), 3, "face 1 repeats vertex 1"},
      {"two_vertex_face", input("two_vertex_face.off"), 3, "face 4 has 2 vertices"},
      {"zero_area_face", input("zero_area_face.off"), 3, "face 4 has zero area"},
      {"huge_coordinates", input("huge_coordinates.off"), 3,
       "coordinates too large to process: the bounding box diagonal is 1.73e+308"},
      {"tiny_coordinates", input("tiny_coordinates.off"), 3,
       "coordinates too small to process: the bounding box diagonal is 1.73e-200"},
      {"unreferenced_vertex", input("unreferenced_vertex.off"), 3, "vertex 4 is used by no face"},
      {"open_surface", input("open_surface.off"), 3, "the surface is open (3 boundary edges)"},
      {"three_vertices", input("three_vertices.off"), 3, "the surface is open"},
      {"two_components", input("two_components.off"), 3, "2 connected components"},
      {"self_intersecting",
       input("self_intersecting.off", "--tet_shape input --tet_route conforming"), 4,
       "tetrahedralization (conforming route): TetGen"},
      {"cotangent_on_surface_graph",
       input("open_surface.off", "--fallback_surface_graph true --arap_weights cotangent"), 2,
       "no tets to take cotangent weights from"},
      {"cotangent_on_surface_domain",
       input("open_surface.off", "--domain surface --arap_weights cotangent"), 2,
       "domain: surface has no tets"},
      {"overflowing_beta",
       input("open_surface.off", "--fallback_surface_graph true --beta_mode absolute --beta 1e308"),
       4, "factorizing the global matrix failed at beta = 1e+308"},
      {"user_pairs_out_of_range",
       [] {
         return "--input " + corpus("nonmanifold_edge.off") + " --user_pairs " +
                corpus("pairs_out_of_range.csv");
       },
       3, "vertex index 99999 is not in [0, "},
      {"user_pairs_short_row",
       [] {
         return "--input " + corpus("nonmanifold_edge.off") + " --user_pairs " +
                corpus("pairs_short_row.csv");
       },
       3, "line 2: expected i, j, tx, ty, tz"},
      {"user_pairs_missing", input("nonmanifold_edge.off", "--user_pairs /nonexistent/p.csv"), 3,
       "cannot read user pairs file '/nonexistent/p.csv'"},
      // Bad configuration files and flags.
      {"config_missing", flags("--config /nonexistent/c.yaml"), 2, "/nonexistent/c.yaml"},
      {"config_invalid_yaml", config("invalid_yaml.yaml"), 2, "invalid YAML"},
      {"config_not_a_mapping", config("not_a_mapping.yaml"), 2, "is not a mapping"},
      {"config_complex_key", config("complex_key.yaml"), 2, "is not a plain name"},
      {"config_unknown_key", config("unknown_key.yaml"), 2, "unknown config key 'cascade.kiter'"},
      {"config_mistyped_value", config("mistyped_value.yaml"), 2,
       "'cascade.k_iter' must be an integer"},
      {"config_nan_beta", config("nan_beta.yaml"), 2, "beta.value"},
      {"config_negative_beta", config("negative_beta.yaml"), 2, "beta.value"},
      {"config_k_iter_zero", config("zero_k_iter.yaml"), 2, "cascade.k_iter"},
      {"flag_negative_beta", flags("--beta -3"), 2, "beta.value"},
      {"flag_nan_beta", flags("--beta nan"), 2, "beta.value"},
      {"flag_k_iter_zero", flags("--k_iter 0"), 2, "cascade.k_iter"},
      {"flag_unknown", flags("--no_such_flag 1"), 2, "unknown flag --no_such_flag"},
      {"flag_bad_components", flags("--components sometimes"), 2, "components"},
      {"flag_bad_boolean", flags("--fallback_surface_graph maybe"), 2, "must be true or false"},
      {"stray_argument", flags("shape.off"), 2, "unexpected argument 'shape.off'"},
      // Outputs that cannot be written: refused before any work.
      {"output_bad_extension", flags("--input_copy " + scratch("copy.xyz")), 5,
       "unsupported extension"},
      {"output_directory_missing", flags("--metrics_json /nonexistent_dir/m.json"), 5,
       "/nonexistent_dir"},
      {"output_directory_is_a_file",
       [] { return "--metrics_json " + corpus("empty.off") + "/m.json"; }, 5,
       "cannot write '" UNFOLD_SOURCE_DIR "/tests/bad_inputs/empty.off/m.json'"},
      {"output_directory_read_only",
       [] {
         const std::string dir = scratch("read_only");
         std::filesystem::create_directories(dir);
         chmod(dir.c_str(), 0555);
         return "--metrics_json " + dir + "/m.json";
       },
       5, "Permission denied"},
      // Tolerated defects and graceful paths: exit 0 with a warning, or with
      // the path's line among the stages' (-v).
      {"nonmanifold_edge", input("nonmanifold_edge.off"), 0, "1 non-manifold edges"},
      {"nonmanifold_vertex", input("nonmanifold_vertex.off"), 0, "1 non-manifold vertices"},
      {"open_surface_on_surface_graph", input("open_surface.off", "--fallback_surface_graph true"),
       0, "unfolding on the surface edge graph"},
      {"self_intersecting_on_surface_graph",
       input("self_intersecting.off",
             "--tet_shape input --tet_route conforming --fallback_surface_graph true"),
       0, "unfolding on the surface edge graph"},
      {"self_intersecting_robust_route", input("self_intersecting.off", "-v --tet_shape input"), 0,
       "using the robust route"},
      {"self_intersecting_contact", input("self_intersecting.off", "-v --tet_shape contact"), 0,
       "parts passing through each other"},
      {"self_intersecting_unfolded", input("self_intersecting.off", "-v"), 0,
       "tetrahedralized the unfolded shape (robust)"},
      {"two_components_separately", input("two_components.off", "-v --components separately"), 0,
       "2 connected components"},
  };
  return table;
}

class BadInputs : public ::testing::TestWithParam<BadInput> {};

TEST_P(BadInputs, ExitCodeMessageAndNoOutput) {
  const BadInput& c = GetParam();
  if (c.name == "output_directory_read_only" && geteuid() == 0)
    GTEST_SKIP() << "running as root: permissions do not stop writes";
  const std::string output = scratch(c.name + ".off");
  std::remove(output.c_str());
  if (c.code != 0) {
    test::expect_failure(c.args(), c.code, c.words, output);
    return;
  }
  const test::AppRun r = test::run_unfold(c.args() + " --output " + output);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find(c.words), std::string::npos) << "'" << c.words << "' not in: " << r.err;
  EXPECT_TRUE(test::file_exists(output));
  std::remove(output.c_str());
}

INSTANTIATE_TEST_SUITE_P(Corpus, BadInputs, ::testing::ValuesIn(cases()),
                         [](const auto& info) { return info.param.name; });

TEST(BadInputsCorpus, HasAtLeastThirtyFailureCases) {
  int failures = 0;
  for (const auto& c : cases()) failures += c.code != 0;
  EXPECT_GE(failures, 30);
}

}  // namespace
}  // namespace unfold
