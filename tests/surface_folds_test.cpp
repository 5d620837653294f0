// The fold measure: zero for a similarity of the input, and it sees a fold
// that keeps every edge length (which the edge-ratio damage measure cannot).
#include "metrics/surface_folds.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/errors.h"
#include "metrics/surface_damage.h"
#include "pipeline/region_pictures.h"
#include "pipeline/result_pictures.h"
#include "test_meshes.h"

namespace unfold {
namespace {

// A flat sheet of nx x ny squares in the z = 0 plane, each split into two
// triangles; vertex (i, j) is row j * (nx + 1) + i.
void sheet(int nx, int ny, Eigen::MatrixX3d* V, Eigen::MatrixX3i* F) {
  V->resize((nx + 1) * (ny + 1), 3);
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) V->row(j * (nx + 1) + i) << i, j, 0;
  F->resize(2 * nx * ny, 3);
  int t = 0;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int a = j * (nx + 1) + i, b = a + 1, c = a + nx + 1, d = c + 1;
      F->row(t++) << a, b, d;
      F->row(t++) << a, d, c;
    }
}

// The flat sheet V with its part beyond x = x0 turned about that line by
// `degrees` (every length kept): a crease of that angle.
Eigen::MatrixX3d creased(const Eigen::MatrixX3d& V, double x0, double degrees) {
  const double angle = degrees * 3.14159265358979323846 / 180;
  Eigen::MatrixX3d C = V;
  for (Eigen::Index v = 0; v < V.rows(); ++v)
    if (V(v, 0) > x0) {
      const double d = V(v, 0) - x0;
      C(v, 0) = x0 + d * std::cos(angle);
      C(v, 2) = d * std::sin(angle);
    }
  return C;
}

TEST(SurfaceFolds, NoneUnderASimilarity) {
  const SurfaceMesh sphere = test::uv_sphere(12, 16);
  const Eigen::MatrixX3i F = triangulate_faces(sphere);
  const Eigen::MatrixX3d moved = (2.5 * sphere.V * test::random_rotation(4).transpose()).rowwise() +
                                 Eigen::RowVector3d(1, 2, 3);
  const SurfaceFolds folds = surface_folds(sphere.V, moved, F);
  EXPECT_GT(folds.edges, 0);
  EXPECT_EQ(folds.folded_edges, 0);
  EXPECT_LT(folds.dihedral_change_max, 1e-6);
  EXPECT_LT(folds.per_vertex.maxCoeff(), 1e-6);
}

// The sheet folded along its middle column line by 120 degrees: every length is
// kept, so no edge is damaged, but the edges on the fold line turn by 120
// degrees and no other edge turns at all.
TEST(SurfaceFolds, SeesAFoldThatKeepsEveryLength) {
  const int nx = 6, ny = 5;
  Eigen::MatrixX3d V;
  Eigen::MatrixX3i F;
  sheet(nx, ny, &V, &F);
  const double x0 = nx / 2;
  const Eigen::MatrixX3d folded = creased(V, x0, 120);
  const SurfaceDamage damage = surface_damage(V, folded, Eigen::MatrixXi(F));
  EXPECT_EQ(damage.damaged_edges, 0);
  EXPECT_NEAR(damage.ratio_max, 1.0, 1e-12);
  const SurfaceFolds folds = surface_folds(V, folded, F);
  // Interior edges: the sheet's edges but those on its border.
  const int all_edges = nx * (ny + 1) + (nx + 1) * ny + nx * ny;
  EXPECT_EQ(folds.edges, all_edges - 2 * (nx + ny));
  EXPECT_EQ(folds.folded_edges, ny);  // the fold line's inner edges
  EXPECT_NEAR(folds.dihedral_change_max, 120, 1e-9);
  EXPECT_NEAR(folds.folded_edges_percent, 100.0 * ny / folds.edges, 1e-12);
  for (Eigen::Index v = 0; v < V.rows(); ++v)
    EXPECT_NEAR(folds.per_vertex[v], V(v, 0) == x0 ? 120 : 0, 1e-9) << "vertex " << v;
  // A gentler bend is no fold: 60 degrees is below the right-angle bound.
  const Eigen::MatrixX3d bent = creased(V, x0, 60);
  EXPECT_EQ(surface_folds(V, bent, F).folded_edges, 0);
  EXPECT_NEAR(surface_folds(V, bent, F).dihedral_change_max, 60, 1e-9);
}

