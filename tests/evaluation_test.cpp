// Evaluation: retrieval finds a rigidly moved and scaled copy at distance ~0
// as its own nearest neighbour; pose distances; shape classes and shards; the
// batch runner end to end (a failing shape recorded, the others run).
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

#include "core/errors.h"
#include "mesh/write_surface_mesh.h"
#include "metrics/pose_invariance.h"
#include "metrics/retrieval_measures.h"
#include "metrics/shape_retrieval.h"
#include "output_checks.h"
#include "pipeline/batch_run.h"
#include "pipeline/evaluation_report.h"
#include "render/plot_axes.h"
#include "render/plot_cdf.h"
#include "render/plot_precision_recall.h"
#include "shapes/articulated_shape.h"
#include "test_files.h"
#include "test_meshes.h"

namespace unfold {
namespace {

Eigen::MatrixX3d turned_and_moved(const Eigen::MatrixX3d& V, double scale) {
  return ((scale * V) * test::random_rotation(7).transpose()).rowwise() +
         Eigen::RowVector3d(3, -1, 2);
}

TEST(Retrieval, AMovedScaledCopyMatchesItselfAndIsItsNearestNeighbour) {
  const Eigen::MatrixX3d shape = make_articulated_shape(ShapePose::preset(0), 24).V;
  Eigen::MatrixX3d other = test::uv_sphere(12, 16).V;
  other.col(0) *= 2.5;  // an ellipsoid: distinct principal axes
  const RetrievalOptions options;
  const std::vector<Eigen::MatrixX3d> samples = {
      retrieval_sample(shape, options), retrieval_sample(turned_and_moved(shape, 3.7), options),
      retrieval_sample(other, options)};
  EXPECT_LT(shape_dissimilarity(samples[0], samples[1], options), 1e-9);
  EXPECT_GT(shape_dissimilarity(samples[0], samples[2], options), 0.05);
  const Eigen::MatrixXd D = dissimilarity_matrix(samples, options);
  EXPECT_LT(D(0, 1), 1e-9);
  EXPECT_EQ(D, D.transpose());
  // Shapes 0 and 1 find each other; the ellipsoid, alone in its class, is no query.
  const RetrievalMeasures m = retrieval_measures(D, {"a", "a", "b"});
  EXPECT_EQ(m.queries, 2);
  EXPECT_DOUBLE_EQ(m.nn, 1);
}

TEST(Retrieval, NearestPointDistanceIsSymmetricAndZeroOnlyForTheSameSet) {
  const Eigen::MatrixX3d A = test::uv_sphere(6, 8).V;
  const Eigen::MatrixX3d B = A.rowwise() + Eigen::RowVector3d(0.1, 0, 0);
  EXPECT_DOUBLE_EQ(nearest_point_distance(A, A), 0);
  EXPECT_DOUBLE_EQ(nearest_point_distance(A, B), nearest_point_distance(B, A));
  EXPECT_GT(nearest_point_distance(A, B), 0);
}

TEST(PoseInvariance, ZeroForARigidMotionAndAScaleAndMeasuredAtUnitArea) {
  const SurfaceMesh s = test::uv_sphere(8, 12, 2.0);
  const Eigen::MatrixX3i F = triangulate_faces(s);
  const double area = surface_area(s);
  EXPECT_NEAR(area, 4 * M_PI * 4, 0.1 * 4 * M_PI * 4);  // a coarse sphere of radius 2
  EXPECT_DOUBLE_EQ(surface_area(3 * s.V, F), 9 * area);
  EXPECT_NEAR(pose_distance(s.V, turned_and_moved(s.V, 1.0), F), 0, 1e-12);
  EXPECT_NEAR(pose_distance(s.V, 2.5 * turned_and_moved(s.V, 1.0), F), 0, 1e-12);
  // A non-rigid change is seen, and the same at any common scale.
  Eigen::MatrixX3d bumped = s.V;
  bumped(0, 0) += 1.0;
  const double d = pose_distance(s.V, bumped, F);
  EXPECT_GT(d, 1e-3);
  EXPECT_NEAR(pose_distance(10 * s.V, 10 * bumped, F), d, 1e-12);
  EXPECT_THROW(pose_distance(s.V, s.V.topRows(3), F), UsageError);
  EXPECT_THROW(pose_distance(Eigen::MatrixX3d::Zero(s.V.rows(), 3), s.V, F), UsageError);
  EXPECT_EQ(transfer_by_nearest_point(s.V, 2 * s.V, s.V), 2 * s.V);
}

TEST(Batch, ShapeClassesAndShards) {
  EXPECT_EQ(shape_class("cat3"), "cat");
  EXPECT_EQ(shape_class("centaur12"), "centaur");
  EXPECT_EQ(shape_class("tr_reg_000"), "tr_reg");
  EXPECT_EQ(shape_class("wolf"), "wolf");
  EXPECT_EQ(parse_shard("2/5"), std::make_pair(2, 5));
  EXPECT_THROW(parse_shard("5/5"), UsageError);
  EXPECT_THROW(parse_shard("1"), UsageError);
  EXPECT_THROW(parse_shard("a/2"), UsageError);
}

TEST(Batch, RunsEveryShapeRecordsFailuresAndWritesTheTables) {
  test::TempDir dir;
  const std::string in = dir.file("in"), out = dir.file("out");
  std::filesystem::create_directories(in);
  write_surface_mesh(in + "/body0.off", make_articulated_shape(ShapePose::preset(0), 24));
  write_surface_mesh(in + "/body1.off", make_articulated_shape(ShapePose::preset(1), 24));
  test::write_bytes(in + "/broken2.off", "OFF\n3 1 0\n0 0 0\n");  // truncated
  const std::string command = std::string(UNFOLD_BIN_DIR) + "/unfold_batch --input_dir " + in +
                              " --output_dir " + out + " --configs " + UNFOLD_SOURCE_DIR +
                              "/configs/default.yaml," + UNFOLD_SOURCE_DIR +
                              "/configs/lsmds.yaml --jobs 2 --cmbof_words 32 --cmbof_image_size "
                              "128 --cmbof_view_subdivisions 0 > " +
                              dir.file("stdout") + " 2>&1";
  ASSERT_EQ(std::system(command.c_str()), 0);
  const std::vector<BatchRow> rows = read_results_csv(out + "/results.csv");
  ASSERT_EQ(rows.size(), 6u);
  int ok = 0;
  for (const auto& r : rows) {
    if (r.shape == "broken2") {
      EXPECT_NE(r.status, "ok");
      continue;
    }
    EXPECT_EQ(r.status, "ok") << r.shape << " " << r.method;
    EXPECT_EQ(r.shape_class, "body");
    EXPECT_GT(r.E_rig, 0);
    ++ok;
    EXPECT_TRUE(std::filesystem::exists(out + "/" + r.method + "/" + r.shape + ".off"));
    EXPECT_TRUE(std::filesystem::exists(out + "/" + r.method + "/" + r.shape + ".json"));
  }
  EXPECT_EQ(ok, 4);
  std::ifstream retrieval(out + "/retrieval.csv"), pose(out + "/pose_invariance.csv");
  std::stringstream r, p;
  r << retrieval.rdbuf();
  p << pose.rdbuf();
  EXPECT_EQ(r.str().rfind("method,framework,queries,nn,first_tier,second_tier,e_measure,dcg,"
                          "precision_0.05,",
                          0),
            0u)
      << r.str();
  EXPECT_NE(r.str().find("\nraw,icp,2,"), std::string::npos) << r.str();
  EXPECT_NE(r.str().find("\nlsmds,ort,2,"), std::string::npos) << r.str();
  EXPECT_NE(r.str().find("\nlsmds,cmbof,2,"), std::string::npos) << r.str();
  EXPECT_NE(p.str().find("body,raw,"), std::string::npos) << p.str();
  EXPECT_NE(p.str().find("body,default,"), std::string::npos) << p.str();
  EXPECT_TRUE(std::filesystem::exists(out + "/similarity_default.csv"));
  EXPECT_TRUE(std::filesystem::exists(out + "/similarity_default_ort.csv"));
  EXPECT_TRUE(std::filesystem::exists(out + "/similarity_default_cmbof.csv"));
  EXPECT_TRUE(std::filesystem::exists(out + "/descriptors/raw/body0.txt"));
  // One pair of poses: its row, with the ratio of canonical to raw distance.
  std::ifstream pairs_file(out + "/pose_pairs.csv");
  std::string header, raw_row;
  std::getline(pairs_file, header);
  std::getline(pairs_file, raw_row);
  EXPECT_EQ(header, "class,method,shape_a,shape_b,raw_distance,pose_distance,ratio,correspondence");
  EXPECT_EQ(raw_row.rfind("body,raw,body0,body1,", 0), 0u) << raw_row;
  EXPECT_EQ(raw_row.substr(raw_row.size() - 15), ",1,vertex_order")
      << "raw poses have ratio 1, shared vertex order: " << raw_row;
  for (const char* method : {"raw", "default", "lsmds"})
    EXPECT_TRUE(std::filesystem::exists(out + "/poses_body_" + method + ".png")) << method;
  // The worst regions of every method's forms; the raw poses are the input itself.
  for (const char* method : {"default", "lsmds"})
    EXPECT_TRUE(std::filesystem::exists(out + "/worst_body_" + method + ".png")) << method;
  EXPECT_FALSE(std::filesystem::exists(out + "/worst_body_raw.png"));
  // And the most folded region of each.
  for (const char* method : {"default", "lsmds"})
    EXPECT_TRUE(std::filesystem::exists(out + "/folds_body_" + method + ".png")) << method;
  EXPECT_FALSE(std::filesystem::exists(out + "/folds_body_raw.png"));
}

// Shards unfold their shapes, then (once every shape is done) compute their
// rows of each similarity matrix; the collecting run assembles the blocks and
// writes the same tables as one run.
TEST(Batch, AShardSplitRunGivesTheRetrievalOfOneRun) {
  test::TempDir dir;
  const std::string in = dir.file("in");
  std::filesystem::create_directories(in);
  for (int k = 0; k < 4; ++k)
    write_surface_mesh(in + "/" + (k < 2 ? "a" : "b") + std::to_string(k % 2) + ".off",
                       make_articulated_shape(ShapePose::preset(k % 3), k < 2 ? 24 : 16));
  auto batch = [&](const std::string& out, const std::string& extra) {
    const std::string command = std::string(UNFOLD_BIN_DIR) + "/unfold_batch --input_dir " + in +
                                " --output_dir " + dir.file(out) + " --configs " +
                                UNFOLD_SOURCE_DIR + "/configs/default.yaml --jobs 1 " +
                                "--retrieval_points 150 --cmbof_words 32 --cmbof_image_size 128 "
                                "--cmbof_view_subdivisions 0 " +
                                extra + " >> " + dir.file("log") + " 2>&1";
    return std::system(command.c_str());
  };
  ASSERT_EQ(batch("single", ""), 0);
  for (int pass = 0; pass < 2; ++pass)
    for (const char* shard : {"0/2", "1/2"})
      ASSERT_EQ(batch("split", std::string("--skip_existing --shard ") + shard), 0);
  const std::string blocks = dir.file("split/similarity_blocks/");
  for (const char* matrix :
       {"raw_icp", "raw_ort", "raw_cmbof", "default_icp", "default_ort", "default_cmbof"})
    for (const char* block : {".0-of-2.csv", ".1-of-2.csv"})
      EXPECT_TRUE(std::filesystem::exists(blocks + matrix + block)) << matrix << block;
  EXPECT_FALSE(std::filesystem::exists(dir.file("split/retrieval.csv")));
  ASSERT_EQ(batch("split", "--skip_existing"), 0);
  for (const char* table :
       {"retrieval.csv", "similarity_raw.csv", "similarity_raw_ort.csv", "similarity_raw_cmbof.csv",
        "similarity_default.csv", "similarity_default_ort.csv", "similarity_default_cmbof.csv",
        "descriptors/raw.cmbof_vocabulary.txt"})
    EXPECT_EQ(test::file_text(dir.file("split/") + table),
              test::file_text(dir.file("single/") + table))
        << table;
  // The collecting run took the rows from the blocks: a changed value shows.
  std::string block = test::file_text(blocks + "raw_icp.0-of-2.csv");
  const size_t row = block.find("\na0,,");
  ASSERT_NE(row, std::string::npos) << block;
  block.replace(row, block.find('\n', row + 1) - row, "\na0,,123,123,123");
  test::write_bytes(blocks + "raw_icp.0-of-2.csv", block);
  ASSERT_EQ(batch("split", "--skip_existing"), 0);
  EXPECT_NE(test::file_text(dir.file("split/similarity_raw.csv")).find("\na0,0,123,123,123\n"),
            std::string::npos);
  // A CMBOF block made with another vocabulary is not mixed in: its rows are
  // computed again, with the vocabulary the shards agreed on.
  block = test::file_text(blocks + "raw_cmbof.0-of-2.csv");
  const size_t key = block.find("vocabulary=");
  ASSERT_NE(key, std::string::npos) << block;
  block.replace(key, 11, "vocabulary=0");
  const size_t cmbof_row = block.find("\na0,,");
  block.replace(cmbof_row, block.find('\n', cmbof_row + 1) - cmbof_row, "\na0,,123,123,123");
  test::write_bytes(blocks + "raw_cmbof.0-of-2.csv", block);
  ASSERT_EQ(batch("split", "--skip_existing"), 0);
  EXPECT_EQ(test::file_text(dir.file("split/similarity_raw_cmbof.csv")),
            test::file_text(dir.file("single/similarity_raw_cmbof.csv")));
}

}  // namespace
}  // namespace unfold

