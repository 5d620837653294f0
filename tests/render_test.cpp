// The renderer: rasteriser coverage and depth order, framing, pictures of a
// whole run (the demo shape through the command line), the convergence plot.
#include <gtest/gtest.h>
#include <stb/stb_image.h>
#include <sys/wait.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "core/errors.h"
#include "mesh/write_surface_mesh.h"
#include "render/camera.h"
#include "render/color_map.h"
#include "render/plot_convergence.h"
#include "render/plot_scaling.h"
#include "render/rasterize.h"
#include "render/render_comparison.h"
#include "render/write_png.h"
#include "test_files.h"
#include "test_meshes.h"

namespace unfold {
namespace {

const Rgb kWhite{255, 255, 255};

int count_pixels(const Image& image, Rgb color) {
  int n = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) n += image.at(x, y) == color;
  return n;
}

Eigen::Matrix3f uniform(float r, float g, float b) {
  Eigen::Matrix3f c;
  c.rowwise() = Eigen::RowVector3f(r, g, b);
  return c;
}

TEST(Rasterize, CoversPixelCentresInsideTheTriangle) {
  Canvas canvas(10, 10);
  Eigen::Matrix3d xyz;
  xyz << 0, 0, 1, 10, 0, 1, 0, 10, 1;
  rasterize_triangle(xyz, uniform(1, 0, 0), &canvas);
  // Centres (x + .5, y + .5) with x + y <= 9 are inside: 10 + 9 + ... + 1 pixels.
  EXPECT_EQ(count_pixels(canvas.image, {255, 0, 0}), 55);
  EXPECT_EQ(canvas.image.at(0, 9), (Rgb{255, 0, 0}));
  EXPECT_EQ(canvas.image.at(1, 9), kWhite);
  // The other winding covers the same pixels.
  Canvas flipped(10, 10);
  xyz.row(1).swap(xyz.row(2));
  rasterize_triangle(xyz, uniform(1, 0, 0), &flipped);
  EXPECT_EQ(flipped.image.pixels, canvas.image.pixels);
}

TEST(Rasterize, NearerTrianglesWinWhateverTheOrder) {
  Eigen::Matrix3d near, far;
  near << 0, 0, 0.5, 8, 0, 0.5, 0, 8, 0.5;
  far << 0, 0, 2, 8, 0, 2, 0, 8, 2;
  Canvas a(8, 8), b(8, 8);
  rasterize_triangle(far, uniform(0, 1, 0), &a);
  rasterize_triangle(near, uniform(0, 0, 1), &a);
  rasterize_triangle(near, uniform(0, 0, 1), &b);
  rasterize_triangle(far, uniform(0, 1, 0), &b);
  EXPECT_EQ(a.image.at(1, 1), (Rgb{0, 0, 255}));
  EXPECT_EQ(b.image.at(1, 1), (Rgb{0, 0, 255}));
  EXPECT_EQ(count_pixels(b.image, {0, 255, 0}), 0);
  EXPECT_DOUBLE_EQ(b.depth[1 * 8 + 1], 0.5);
}

TEST(Rasterize, InterpolatesCornerColours) {
  Canvas canvas(30, 30);
  Eigen::Matrix3d xyz;
  xyz << 0, 0, 0, 30, 0, 0, 0, 30, 0;
  Eigen::Matrix3f colors = Eigen::Matrix3f::Identity();  // red, green, blue corners
  rasterize_triangle(xyz, colors, &canvas);
  const Rgb corner = canvas.image.at(0, 0), middle = canvas.image.at(9, 9);
  EXPECT_GT(corner.r, 240);
  EXPECT_GT(middle.g, 60);
  EXPECT_GT(middle.b, 60);
  EXPECT_GT(middle.r, 60);
}

TEST(Rasterize, DegenerateTriangleDrawsNothing) {
  Canvas canvas(8, 8);
  Eigen::Matrix3d xyz;
  xyz << 0, 0, 0, 4, 4, 0, 8, 8, 0;
  rasterize_triangle(xyz, uniform(0, 0, 0), &canvas);
  EXPECT_EQ(count_pixels(canvas.image, kWhite), 64);
}

TEST(Camera, SideViewLooksAcrossTheLongHorizontalAxis) {
  Eigen::MatrixX3d V(4, 3);  // long along y, up z
  V << 0, -5, 0, 0, 5, 0, 1, 0, 0, 0, 0, 2;
  const std::vector<View> views = side_and_top_views(V, 2);
  ASSERT_EQ(views.size(), 2u);
  EXPECT_NEAR(std::abs(views[0].axes(0, 1)), 1.0, 1e-12);  // screen x along y
  EXPECT_NEAR(views[0].axes(1, 2), 1.0, 1e-12);            // screen up is z
  for (const View& v : views)
    EXPECT_NEAR((v.axes * v.axes.transpose() - Eigen::Matrix3d::Identity()).norm(), 0, 1e-12);
  EXPECT_NEAR(views[0].axes.determinant(), 1.0, 1e-12);
  EXPECT_THROW(side_and_top_views(V, 3), UsageError);
  EXPECT_EQ(axis_index("y", "up"), 1);
  EXPECT_THROW(axis_index("w", "up"), UsageError);
}

TEST(RenderComparison, SameScaleInBothColumns) {
  const SurfaceMesh sphere = test::uv_sphere(8, 12);
  RenderPanel small{"small", sphere.V, triangulate_faces(sphere), {}};
  RenderPanel big = small;
  big.V *= 2.0;
  RenderOptions options;
  options.panel_width = options.panel_height = 100;
  const Image image = render_comparison({small, big}, options);
  ASSERT_EQ(image.width, 200);
  ASSERT_EQ(image.height, kCaptionHeight + 200);
  int left = 0, right = 0;
  for (int y = kCaptionHeight; y < kCaptionHeight + 100; ++y)
    for (int x = 1; x < 100; ++x) {
      left += image.at(x, y) != kWhite;
      right += image.at(100 + x, y) != kWhite;
    }
  // Twice the radius at one scale: about four times the pixels.
  EXPECT_NEAR(double(right) / left, 4.0, 0.6);
}

// A segment inside an ellipsoid, along its long axis through its centre, is
// drawn over it in both views, on the centre row of each and nowhere else.
TEST(RenderComparison, LinesAreDrawnOverTheMeshWhereTheyAre) {
  SurfaceMesh ellipsoid = test::uv_sphere(12, 16);
  ellipsoid.V.col(0) *= 3;
  RenderPanel plain{"plain", ellipsoid.V, triangulate_faces(ellipsoid), {}};
  RenderPanel lined = plain;
  lined.line_points.resize(2, 3);
  lined.line_points << -1.5, 0, 0, 1.5, 0, 0;
  lined.lines.resize(1, 2);
  lined.lines << 0, 1;
  RenderOptions options;
  options.panel_width = 160;
  options.panel_height = 100;
  const Image a = render_comparison({plain}, options), b = render_comparison({lined}, options);
  for (int view = 0; view < 2; ++view) {
    const int y0 = kCaptionHeight + view * options.panel_height;
    int changed = 0, x_min = options.panel_width, x_max = 0;
    for (int y = y0; y < y0 + options.panel_height; ++y)
      for (int x = 0; x < options.panel_width; ++x) {
        if (a.at(x, y) == b.at(x, y)) continue;
        ++changed;
        EXPECT_LE(std::abs(y - (y0 + options.panel_height / 2)), 2) << x << "," << y;
        EXPECT_GT(b.at(x, y).r, b.at(x, y).g + 40) << x << "," << y;  // red
        x_min = std::min(x_min, x);
        x_max = std::max(x_max, x);
      }
    // The segment is half the ellipsoid's length, which nearly fills the panel's width.
    EXPECT_NEAR(x_max - x_min, 0.5 * (options.panel_width - 16), 6) << view;
    EXPECT_GE(changed, 2 * (x_max - x_min)) << view;  // 2 pixels wide
  }
  lined.lines(0, 1) = 2;
  EXPECT_THROW(render_comparison({lined}, options), UsageError);
}

TEST(ColorMap, EndsAndClamping) {
  EXPECT_NEAR(color_map(0.0)[0], 0.267f, 1e-3);
  EXPECT_NEAR(color_map(1.0)[1], 0.906f, 1e-3);
  EXPECT_EQ(color_map(-3.0), color_map(0.0));
  EXPECT_EQ(color_map(7.0), color_map(1.0));
}

// One row per line of a CSV file.
std::vector<std::string> lines(const std::string& path) {
  std::ifstream in(path);
  std::vector<std::string> result;
  for (std::string line; std::getline(in, line);) result.push_back(line);
  return result;
}

int unfold_exit_code(const std::string& args) {
  const int status =
      std::system((std::string(UNFOLD_BIN_DIR) + "/unfold " + args + " >/dev/null 2>&1").c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

struct Png {
  int width = 0, height = 0;
  std::vector<unsigned char> rgb;
  bool white(int x, int y) const {
    const unsigned char* p = &rgb[(size_t(y) * width + x) * 3];
    return p[0] == 255 && p[1] == 255 && p[2] == 255;
  }
};

Png read_png(const std::string& path) {
  Png png;
  int channels = 0;
  unsigned char* data = stbi_load(path.c_str(), &png.width, &png.height, &channels, 3);
  if (data) png.rgb.assign(data, data + size_t(png.width) * png.height * 3);
  stbi_image_free(data);
  return png;
}

TEST(RenderCli, DemoBeforeAfterAndConvergence) {
  test::TempDir dir;
  const std::string picture = dir.file("demo.png"), csv = dir.file("c.csv"),
                    plot = dir.file("c.png"), vtu = dir.file("t.vtu");
  ASSERT_EQ(unfold_exit_code("--demo_pose 1 --render " + picture + " --render_color rigidity" +
                             " --convergence " + csv + " --convergence_png " + plot +
                             " --tet_output " + vtu),
            0);
  const Png png = read_png(picture);
  const RenderOptions defaults;
  ASSERT_EQ(png.width, 2 * defaults.panel_width);
  ASSERT_EQ(png.height, kCaptionHeight + 2 * defaults.panel_height);
  // Each of the four panels (before/after x side/top) shows the shape, and the
  // shape stays off the panel's edges: inside the frame.
  for (int col = 0; col < 2; ++col)
    for (int row = 0; row < 2; ++row) {
      const int x0 = col * defaults.panel_width, y0 = kCaptionHeight + row * defaults.panel_height;
      int shape = 0, on_edge = 0;
      for (int y = 0; y < defaults.panel_height; ++y)
        for (int x = 0; x < defaults.panel_width; ++x) {
          const bool edge =
              x < 3 || y < 3 || x >= defaults.panel_width - 3 || y >= defaults.panel_height - 3;
          // The top-left view label and the bottom-right colour bar are not shape.
          const bool decoration = (x < 40 && y < 14) || (col == 1 && row == 1 && y > 210);
          if (png.white(x0 + x, y0 + y) || decoration) continue;
          edge ? ++on_edge : ++shape;
        }
      EXPECT_GT(shape, defaults.panel_width * defaults.panel_height / 20) << col << "," << row;
      EXPECT_LE(on_edge, (col > 0 ? defaults.panel_height : 0)) << col << "," << row;
    }

  const std::vector<std::string> rows = lines(csv);
  ASSERT_GE(rows.size(), 3u);
  EXPECT_EQ(rows[0], "iteration,cascade,beta,energy,edge_ratio");
  EXPECT_EQ(rows[1].rfind("1,1,", 0), 0u) << rows[1];
  const Png chart = read_png(plot);
  EXPECT_EQ(chart.width, 720);
  EXPECT_EQ(chart.height, 520);

  std::ifstream in(vtu);
  std::stringstream text;
  text << in.rdbuf();
  for (const char* field : {"<PointData", "Name=\"rigidity_error\"", "Name=\"stretch_ratio\"",
                            "<CellData", "Name=\"volume_ratio\"", "Name=\"rigidity\""})
    EXPECT_TRUE(test::Contains(text.str(), field));
}

// --render_focus worst: two close-ups (input, canonical), each showing the
// surface at its centre, where the region is.
TEST(RenderCli, FocusOnTheWorstRegionOfTheDemo) {
  test::TempDir dir;
  const std::string picture = dir.file("worst.png");
  ASSERT_EQ(unfold_exit_code("--demo_pose 1 --render " + picture +
                             " --render_focus worst --render_color damage"),
            0);
  const Png png = read_png(picture);
  const int tile = 360;
  ASSERT_EQ(png.width, 2 * tile);
  ASSERT_GT(png.height, kCaptionHeight + tile);
  for (int col = 0; col < 2; ++col)
    EXPECT_FALSE(png.white(col * tile + tile / 2, kCaptionHeight + tile / 2)) << col;
  // With folds, 'worst' is the most folded vertex: again a region at each centre.
  const std::string folds = dir.file("folds.png");
  ASSERT_EQ(unfold_exit_code("--demo_pose 1 --render " + folds +
                             " --render_focus worst --render_color folds"),
            0);
  const Png fold_png = read_png(folds);
  for (int col = 0; col < 2; ++col)
    EXPECT_FALSE(fold_png.white(col * tile + tile / 2, kCaptionHeight + tile / 2)) << col;
  EXPECT_EQ(unfold_exit_code("--render " + folds + " --render_color fold"), 2);  // not a colouring
}

TEST(RenderCli, BetaSweepRendersOneColumnPerBeta) {
  test::TempDir dir;
  const std::string picture = dir.file("sweep.png"), input = dir.file("ellipsoid.off");
  SurfaceMesh ellipsoid = test::uv_sphere(10, 16);  // small: the sweep runs the solve 3 times
  ellipsoid.V.col(0) *= 3;
  write_surface_mesh(input, ellipsoid);
  ASSERT_EQ(unfold_exit_code("--input " + input + " --beta_sweep 1,4 --render " + picture), 0);
  const Png png = read_png(picture);
  EXPECT_EQ(png.width, 3 * RenderOptions().panel_width);
  EXPECT_EQ(unfold_exit_code("--beta_sweep 1,x --render " + picture), 2);
  EXPECT_EQ(unfold_exit_code("--beta_sweep 1,2"), 2);  // no --render
  EXPECT_EQ(unfold_exit_code("--render " + dir.file("x.jpg")), 5);
  // The skeleton is method scf's, drawn in the before/after picture only.
  EXPECT_EQ(unfold_exit_code("--render_skeleton --render " + picture), 2);
  EXPECT_EQ(unfold_exit_code("--method scf --render_skeleton"), 2);
}

TEST(PlotConvergence, DrawsBothSeries) {
  std::vector<IterationRecord> history;
  for (int i = 1; i <= 12; ++i)
    history.push_back({i, i <= 6 ? 1 : 2, i <= 6 ? 1.0 : 2.0, -100.0 * i, 0.5 + 0.04 * i});
  const Image image = plot_convergence(history, {0.95, 1.05}, 400, 300);
  EXPECT_EQ(image.width, 400);
  EXPECT_GT(count_pixels(image, {31, 119, 180}), 50);  // energy line
  EXPECT_GT(count_pixels(image, {214, 39, 40}), 50);   // edge-ratio line
  // No iteration (Ceres starting at its minimum): the title only, no series.
  const Image empty = plot_convergence({}, {0.95, 1.05}, 400, 300);
  EXPECT_EQ(empty.width, 400);
  EXPECT_EQ(count_pixels(empty, {31, 119, 180}), 0);
  EXPECT_GT(count_pixels(empty, {40, 40, 40}), 100);  // the title's ink
  EXPECT_THROW(plot_convergence(history, {0.95, 1.05}, 100, 100), UsageError);
}

TEST(PlotScaling, DrawsTimeAndMemoryPanels) {
  const std::vector<double> n = {5e3, 2e4, 5e4, 1e5};
  const Image image =
      plot_scaling(n, {{"whole run", {0.5, 2, 5, 10}}, {"cascade", {0.2, 1, 2.5, 5}}},
                   {40, 120, 300, 600}, 600, 300);
  EXPECT_EQ(image.width, 600);
  EXPECT_GT(count_pixels(image, {31, 119, 180}), 80);   // first time series
  EXPECT_GT(count_pixels(image, {214, 39, 40}), 80);    // second
  EXPECT_GT(count_pixels(image, {148, 103, 189}), 80);  // memory
  EXPECT_THROW(plot_scaling({1e3}, {}, {1}), UsageError);
  EXPECT_THROW(plot_scaling(n, {{"short", {1, 2}}}, {1, 2, 3, 4}), UsageError);
  EXPECT_THROW(plot_scaling({2e3, 1e3}, {}, {1, 2}), UsageError);
}

TEST(WritePng, RefusesOtherFormatsAndWritesNothing) {
  test::TempDir dir;
  EXPECT_THROW(write_png(dir.file("a.bmp"), Image(4, 4)), OutputError);
  EXPECT_THROW(write_png(dir.file("a.png"), Image()), OutputError);
  EXPECT_EQ(dir.count(), 0);
  write_png(dir.file("a.png"), Image(4, 3, {1, 2, 3}));
  const Png png = read_png(dir.file("a.png"));
  EXPECT_EQ(png.width, 4);
  EXPECT_EQ(png.height, 3);
  EXPECT_EQ(png.rgb[2], 3);
}

}  // namespace
}  // namespace unfold
