#include <gtest/gtest.h>
#include <sys/wait.h>
#include <tetgen.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iomanip>
#include <iterator>
#include <map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "core/errors.h"
#include "mesh/edge_graph.h"
#include "shapes/articulated_shape.h"
#include "test_meshes.h"

namespace unfold {

// A stored surface as test names show it: 48, mouth_48 (PrintTo: gtest's
// printer, found by argument-dependent lookup outside the anonymous namespace).
static std::string stored_name(const StoredRestSurface& stored) {
  return (stored.mouth ? "mouth_" : "") + std::to_string(stored.resolution);
}
static void PrintTo(const StoredRestSurface& stored, std::ostream* out) {
  *out << stored_name(stored);
}

namespace {

// Rest pose first, then the presets; built once for the whole suite.
class ShapeTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    shapes_ = new std::vector<SurfaceMesh>;
    shapes_->push_back(make_articulated_shape(ShapePose::rest()));
    for (int k = 0; k < ShapePose::num_presets(); ++k)
      shapes_->push_back(make_articulated_shape(ShapePose::preset(k)));
  }
  static void TearDownTestSuite() {
    delete shapes_;
    shapes_ = nullptr;
  }
  static std::vector<SurfaceMesh>* shapes_;
};
std::vector<SurfaceMesh>* ShapeTest::shapes_ = nullptr;

double min_angle_degrees(const SurfaceMesh& m) {
  const Eigen::MatrixX3i F = triangulate_faces(m);
  double worst = 180;
  for (Eigen::Index t = 0; t < F.rows(); ++t)
    for (int a = 0; a < 3; ++a) {
      const Eigen::Vector3d p = m.V.row(F(t, a)), q = m.V.row(F(t, (a + 1) % 3)),
                            r = m.V.row(F(t, (a + 2) % 3));
      const double c = (q - p).normalized().dot((r - p).normalized());
      worst = std::min(worst, std::acos(std::clamp(c, -1.0, 1.0)) * 180 / M_PI);
    }
  return worst;
}

TEST_F(ShapeTest, RestMeshIsClosedOrientedManifoldSphere) {
  const SurfaceMesh& m = shapes_->front();
  const Eigen::MatrixX3i F = triangulate_faces(m);
  ASSERT_EQ(size_t(F.rows()), m.faces.size()) << "all faces are triangles";
  // Closed and consistently oriented: every directed edge once, its reverse once.
  std::map<std::pair<int, int>, int> directed;
  for (Eigen::Index t = 0; t < F.rows(); ++t)
    for (int a = 0; a < 3; ++a) ++directed[{F(t, a), F(t, (a + 1) % 3)}];
  for (const auto& [edge, count] : directed) {
    ASSERT_EQ(count, 1) << "edge " << edge.first << "-" << edge.second;
    ASSERT_EQ(directed.count({edge.second, edge.first}), 1u)
        << "boundary edge " << edge.first << "-" << edge.second;
  }
  // 2-manifold at vertices too: each vertex's faces form a single fan.
  const EdgeGraph graph = build_edge_graph(int(m.V.rows()), F);
  std::vector<int> faces_at(size_t(m.V.rows()), 0);
  for (Eigen::Index t = 0; t < F.rows(); ++t)
    for (int a = 0; a < 3; ++a) ++faces_at[size_t(F(t, a))];
  for (int i = 0; i < graph.num_vertices; ++i)
    ASSERT_EQ(faces_at[size_t(i)], graph.degree(i)) << "vertex " << i << " is not a single fan";
  EXPECT_EQ(connected_components(graph), 1);
  EXPECT_EQ(m.V.rows() - graph.num_edges() + F.rows(), 2) << "Euler characteristic";
  EXPECT_GT(test::signed_volume(m), 0.5) << "outward orientation";
  EXPECT_GE(m.V.rows(), 3000);
  EXPECT_LE(m.V.rows(), 5000);
  EXPECT_GT(min_angle_degrees(m), 10.0);
}

TEST_F(ShapeTest, PosesShareConnectivityAndKeepVolume) {
  const SurfaceMesh& rest = shapes_->front();
  for (const SurfaceMesh& m : *shapes_) {
    EXPECT_EQ(m.faces, rest.faces);
    ASSERT_EQ(m.V.rows(), rest.V.rows());
    EXPECT_NEAR(test::signed_volume(m), test::signed_volume(rest),
                0.03 * test::signed_volume(rest));
    EXPECT_GT(min_angle_degrees(m), 5.0);
  }
}

