// Per-vertex and per-tet fields for viewers, and the VTU that carries them.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <fstream>
#include <sstream>

#include "core/errors.h"
#include "mesh/edge_graph.h"
#include "mesh/write_tet_mesh.h"
#include "metrics/edge_ratio.h"
#include "metrics/tet_deformation.h"
#include "test_files.h"
#include "test_meshes.h"

namespace unfold {
namespace {

TEST(TetDeformation, RotationIsRigidScalingIsNot) {
  const TetMesh mesh = test::grid_tet_mesh(2, 1, 1);
  const Eigen::Matrix3d R = test::random_rotation(3);
  const Eigen::MatrixX3d rotated = mesh.V * R.transpose();
  const TetDeformation rigid = tet_deformation(mesh.V, rotated, mesh.T);
  EXPECT_NEAR(rigid.rigidity.maxCoeff(), 0, 1e-12);
  EXPECT_NEAR((rigid.volume_ratio.array() - 1).abs().maxCoeff(), 0, 1e-12);
  const TetDeformation scaled = tet_deformation(mesh.V, 2 * rotated, mesh.T);
  EXPECT_NEAR((scaled.volume_ratio.array() - 8).abs().maxCoeff(), 0, 1e-9);
  EXPECT_NEAR((scaled.rigidity.array() - std::sqrt(3.0)).abs().maxCoeff(), 0, 1e-9);  // |2R-R|
  Eigen::MatrixX3d mirrored = mesh.V;
  mirrored.col(0) *= -1;
  EXPECT_LT(tet_deformation(mesh.V, mirrored, mesh.T).volume_ratio.maxCoeff(), 0);
  Eigen::MatrixX4i flat(1, 4);
  flat << 0, 1, 2, 3;
  Eigen::MatrixX3d plane = Eigen::MatrixX3d::Zero(4, 3);
  plane.col(0) << 0, 1, 0, 1;
  plane.col(1) << 0, 0, 1, 1;
  const TetDeformation none = tet_deformation(plane, plane, flat);
  EXPECT_TRUE(std::isnan(none.volume_ratio[0]) && std::isnan(none.rigidity[0]));
}

TEST(VertexEdgeRatio, UniformScaleEverywhere) {
  const TetMesh mesh = test::grid_tet_mesh(2, 2, 1);
  const EdgeGraph graph = build_edge_graph(int(mesh.V.rows()), mesh.T);
  const Eigen::VectorXd ratio = vertex_edge_ratio(graph, mesh.V, 1.5 * mesh.V);
  EXPECT_NEAR((ratio.array() - 1.5).abs().maxCoeff(), 0, 1e-12);
  EXPECT_THROW(vertex_edge_ratio(graph, mesh.V, mesh.V.topRows(3)), UsageError);
}

TEST(WriteTetMesh, VtuCarriesFieldsWithOneValuePerVertexOrTet) {
  test::TempDir dir;
  const TetMesh mesh = test::grid_tet_mesh(1, 1, 1);
  TetMeshFields fields;
  fields.per_vertex = {{"height", mesh.V.col(2)}};
  fields.per_tet = {{"index", Eigen::VectorXd::LinSpaced(mesh.T.rows(), 0, 5)}};
  write_tet_mesh(dir.file("a.vtu"), mesh.V, mesh.T, fields);
  std::ifstream in(dir.file("a.vtu"));
  std::stringstream text;
  text << in.rdbuf();
  const std::string s = text.str();
  const size_t height = s.find("Name=\"height\"");
  ASSERT_NE(height, std::string::npos);
  EXPECT_LT(s.find("<PointData"), height);
  const std::string values =
      s.substr(s.find('\n', height) + 1, s.find("</DataArray>", height) - s.find('\n', height) - 1);
  EXPECT_EQ(std::count(values.begin(), values.end(), '\n'), mesh.V.rows());
  EXPECT_TRUE(test::Contains(s, "<CellData Scalars=\"index\">"));
  fields.per_tet.front().second.resize(2);
  EXPECT_THROW(write_tet_mesh(dir.file("b.vtu"), mesh.V, mesh.T, fields), UsageError);
  EXPECT_EQ(dir.count(), 1);
}

}  // namespace
}  // namespace unfold
