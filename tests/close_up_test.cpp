// Close-ups (issue 44): a camera framing a ball, the worst region of a form,
// and unfold's --render_focus.
#include "render/close_up.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "core/errors.h"
#include "metrics/surface_damage.h"
#include "metrics/worst_region.h"
#include "run_app.h"
#include "test_files.h"
#include "test_meshes.h"

namespace unfold {
namespace {

// A sphere's vertices all lie at the radius from its centre, so the framing
// of the ball puts them on a disc that just fills the panel: the sphere's
// projected extent is the panel less its margins, about the panel's centre.
TEST(CloseUp, TheBallFillsThePanelAboutItsCentre) {
  const double radius = 0.3;
  const Eigen::Vector3d centre(2, -1, 5);
  const SurfaceMesh sphere = test::uv_sphere(24, 48, radius);
  const Eigen::MatrixX3d V = sphere.V.rowwise() + centre.transpose();
  const int width = 300, height = 200, margin = 10;
  for (const Eigen::Vector3d& normal :
       {Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0.3, -2, 0.5), Eigen::Vector3d(0, 0, 1)}) {
    const View view = view_facing(normal, 2);
    EXPECT_NEAR((view.axes * view.axes.transpose() - Eigen::Matrix3d::Identity()).norm(), 0, 1e-12);
    EXPECT_NEAR(view.axes.determinant(), 1, 1e-12);
    EXPECT_NEAR(view.axes.row(2).dot(normal.normalized()), 1, 1e-12) << "looks along -normal";
    const double scale = ball_scale(radius, width, height, margin);
    const Eigen::MatrixX3d at = project_about(V, centre, view, scale, width, height);
    const Eigen::MatrixX3d mid =
        project_about(centre.transpose(), centre, view, scale, width, height);
    EXPECT_NEAR(mid(0, 0), width / 2.0, 1e-9);
    EXPECT_NEAR(mid(0, 1), height / 2.0, 1e-9);
    const double room = height - 2 * margin;  // the smaller side
    for (int axis = 0; axis < 2; ++axis) {
      const double low = at.col(axis).minCoeff(), high = at.col(axis).maxCoeff();
      // The sphere's widest ring of 48 vertices reaches at least cos(pi / 48) of the radius.
      EXPECT_LE(high - low, room + 1e-9) << axis;
      EXPECT_GE(high - low, room * std::cos(M_PI / 24)) << axis;
      EXPECT_NEAR(0.5 * (low + high), (axis == 0 ? width : height) / 2.0, 0.02 * room) << axis;
    }
  }
  EXPECT_THROW(ball_scale(0, width, height, margin), UsageError);
  EXPECT_THROW(ball_scale(1, 20, 20, 10), UsageError);
  EXPECT_THROW(view_facing(Eigen::Vector3d::Zero(), 2), UsageError);
}

// Drawn, the ball is a disc of the panel's room at its centre; a plate between
// the viewer and the ball, which would hide it, is cut away.
TEST(CloseUp, DrawsTheBallAndCutsAwayWhatIsInFront) {
  const double radius = 1;
  CloseUp tile;
  const SurfaceMesh sphere = test::uv_sphere(24, 48, radius);
  // The plate: a square much larger than the panel, 3 radii in front (+z).
  Eigen::MatrixX3d V(sphere.V.rows() + 4, 3);
  V << sphere.V, -10, -10, 3, 10, -10, 3, 10, 10, 3, -10, 10, 3;
  Eigen::MatrixX3i F(Eigen::Index(sphere.faces.size()) + 2, 3);
  for (size_t f = 0; f < sphere.faces.size(); ++f)
    F.row(Eigen::Index(f)) << sphere.faces[f][0], sphere.faces[f][1], sphere.faces[f][2];
  const int p = int(sphere.V.rows());
  F.bottomRows(2) << p, p + 1, p + 2, p, p + 2, p + 3;
  tile.V = V;
  tile.F = F;
  tile.colors = Eigen::MatrixX3f::Zero(V.rows(), 3);
  tile.colors.col(0).head(p).setOnes();  // the sphere red
  tile.colors.col(2).tail(4).setOnes();  // the plate blue
  tile.view = view_facing(Eigen::Vector3d::UnitZ(), 1);
  const int size = 100, margin = 10;
  Canvas canvas(size, size);
  render_close_up(tile, Shading::kFlat, margin, &canvas);
  int red = 0, blue = 0, other = 0;
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const Rgb c = canvas.image.at(x, y);
      if (c == Rgb{255, 255, 255}) continue;
      (c.r > 0 && c.b == 0 ? red : c.b > 0 && c.r == 0 ? blue : other)++;
    }
  EXPECT_EQ(blue, 0) << "the plate in front is cut away";
  EXPECT_EQ(other, 0);
  const double disc = M_PI * std::pow((size - 2 * margin) / 2.0, 2);
  EXPECT_NEAR(red, disc, 0.05 * disc);
  EXPECT_NE(canvas.image.at(size / 2, size / 2), (Rgb{255, 255, 255}));
}