namespace unfold {
namespace {

TEST(Report, TableOfClassMeansRetrievalAndPoseFromTheRunFiles) {
  test::TempDir dir;
  std::vector<BatchRow> results = {{"cat0", "cat", "default", 0.5, 0.1, 0.2, 1.0, "ok"},
                                   {"cat1", "cat", "default", 0.7, 0.3, 0.4, 1.0, "ok"},
                                   {"cat0", "cat", "lsmds", 3.0, 0.2, 0.05, 2.0, "ok"},
                                   {"cat1", "cat", "lsmds", 0, 0, 0, 0, "no, it failed"}};
  // The damage and fold measures (issue 44) of the default's two cats.
  const double damage[2][6] = {{0.5, 2.5, 8, 10, 0.25, 100}, {1.5, 48, 810, 30, 0.125, 140}};
  for (int k = 0; k < 2; ++k) {
    BatchRow& r = results[size_t(k)];
    r.damaged_edges_percent = damage[k][0], r.surface_edge_ratio_p999 = damage[k][1];
    r.surface_edge_ratio_max = damage[k][2], r.inverted_tets = damage[k][3];
    r.folded_edges_percent = damage[k][4], r.dihedral_change_p999 = damage[k][5];
  }
  write_results_csv(dir.file("results.csv"), results);
  std::string precision = "", header =
                                  "method,framework,queries,nn,first_tier,second_tier,"
                                  "e_measure,dcg";
  for (int k = 1; k <= kRecallLevels; ++k)
    header += ",precision_" + std::to_string(k), precision += k < 10 ? ",1" : ",0.5";
  test::write_bytes(dir.file("retrieval.csv"), header + "\nraw,icp,2,0.5,0.5,1,0.1,0.75" +
                                                   precision + "\ndefault,icp,2,1,1,1,0.2,1" +
                                                   precision + "\ndefault,ort,2,1,0.5,1,0.2,1" +
                                                   precision + "\n");
  test::write_bytes(dir.file("pose_invariance.csv"),
                    "class,method,pose_distance,mean_ratio,max_ratio,pairs,correspondence\n"
                    "cat,raw,0.2,1,1,1,vts\ncat,default,0.1,0.5,0.75,1,vts\n"
                    "dog,raw,,,,0,none\ndog,default,,,,0,none\n");
  const std::string dir_path = dir.file("");
  const std::string md = evaluation_report_markdown({{dir_path, "2k"}});
  EXPECT_NE(md.find("| cat | 0.6000 (2/2) | 3.0000 (1/2) |"), std::string::npos) << md;
  EXPECT_NE(md.find("cat1, lsmds@2k: no, it failed"), std::string::npos) << md;
  // Damage: per class the mean and the worst shape; lsmds has no damage figures.
  EXPECT_NE(md.find("| cat | 1.000 (worst 1.500 cat1) (2/2) | - (0/2) |"), std::string::npos) << md;
  EXPECT_NE(md.find("| cat | 25.25 (worst 48.00 cat1) (2/2) |"), std::string::npos) << md;
  EXPECT_NE(md.find("| cat | 409.00 (worst 810.00 cat1) (2/2) |"), std::string::npos) << md;
  EXPECT_NE(md.find("| cat | 20 (worst 30 cat1) (2/2) |"), std::string::npos) << md;
  EXPECT_NE(md.find("| cat | 0.188 (worst 0.250 cat0) (2/2) | - (0/2) |"), std::string::npos) << md;
  EXPECT_NE(md.find("| cat | 120 (worst 140 cat1) (2/2) |"), std::string::npos) << md;
  EXPECT_NE(md.find("| framework | measure | raw@2k | default@2k |"), std::string::npos) << md;
  EXPECT_NE(md.find("| icp | NN | 0.500 | 1.000 |"), std::string::npos) << md;
  EXPECT_NE(md.find("| icp | DCG | 0.750 | 1.000 |"), std::string::npos) << md;
  EXPECT_NE(md.find("| ort | FT | - | 0.500 |"), std::string::npos) << md;
  EXPECT_NE(md.find("| cat | 0.2000 | 0.1000 |"), std::string::npos) << md;
  EXPECT_NE(md.find("| cat | 0.500 (max 0.750) |"), std::string::npos) << md;
  // A class without correspondence (docs/evaluation.md): said, not a number.
  EXPECT_NE(md.find("| dog | no correspondence | no correspondence |"), std::string::npos) << md;
  EXPECT_NE(md.find("| dog | no correspondence |\n"), std::string::npos) << md;
  write_cdf_plots({{dir_path, ""}}, dir_path);
  EXPECT_TRUE(std::filesystem::exists(dir.file("cdf_E_rig.png")));
  write_precision_recall_plots({{dir_path, ""}}, dir_path);
  EXPECT_TRUE(std::filesystem::exists(dir.file("pr_icp.png")));
  EXPECT_TRUE(std::filesystem::exists(dir.file("pr_ort.png")));
}

// Pixels of the first two series' colours.
std::pair<int, int> series_pixels(const Image& image) {
  int first = 0, second = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      first += image.at(x, y) == series_color(0);
      second += image.at(x, y) == series_color(1);
    }
  return {first, second};
}

TEST(Report, CdfPlotDrawsEachSeriesAndRefusesEmptyOnes) {
  const auto [blue, red] = series_pixels(plot_cdf({{"a", {0.1, 0.5, 0.9}}, {"b", {0.3}}}, "x"));
  EXPECT_GT(blue, 100);
  EXPECT_GT(red, 100);
  EXPECT_THROW(plot_cdf({{"a", {}}}, "x"), UsageError);
  EXPECT_THROW(plot_cdf({}, "x"), UsageError);
}

TEST(Report, PrecisionRecallPlotDrawsEachSeriesAndRefusesBadOnes) {
  const auto [blue, red] =
      series_pixels(plot_precision_recall({{"a", {1, 0.8, 0.5}}, {"b", {0.5, 0.5, 0.2}}}, "P"));
  EXPECT_GT(blue, 100);
  EXPECT_GT(red, 100);
  EXPECT_THROW(plot_precision_recall({{"a", {0.5}}}, "P"), UsageError);
  EXPECT_THROW(plot_precision_recall({{"a", {0.5, 1.5}}}, "P"), UsageError);
  EXPECT_THROW(plot_precision_recall({}, "P"), UsageError);
}

}  // namespace
}  // namespace unfold