// --render_color folds: a sheet folded over along a line, every length kept.
// The folds colouring marks the crease in its top colour (yellow), in the whole
// picture and in the close-up of the most folded vertex; the close-up's damage
// colouring (on its fixed scale), which sees lengths alone, marks nothing, nor
// does plain shading.
TEST(SurfaceFolds, TheFoldsColouringMarksACreaseTheDamageCannotSee) {
  const int nx = 20, ny = 20;
  Eigen::MatrixX3d V;
  Eigen::MatrixX3i F;
  sheet(nx, ny, &V, &F);
  UnfoldResult result;
  result.surface.V = V;
  for (Eigen::Index t = 0; t < F.rows(); ++t)
    result.surface.faces.push_back({F(t, 0), F(t, 1), F(t, 2)});
  result.canonical = result.surface;
  result.canonical.V = creased(V, nx / 2, 150);
  result.metrics.damage = surface_damage(V, result.canonical.V, Eigen::MatrixXi(F));
  result.metrics.folds = surface_folds(V, result.canonical.V, F);
  ASSERT_EQ(result.metrics.damage.damaged_edges, 0);
  // Yellow pixels of the right half, rows [top, bottom): the canonical form.
  const auto yellow = [](const Image& image, int top, int bottom) {
    int count = 0;
    for (int y = top; y < bottom; ++y)
      for (int x = image.width / 2; x < image.width; ++x) {
        const Rgb c = image.at(x, y);
        count += c.r > 180 && c.g > 160 && c.b < 90;
      }
    return count;
  };
  RenderOptions render;
  render.up_axis = 1;
  const auto whole = [&](const char* coloring) {
    const Image image = render_before_after(result, render, surface_coloring(coloring));
    return yellow(image, kCaptionHeight, image.height - 20);  // above any colour bar
  };
  // The whole form's side view sees the crease edge on (the folded half lies
  // over the other), a line of yellow; the close-up sees it face on, a band.
  EXPECT_GT(whole("folds"), 0);
  EXPECT_EQ(whole("shading"), 0);
  // The close-up's tiles are 360 pixels square below the title.
  const auto close_up = [&](SurfaceColoring coloring) {
    return yellow(render_region_before_after(result, -1, 0.2, 1, coloring), kCaptionHeight,
                  kCaptionHeight + 360);
  };
  EXPECT_GT(close_up(SurfaceColoring::kFolds), 20);
  EXPECT_EQ(close_up(SurfaceColoring::kDamage), 0);
  EXPECT_EQ(close_up(SurfaceColoring::kShading), 0);
  EXPECT_THROW(surface_coloring("fold"), UsageError);
  result.metrics.folds.per_vertex.resize(3);
  EXPECT_THROW(render_before_after(result, render, SurfaceColoring::kFolds), UsageError);
  EXPECT_THROW(render_region_before_after(result, -1, 0.2, 1, SurfaceColoring::kFolds), UsageError);
}

// The other way round: a creased input opened flat (a bent joint straightened,
// its inner skin fold gone) is what unfolding should do, and no fold; a crease
// turned the other way keeps its sharpness and is none either.
TEST(SurfaceFolds, AnInputCreaseThatOpensOrTurnsIsNoFold) {
  const int nx = 6, ny = 5;
  Eigen::MatrixX3d V;
  Eigen::MatrixX3i F;
  sheet(nx, ny, &V, &F);
  const double x0 = nx / 2;
  const auto crease = [&](double degrees) { return creased(V, x0, degrees); };
  const SurfaceFolds opened = surface_folds(crease(120), V, F);
  EXPECT_EQ(opened.folded_edges, 0);
  EXPECT_EQ(opened.dihedral_change_max, 0);
  const SurfaceFolds turned = surface_folds(crease(120), crease(-120), F);
  EXPECT_EQ(turned.folded_edges, 0);
  EXPECT_LT(turned.dihedral_change_max, 1e-9);
  // Sharpened from 60 to 170 degrees: 110 more, folded.
  const SurfaceFolds sharper = surface_folds(crease(60), crease(170), F);
  EXPECT_EQ(sharper.folded_edges, ny);
  EXPECT_NEAR(sharper.dihedral_change_max, 110, 1e-9);
}

TEST(SurfaceFolds, RefusesMismatchedPositionsABadBoundAndBadIndices) {
  Eigen::MatrixX3d V;
  Eigen::MatrixX3i F;
  sheet(2, 2, &V, &F);
  EXPECT_THROW(surface_folds(V, V.topRows(3), F), UsageError);
  EXPECT_THROW(surface_folds(V, V, F, 0.0), UsageError);
  EXPECT_THROW(surface_folds(V, V, F, 4.0), UsageError);
  F(0, 0) = int(V.rows());
  EXPECT_THROW(surface_folds(V, V, F), UsageError);
}

}  // namespace
}  // namespace unfold