TEST_F(ShapeTest, PresetsDifferClearlyFromRest) {
  const SurfaceMesh& rest = shapes_->front();
  for (size_t k = 1; k < shapes_->size(); ++k) {
    // Most vertices are on the body, which stays put; limbs move a lot.
    const Eigen::VectorXd moved = ((*shapes_)[k].V - rest.V).rowwise().norm();
    EXPECT_GT(moved.mean(), 0.1) << "preset " << k - 1;
    EXPECT_GT(moved.maxCoeff(), 0.5) << "preset " << k - 1;
  }
}

TEST_F(ShapeTest, ExtremitiesKeepClearOfEachOther) {
  // Groups by rest position (vertex i is the same body point in every pose):
  // the four lower feet, the tail's outer end and the head.
  const SurfaceMesh& rest = shapes_->front();
  std::vector<std::vector<int>> groups(6);
  for (int i = 0; i < int(rest.V.rows()); ++i) {
    const Eigen::Vector3d p = rest.V.row(i);
    if (p.z() < -1.0) groups[size_t((p.x() > 0 ? 0 : 2) + (p.y() > 0 ? 0 : 1))].push_back(i);
    if (p.x() < -1.6) groups[4].push_back(i);
    if (p.x() > 1.3 && p.z() > 0.45) groups[5].push_back(i);
  }
  for (const auto& g : groups) ASSERT_FALSE(g.empty());
  for (const SurfaceMesh& m : *shapes_)
    for (size_t a = 0; a < groups.size(); ++a)
      for (size_t b = a + 1; b < groups.size(); ++b) {
        double d = INFINITY;
        for (const int i : groups[a])
          for (const int j : groups[b]) d = std::min(d, (m.V.row(i) - m.V.row(j)).norm());
        EXPECT_GT(d, 0.1) << "groups " << a << " and " << b;
      }
}

TEST_F(ShapeTest, TetGenAcceptsEveryPoseKeepingSurfaceVertices) {
  for (size_t k = 0; k < shapes_->size(); ++k) {
    const SurfaceMesh& m = (*shapes_)[k];
    const Eigen::MatrixX3i F = triangulate_faces(m);
    tetgenio in, out;
    in.numberofpoints = int(m.V.rows());
    in.pointlist = new REAL[size_t(3 * m.V.rows())];
    for (Eigen::Index i = 0; i < m.V.rows(); ++i)
      for (int a = 0; a < 3; ++a) in.pointlist[3 * i + a] = m.V(i, a);
    in.numberoffacets = int(F.rows());
    in.facetlist = new tetgenio::facet[size_t(F.rows())];
    for (Eigen::Index t = 0; t < F.rows(); ++t) {
      tetgenio::facet& f = in.facetlist[t];
      tetgenio::init(&f);
      f.numberofpolygons = 1;
      f.polygonlist = new tetgenio::polygon[1];
      tetgenio::init(&f.polygonlist[0]);
      f.polygonlist[0].numberofvertices = 3;
      f.polygonlist[0].vertexlist = new int[3]{F(t, 0), F(t, 1), F(t, 2)};
    }
    char switches[] = "pYQ";
    bool failed = false;
    try {
      tetrahedralize(switches, &in, &out);
    } catch (int code) {
      failed = true;
      ADD_FAILURE() << "TetGen failed with code " << code << " on shape " << k;
    }
    if (failed) continue;
    ASSERT_GE(out.numberofpoints, in.numberofpoints);
    EXPECT_GT(out.numberoftetrahedra, 0);
    for (int i = 0; i < 3 * in.numberofpoints; ++i)
      ASSERT_EQ(out.pointlist[i], in.pointlist[i]) << "shape " << k << " moved a surface point";
  }
}