// One vertex of a sphere pulled out to twice its distance: its edges are the
// most stretched, and the worst region is about it, whatever rotation, scale
// and move the form is in.
TEST(WorstRegion, FindsThePlantedStretchedEdge) {
  const SurfaceMesh sphere = test::uv_sphere(10, 16);
  Eigen::MatrixXi F(Eigen::Index(sphere.faces.size()), 3);
  for (size_t f = 0; f < sphere.faces.size(); ++f)
    F.row(Eigen::Index(f)) << sphere.faces[f][0], sphere.faces[f][1], sphere.faces[f][2];
  for (const int planted : {37, 100}) {
    Eigen::MatrixX3d form = sphere.V;
    form.row(planted) *= 2;
    form = ((3.0 * form * test::random_rotation(unsigned(planted)).transpose()).rowwise() +
            Eigen::RowVector3d(1, 2, 3))
               .eval();
    const SurfaceDamage damage = surface_damage(sphere.V, form, F);
    const WorstRegion worst = worst_region(damage, F);
    EXPECT_EQ(worst.vertex, planted);
    EXPECT_GT(worst.ratio, 1.5) << "stretched";
    EXPECT_NEAR(worst.damage, std::log(worst.ratio), 1e-12);
    EXPECT_DOUBLE_EQ(worst.damage, damage.per_vertex.maxCoeff());
    EXPECT_DOUBLE_EQ(worst.ratio, damage.ratio_max);
  }
  // Crushed: one edge planted nearly collapsed, its end 50 moved to 1 % of the
  // way from its neighbour; the worst region is about one of the two ends.
  Eigen::Index face = 0;
  while (F(face, 0) != 50) ++face;
  const int neighbour = F(face, 1);
  Eigen::MatrixX3d crushed = sphere.V;
  crushed.row(50) = 0.99 * sphere.V.row(neighbour) + 0.01 * sphere.V.row(50);
  const WorstRegion worst = worst_region(surface_damage(sphere.V, crushed, F), F);
  EXPECT_TRUE(worst.vertex == 50 || worst.vertex == neighbour) << worst.vertex;
  EXPECT_LT(worst.ratio, 0.02);
  // No damage at all: still one vertex, deterministically, with ratio 1.
  const WorstRegion none = worst_region(surface_damage(sphere.V, sphere.V, F), F);
  EXPECT_EQ(none.vertex, worst_region(surface_damage(sphere.V, sphere.V, F), F).vertex);
  EXPECT_EQ(none.ratio, 1);
  EXPECT_THROW(worst_region(SurfaceDamage(), F), UsageError);
  EXPECT_NEAR(region_radius(sphere.V, 0.5), 0.5 * std::sqrt(12.0), 1e-9);
  EXPECT_THROW(region_radius(sphere.V, 0), UsageError);
  EXPECT_THROW(region_radius(sphere.V, 1.5), UsageError);
}

TEST(RenderFocusCli, BadValuesAreOneLineUsageErrors) {
  test::TempDir dir;
  const std::string png = " --render " + dir.file("x.png");
  test::expect_failure(png + " --render_focus head", 2, "--render_focus: 'head'",
                       dir.file("a.off"));
  test::expect_failure(png + " --render_focus -3", 2, "--render_focus", dir.file("a.off"));
  test::expect_failure(png + " --render_focus 99999999", 2, "vertex 99999999 is not in [0, ",
                       dir.file("a.off"));
  test::expect_failure(png + " --render_focus worst --render_focus_radius 0", 2,
                       "--render_focus_radius", dir.file("a.off"));
  test::expect_failure(" --render_focus worst", 2, "--render_focus needs --render",
                       dir.file("a.off"));
  EXPECT_FALSE(test::file_exists(dir.file("x.png")));
}

}  // namespace
}  // namespace unfold