std::string read_file(const std::string& path) {
  std::ifstream in(path);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

int run_app(const std::string& args) {
  const int status =
      std::system((std::string(UNFOLD_BIN_DIR) + "/unfold_shape " + args + " 2>/dev/null").c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

TEST(ShapeApp, WritesTheSameOffInSeparateRuns) {
  // Separate processes make the shape again: checks determinism. (Its rest
  // surface is stored; that meshing it gives the stored bits in any process is
  // StoredRestSurfaces.AreTheMeshedOnes'.)
  const std::string dir = ::testing::TempDir();
  ASSERT_EQ(run_app("--pose 1 --resolution 24 --output " + dir + "shape_a.off"), 0);
  ASSERT_EQ(run_app("--pose 1 --resolution 24 --output " + dir + "shape_b.off"), 0);
  const std::string a = read_file(dir + "shape_a.off");
  EXPECT_EQ(a.rfind("OFF\n", 0), 0u);
  EXPECT_EQ(a, read_file(dir + "shape_b.off"));
}

TEST(ShapeApp, BadFlagsExitWithTwo) {
  const std::string out = " --output " + ::testing::TempDir() + "shape_bad.off";
  EXPECT_EQ(run_app("--pose 7" + out), 2);
  EXPECT_EQ(run_app("--pose rest --resolution 5" + out), 2);
  EXPECT_EQ(run_app("--pose rest"), 2);
  EXPECT_EQ(run_app("--resolution abc" + out), 2);
  EXPECT_EQ(run_app("--no_such_flag" + out), 2);
}

// The file a stored rest surface is read from.
std::string rest_surface_file(const StoredRestSurface& stored) {
  return "articulated_rest_surface_" + stored_name(stored) + ".inc";
}

// articulated_rest_surface_*.inc's text for `mesh`: each coordinate's bits, so
// the stored copy is bit for bit the meshed one.
std::string rest_surface_source(const SurfaceMesh& mesh, const StoredRestSurface& stored) {
  const std::string resolution = std::to_string(stored.resolution);
  std::ostringstream out;
  out << "// The demo shape's rest surface" << (stored.mouth ? " with the mouth" : "")
      << " at resolution " << resolution << ": mesh_articulated_rest_surface(" << resolution
      << (stored.mouth ? ", true" : "")
      << "),\n"
         "// stored because meshing takes seconds. Written by tests/shape_test.cpp\n"
         "// (StoredRestSurfaces.AreTheMeshedOnes) when it differs: do not edit.\n"
         "// clang-format off\n"
         "static constexpr uint64_t kRestVertexBits[] = {  // x, y, z of each vertex\n";
  out << std::hex << std::setfill('0');
  for (Eigen::Index i = 0; i < mesh.V.rows(); ++i) {
    for (int a = 0; a < 3; ++a) {
      uint64_t bits;
      const double x = mesh.V(i, a);
      std::memcpy(&bits, &x, sizeof bits);
      out << "0x" << std::setw(16) << bits << ",";
    }
    out << "\n";
  }
  out << std::dec << "};\nstatic constexpr int kRestTriangles[] = {\n";
  for (const auto& face : mesh.faces) {
    for (const int v : face) out << v << ",";
    out << "\n";
  }
  out << "};\n// clang-format on\n";
  return out.str();
}

// One test a stored surface, each meshing it in a process of its own (seconds each).
class StoredRestSurfaces : public ::testing::TestWithParam<StoredRestSurface> {};

TEST_P(StoredRestSurfaces, AreTheMeshedOnes) {
  const StoredRestSurface stored = GetParam();
  const SurfaceMesh meshed = mesh_articulated_rest_surface(stored.resolution, stored.mouth);
  const std::string file = rest_surface_file(stored);
  const std::string stored_path = UNFOLD_SOURCE_DIR "/shapes/" + file;
  const std::string fresh_path = ::testing::TempDir() + file;
  const std::string fresh = rest_surface_source(meshed, stored);
  const bool same = read_file(stored_path) == fresh;
  if (!same) std::ofstream(fresh_path) << fresh;
  EXPECT_TRUE(same) << "the stored rest surface is not what the code meshes; if the change is "
                       "meant: cp "
                    << fresh_path << " " << stored_path;
  // And the shape made from it is the meshed surface, skinned.
  const ShapePose rest = stored.mouth ? ShapePose::open_mouth() : ShapePose::rest();
  const SurfaceMesh made = make_articulated_shape(rest, stored.resolution);
  EXPECT_EQ(made.faces, meshed.faces);
  ASSERT_EQ(made.V.rows(), meshed.V.rows());
  EXPECT_LT((made.V - meshed.V).cwiseAbs().maxCoeff(), 1e-12);
}

INSTANTIATE_TEST_SUITE_P(Shapes, StoredRestSurfaces, ::testing::ValuesIn(stored_rest_surfaces()),
                         [](const auto& info) { return stored_name(info.param); });

TEST(ShapeMake, RejectsBadParameters) {
  EXPECT_THROW(make_articulated_shape(ShapePose::rest(), 15), UsageError);
  EXPECT_THROW(make_articulated_shape(ShapePose::rest(), 129), UsageError);
  EXPECT_THROW(ShapePose::preset(-1), UsageError);
  EXPECT_THROW(ShapePose::preset(ShapePose::num_presets()), UsageError);
}

}  // namespace
}  // namespace unfold
