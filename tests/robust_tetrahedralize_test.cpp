// The robust tetrahedralization route and the fast winding number behind it:
// any real mesh (self-intersecting, non-manifold, small holes) gives one
// connected tet mesh with the surface vertices first, touching limbs stay
// apart, and every mesh of ../shared/data unfolds with the default settings.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>

#include "core/errors.h"
#include "core/parallel.h"
#include "mesh/edge_graph.h"
#include "mesh/read_surface_mesh.h"
#include "pipeline/unfold_surface.h"
#include "shapes/articulated_shape.h"
#include "test_meshes.h"
#include "tetra/delaunay_tets.h"
#include "tetra/fast_winding_number.h"
#include "tetra/interior_grid_points.h"
#include "tetra/run_tetgen.h"
#include "tetra/tetrahedralize.h"

namespace unfold {
namespace {

// Every surface vertex first and unmoved, every vertex in a tet, no zero-length
// edge, one connected edge graph: what the solver needs.
void expect_usable(const SurfaceMesh& surface, const TetMesh& tets) {
  const int n = int(surface.V.rows());
  ASSERT_EQ(tets.num_surface_vertices, n);
  ASSERT_GE(tets.V.rows(), n);
  EXPECT_EQ(tets.V.topRows(n), surface.V);
  const EdgeGraph graph = build_edge_graph(int(tets.V.rows()), tets.T);
  for (int v = 0; v < graph.num_vertices; ++v) EXPECT_GT(graph.degree(v), 0) << "vertex " << v;
  EXPECT_EQ(connected_components(graph), 1);
  for (int e = 0; e < graph.num_edges(); ++e)
    EXPECT_GT((tets.V.row(graph.edges(e, 0)) - tets.V.row(graph.edges(e, 1))).norm(), 0);
}

TEST(FastWindingNumber, MatchesTheExactSumInsideOutsideAndNearTheSurface) {
  const SurfaceMesh shape = make_articulated_shape(ShapePose::preset(1), 32);
  const Eigen::MatrixX3i F = triangulate_faces(shape);
  const FastWindingNumberTree tree = fast_winding_number_precomputation(shape.V, F);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(0, 1);
  const Eigen::RowVector3d low = shape.V.colwise().minCoeff(), high = shape.V.colwise().maxCoeff();
  Eigen::MatrixX3d Q(2000, 3);
  for (int i = 0; i < 1000; ++i)  // anywhere in the bounding box
    for (int k = 0; k < 3; ++k) Q(i, k) = low(k) + (high(k) - low(k)) * unit(random);
  for (int i = 1000; i < 2000; ++i)  // close to a vertex, inside or outside
    Q.row(i) =
        shape.V.row(int(unit(random) * double(shape.V.rows() - 1))) +
        0.02 * Eigen::RowVector3d(unit(random) - 0.5, unit(random) - 0.5, unit(random) - 0.5);
  const Eigen::VectorXd fast = fast_winding_number_solve(tree, Q);
  const Eigen::VectorXd exact = winding_number(shape.V, F, Q);
  // First-order far field with beta = 2: a few hundredths off on average
  // (docs/tetrahedralization.md), never on the wrong side of 1/2 when the
  // exact value is clearly inside or outside.
  EXPECT_LT((fast - exact).cwiseAbs().maxCoeff(), 0.15);
  EXPECT_LT((fast - exact).cwiseAbs().mean(), 0.05);
  int inside = 0;
  for (int i = 0; i < 2000; ++i) {
    if (std::abs(exact(i) - 0.5) > 0.2) {
      EXPECT_EQ(fast(i) > 0.5, exact(i) > 0.5) << exact(i);
    }
    inside += exact(i) > 0.5;
  }
  EXPECT_GT(inside, 200);
  EXPECT_LT(inside, 1800);
}

// Queries go down the tree in packets; a query's value must not depend on the
// others in its packet (nor on how many there are).
TEST(FastWindingNumber, AQuerysValueDoesNotDependOnItsPacket) {
  const SurfaceMesh shape = make_articulated_shape(ShapePose::preset(1), 24);
  const FastWindingNumberTree tree =
      fast_winding_number_precomputation(shape.V, triangulate_faces(shape));
  std::mt19937 random(11);
  std::uniform_real_distribution<double> unit(-1, 1);
  Eigen::MatrixX3d Q(203, 3);  // not a multiple of the packet size
  for (Eigen::Index i = 0; i < Q.rows(); ++i)
    Q.row(i) = shape.V.row(i * 7 % shape.V.rows()) +
               0.05 * Eigen::RowVector3d(unit(random), unit(random), unit(random));
  const Eigen::VectorXd together = fast_winding_number_solve(tree, Q);
  const Eigen::VectorXd coarse = fast_winding_number_classify(tree, Q);
  for (Eigen::Index i = 0; i < Q.rows(); i += 5) {
    const Eigen::MatrixX3d alone = Q.row(i);
    EXPECT_EQ(fast_winding_number_solve(tree, alone)(0), together(i)) << i;
    EXPECT_EQ(fast_winding_number_classify(tree, alone)(0), coarse(i)) << i;
  }
}

TEST(FastWindingNumber, ClassifyDecidesLikeTheAccurateTreeAndRefinesNearOneHalf) {
  // A surface with a large hole (the faces right of the middle dropped): near
  // the hole w runs smoothly through 1/2, as at the robust route's holes and
  // self-intersections; a closed surface jumps from 0 to 1 across itself.
  const SurfaceMesh shape = make_articulated_shape(ShapePose::preset(2), 32);
  const Eigen::MatrixX3i all = triangulate_faces(shape);
  const double middle = 0.5 * (shape.V.col(0).minCoeff() + shape.V.col(0).maxCoeff());
  std::vector<Eigen::RowVector3i> kept;
  for (Eigen::Index t = 0; t < all.rows(); ++t)
    if (shape.V(all(t, 0), 0) < middle) kept.push_back(all.row(t));
  Eigen::MatrixX3i F(Eigen::Index(kept.size()), 3);
  for (size_t t = 0; t < kept.size(); ++t) F.row(Eigen::Index(t)) = kept[t];
  const FastWindingNumberTree tree = fast_winding_number_precomputation(shape.V, F);
  std::mt19937 random(11);
  std::uniform_real_distribution<double> unit(0, 1);
  const Eigen::RowVector3d low = shape.V.colwise().minCoeff(), high = shape.V.colwise().maxCoeff();
  Eigen::MatrixX3d Q(4000, 3);
  for (int i = 0; i < 4000; ++i)
    for (int k = 0; k < 3; ++k) Q(i, k) = low(k) + (high(k) - low(k)) * unit(random);
  const Eigen::VectorXd accurate = fast_winding_number_solve(tree, Q);
  const ClassifyOptions options;
  const Eigen::VectorXd w = fast_winding_number_classify(tree, Q, options);
  int refined = 0, coarse = 0;
  for (int i = 0; i < 4000; ++i) {
    EXPECT_EQ(w(i) > 0.5, accurate(i) > 0.5) << accurate(i);
    if (std::abs(w(i) - 0.5) < options.margin) {
      EXPECT_EQ(w(i), accurate(i));  // evaluated again at the tree's accuracy
      ++refined;
    } else {
      coarse += w(i) != accurate(i);
      // Within the margin of the accurate value: what the robust route's
      // rescue relies on when it ranks tets by w.
      EXPECT_LT(std::abs(w(i) - accurate(i)), options.margin);
    }
  }
  EXPECT_GT(refined, 50);
  EXPECT_GT(coarse, 400);  // the first pass really is the coarser one
}

// The coarse pass runs in float. A query a hair's breadth off a face, inside
// or outside, is where float's rounding could take the face's solid angle to
// its other side (w off by 1): classify must still decide as the exact sum
// does, also far from the origin (the shape moved by 10^4 of its size).
TEST(FastWindingNumber, ClassifyDecidesRightAHairsBreadthOffTheSurface) {
  for (const double offset : {0.0, 1e4}) {
    SurfaceMesh shape = make_articulated_shape(ShapePose::preset(1), 24);
    const double size = (shape.V.colwise().maxCoeff() - shape.V.colwise().minCoeff()).norm();
    shape.V.array() += offset * size;
    const Eigen::MatrixX3i F = triangulate_faces(shape);
    const FastWindingNumberTree tree = fast_winding_number_precomputation(shape.V, F);
    std::vector<Eigen::RowVector3d> queries;
    for (Eigen::Index t = 0; t < F.rows(); t += 7) {
      const Eigen::RowVector3d a = shape.V.row(F(t, 0)), b = shape.V.row(F(t, 1)),
                               c = shape.V.row(F(t, 2));
      const Eigen::RowVector3d normal = (b - a).cross(c - a).normalized();
      const double edge = (b - a).norm();
      // Inside the face (not at its centroid, which a Delaunay tet's may be near).
      const Eigen::RowVector3d on = 0.5 * a + 0.3 * b + 0.2 * c;
      for (const double h : {1e-9, 1e-7, 1e-5, 1e-3})
        for (const double side : {-1.0, 1.0}) queries.push_back(on + side * h * edge * normal);
    }
    Eigen::MatrixX3d Q(Eigen::Index(queries.size()), 3);
    for (size_t i = 0; i < queries.size(); ++i) Q.row(Eigen::Index(i)) = queries[i];
    const Eigen::VectorXd exact = winding_number(shape.V, F, Q);
    const Eigen::VectorXd w = fast_winding_number_classify(tree, Q);
    int decided = 0;
    for (Eigen::Index i = 0; i < Q.rows(); ++i) {
      if (std::abs(exact(i) - 0.5) < 0.2) continue;  // a fold or a contact: no clear side
      EXPECT_EQ(w(i) > 0.5, exact(i) > 0.5) << "query " << i << ", offset " << offset;
      ++decided;
    }
    EXPECT_GT(decided, Q.rows() * 9 / 10);
  }
}

TEST(RobustTetrahedralize, FillsASphereWithTheSurfaceVerticesFirst) {
  const SurfaceMesh sphere = test::uv_sphere(12, 24, 2.0);
  TetOptions options;
  options.route = "robust";
  TetReport report;
  const TetMesh tets = tetrahedralize(sphere, options, &report);
  expect_usable(sphere, tets);
  EXPECT_EQ(report.route, "robust");
  EXPECT_EQ(report.num_tets, tets.T.rows());
  EXPECT_EQ(report.num_interior_points, tets.V.rows() - sphere.V.rows());
  EXPECT_GT(report.num_interior_points, 0);
  EXPECT_GT(report.num_removed_tets, 0);  // the Delaunay hull is not the sphere
  double volume = 0;
  for (Eigen::Index t = 0; t < tets.T.rows(); ++t) {
    const Eigen::Vector3d a = tets.V.row(tets.T(t, 0)), b = tets.V.row(tets.T(t, 1)),
                          c = tets.V.row(tets.T(t, 2)), d = tets.V.row(tets.T(t, 3));
    volume += std::abs((b - a).cross(c - a).dot(d - a)) / 6;
  }
  EXPECT_GT(volume, 0.8 * 4.0 / 3.0 * M_PI * 8.0);
  EXPECT_LT(volume, 4.0 / 3.0 * M_PI * 8.0);
}

// tetrahedralize.interior_spacing: a grid of spacing h inside a ball of radius
// 2 has about its volume over h^3 points (fewer: none within h/2 of a surface vertex).
TEST(RobustTetrahedralize, TheInteriorGridHasTheGivenSpacing) {
  const SurfaceMesh sphere = test::uv_sphere(24, 48, 2.0);
  TetOptions options;
  options.route = "robust";
  const double ball = 4.0 / 3.0 * M_PI * 8.0;
  for (const double h : {0.4, 0.25}) {
    options.interior_spacing = h;
    TetReport report;
    const TetMesh tets = tetrahedralize(sphere, options, &report);
    expect_usable(sphere, tets);
    EXPECT_GT(report.num_interior_points, 0.6 * ball / (h * h * h)) << h;
    EXPECT_LT(report.num_interior_points, 1.0 * ball / (h * h * h)) << h;
  }
}

// An N^3 lattice (x, then y, then z in input order) sheared by `shear` as the
// robust route shears its grid.
Eigen::MatrixX3d sheared_lattice(int N, double shear) {
  Eigen::MatrixX3d points(N * N * N, 3);
  for (int i = 0; i < N * N * N; ++i) {
    const double x = i / (N * N), y = i / N % N, z = i % N;
    points.row(i) << x + shear * (y + z), y + shear * (x + z), z + shear * (x + y);
  }
  return points;
}

// The edges of the tets T of an N^3 lattice, leaving out edges between two
// points on the lattice's boundary: the hull's coplanar points are split
// arbitrarily, which the robust route never sees (its hull is the surface).
std::set<std::pair<int, int>> lattice_edges(int N, const Eigen::MatrixX4i& T) {
  const auto on_boundary = [N](int i) {
    const int c[3] = {i / (N * N), i / N % N, i % N};
    return std::any_of(c, c + 3, [N](int x) { return x == 0 || x == N - 1; });
  };
  std::set<std::pair<int, int>> edges;
  for (Eigen::Index t = 0; t < T.rows(); ++t)
    for (int a = 0; a < 4; ++a)
      for (int b = a + 1; b < 4; ++b) {
        const int i = std::min(T(t, a), T(t, b)), j = std::max(T(t, a), T(t, b));
        if (!on_boundary(i) || !on_boundary(j)) edges.emplace(i, j);
      }
  return edges;
}

// TetGen's Delaunay of the unsheared lattice: every cell split by its symbolic perturbation.
std::set<std::pair<int, int>> tetgen_lattice_edges(int N) {
  const Eigen::MatrixX3d points = sheared_lattice(N, 0.0);
  tetgenio in;
  in.firstnumber = 0;
  in.numberofpoints = int(points.rows());
  in.pointlist = new REAL[size_t(in.numberofpoints) * 3];
  for (int i = 0; i < in.numberofpoints; ++i)
    for (int k = 0; k < 3; ++k) in.pointlist[3 * i + k] = points(i, k);
  return lattice_edges(N, run_tetgen("zQ", in, "lattice test").tets);
}

// The robust route shears its interior grid so that the Delaunay needs no
// exact arithmetic on cospherical cell corners, and so that its tets do not
// depend on how a library breaks such ties: the sheared grid's Delaunay
// (CGAL's) must split every cell as TetGen's symbolic perturbation split the
// unsheared lattice when TetGen made the robust route's Delaunay, or the tet
// mesh (and E_rig, E_str) would change with it.
TEST(RobustTetrahedralize, InteriorGridShearSplitsCellsAsTetGensPerturbation) {
  const int N = 6;
  const std::set<std::pair<int, int>> perturbed = tetgen_lattice_edges(N);
  const Eigen::MatrixX3d sheared = sheared_lattice(N, kInteriorGridShear);
  EXPECT_EQ(lattice_edges(N, delaunay_tets(sheared)), perturbed);
  // 6 tets per cell around the (1, 1, 1) diagonal: one diagonal per cell and
  // one per face, besides the lattice edges.
  const int diagonal = N * N + N + 1;  // index step from corner (0, 0, 0) to (1, 1, 1)
  for (int x = 1; x + 2 < N; ++x)
    for (int y = 1; y + 2 < N; ++y)
      for (int z = 1; z + 2 < N; ++z) {
        const int i = (x * N + y) * N + z;
        EXPECT_TRUE(perturbed.count({i, i + diagonal})) << x << " " << y << " " << z;
      }
  // The sign matters: the opposite shear splits cells along another diagonal.
  EXPECT_NE(lattice_edges(N, delaunay_tets(sheared_lattice(N, -kInteriorGridShear))), perturbed);
}

// The Delaunay's tets are positively oriented, hold every point, and fill the
// convex hull: a jittered lattice's tets sum to its box's volume. Points that
// coincide or lie in a plane are refused.
TEST(DelaunayTets, FillsTheHullWithPositiveTetsAndRefusesDegeneratePoints) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> jitter(-0.2, 0.2);
  const int N = 5;
  Eigen::MatrixX3d points = sheared_lattice(N, 0.0);
  for (Eigen::Index i = 0; i < points.rows(); ++i)
    for (int k = 0; k < 3; ++k)
      if (points(i, k) > 0 && points(i, k) < N - 1) points(i, k) += jitter(random);
  const Eigen::MatrixX4i T = delaunay_tets(points);
  std::vector<char> used(size_t(points.rows()), 0);
  double volume = 0;
  for (Eigen::Index t = 0; t < T.rows(); ++t) {
    const Eigen::Vector3d a = points.row(T(t, 0)), b = points.row(T(t, 1)), c = points.row(T(t, 2)),
                          d = points.row(T(t, 3));
    const double v = (b - a).cross(c - a).dot(d - a) / 6;
    EXPECT_GT(v, 0) << "tet " << t;
    volume += v;
    for (int k = 0; k < 4; ++k) used[size_t(T(t, k))] = 1;
  }
  EXPECT_NEAR(volume, std::pow(N - 1, 3), 1e-9);
  EXPECT_EQ(std::count(used.begin(), used.end(), 1), points.rows());

  Eigen::MatrixX3d twice = points;
  twice.row(3) = twice.row(17);
  EXPECT_THROW(delaunay_tets(twice), NumericalError);
  Eigen::MatrixX3d flat = points;
  flat.col(2).setZero();  // a plane (coinciding points too: the plane is found first)
  EXPECT_THROW(delaunay_tets(flat), NumericalError);
  points(4, 1) = std::nan("");
  EXPECT_THROW(delaunay_tets(points), NumericalError);
}

// TetGen's conforming mode refuses these surfaces (the conforming route
// throws on each); auto knows it beforehand and goes robust without trying.
TEST(RobustTetrahedralize, AutoGoesRobustWithoutTryingOnASelfIntersectingSurface) {
  const SurfaceMesh folded = test::two_interpenetrating_octahedra();
  TetReport report;
  const TetMesh tets = tetrahedralize(folded, TetOptions{}, &report);
  expect_usable(folded, tets);
  EXPECT_EQ(report.route, "robust");
  EXPECT_GT(report.num_intersecting_faces, 0);
  EXPECT_NE(report.fallback.find("intersects itself"), std::string::npos) << report.fallback;
  EXPECT_NE(report.fallback.find("not tried"), std::string::npos) << report.fallback;
  TetOptions conforming;
  conforming.route = "conforming";
  EXPECT_THROW(tetrahedralize(folded, conforming), NumericalError);
}

// From kMinParallelRows vertices auto takes the robust route's first steps
// while it counts intersecting faces: a clean surface still goes conforming,
// a self-intersecting one gets the robust route's very tets.
TEST(RobustTetrahedralize, AutoOnLargeSurfacesDecidesAsOnSmallOnes) {
  const SurfaceMesh sphere = test::uv_sphere(65, 130);
  ASSERT_GE(sphere.V.rows(), kMinParallelRows);
  TetReport report;
  TetOptions conforming;
  conforming.route = "conforming";
  const TetMesh automatic = tetrahedralize(sphere, TetOptions{}, &report);
  EXPECT_EQ(report.route, "conforming");
  EXPECT_EQ(report.fallback, "");
  const TetMesh expected = tetrahedralize(sphere, conforming);
  EXPECT_EQ(automatic.V, expected.V);
  EXPECT_EQ(automatic.T, expected.T);

  SurfaceMesh two = test::uv_sphere(46, 92);  // two overlapping spheres
  const int n = int(two.V.rows());
  two.V.conservativeResize(2 * n, 3);
  two.V.bottomRows(n) = two.V.topRows(n).rowwise() + Eigen::RowVector3d(1.0, 0.1, 0.0);
  for (size_t f = 0, count = two.faces.size(); f < count; ++f) {
    std::vector<int> face = two.faces[f];
    for (int& v : face) v += n;
    two.faces.push_back(face);
  }
  ASSERT_GE(two.V.rows(), kMinParallelRows);
  TetOptions robust;
  robust.route = "robust";
  TetReport robust_report;
  const TetMesh folded = tetrahedralize(two, TetOptions{}, &report);
  const TetMesh direct = tetrahedralize(two, robust, &robust_report);
  EXPECT_EQ(report.route, "robust");
  EXPECT_GT(report.num_intersecting_faces, 0);
  EXPECT_EQ(report.num_intersecting_faces, robust_report.num_intersecting_faces);
  EXPECT_EQ(folded.V, direct.V);
  EXPECT_EQ(folded.T, direct.T);
}

// Vertex 0 copied: the copy takes over half of vertex 0's faces, so the two
// are distinct vertices at one position (TetGen alone would merge them).
SurfaceMesh sphere_with_a_vertex_twice() {
  SurfaceMesh sphere = test::uv_sphere(8, 12);
  const int copy = int(sphere.V.rows());
  sphere.V.conservativeResize(copy + 1, 3);
  sphere.V.row(copy) = sphere.V.row(0);
  int moved = 0;
  for (auto& f : sphere.faces)
    for (int& v : f)
      if (v == 0 && moved++ % 2 == 0) v = copy;
  EXPECT_GT(moved, 2);
  return sphere;
}

TEST(RobustTetrahedralize, AutoGoesRobustWithoutTryingWithVerticesAtOnePosition) {
  const SurfaceMesh sphere = sphere_with_a_vertex_twice();
  TetReport report;
  expect_usable(sphere, tetrahedralize(sphere, TetOptions{}, &report));
  EXPECT_EQ(report.route, "robust");
  EXPECT_EQ(report.num_intersecting_faces, 0);
  EXPECT_NE(report.fallback.find("at one position"), std::string::npos) << report.fallback;
  TetOptions conforming;
  conforming.route = "conforming";
  EXPECT_THROW(tetrahedralize(sphere, conforming), NumericalError);
}

TEST(RobustTetrahedralize, KeepsVerticesAtEqualPositionsApart) {
  const SurfaceMesh sphere = sphere_with_a_vertex_twice();
  TetOptions options;
  options.route = "robust";
  expect_usable(sphere, tetrahedralize(sphere, options));
}

TEST(RobustTetrahedralize, UnknownRouteNamesTheKnownOnes) {
  TetOptions options;
  options.route = "magic";
  try {
    tetrahedralize(test::octahedron(), options);
    FAIL() << "unknown route accepted";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("robust"), std::string::npos) << e.what();
  }
}

// The animal with its front legs swung towards each other until they touch:
// tets bridging the gap would glue them; unfolding must pull them apart.
TEST(RobustTetrahedralize, TouchingLegsComeApartWhenUnfolded) {
  const SurfaceMesh rest = make_articulated_shape(ShapePose::rest(), 32);
  ShapePose pose;
  pose.front_left.hip_spread = pose.front_right.hip_spread = -8;
  const SurfaceMesh posed = make_articulated_shape(pose, 32);
  // Lower front legs, left (+y) and right (-y), picked in the rest pose.
  const double low = rest.V.col(2).minCoeff(), high = rest.V.col(2).maxCoeff();
  std::vector<int> left, right;
  for (int i = 0; i < int(rest.V.rows()); ++i)
    if (rest.V(i, 2) < low + 0.3 * (high - low) && rest.V(i, 0) > 0)
      (rest.V(i, 1) > 0 ? left : right).push_back(i);
  const auto gap = [&](const Eigen::MatrixX3d& V) {
    double d = INFINITY;
    for (int i : left)
      for (int j : right) d = std::min(d, (V.row(i) - V.row(j)).norm());
    return d;
  };
  const double mean_edge = 3.5 / 32;  // body length over resolution, roughly
  ASSERT_LT(gap(posed.V), 0.5 * mean_edge) << "the legs should touch in the input";
  Options options;
  options.tet.route = "robust";
  const UnfoldResult r = unfold_surface(posed, options);
  EXPECT_GT(gap(r.canonical.V), 0.5 * gap(rest.V)) << "the legs stayed glued";
}

// Every mesh of ../shared/data with the paper's method: same vertices and
// faces out, edge ratio in the band, limbs stretched (E_str), details kept (E_rig).
// (E_geo, not asserted, is left out: it took about 40 % of a run.)
void expect_unfolds(const std::string& relative) {
  const std::string path = test::shared_data(relative);
  if (path.empty()) GTEST_SKIP() << "shared data absent: " << relative;
  const SurfaceMesh input = read_surface_mesh(path);
  Options options = paper_options();
  options.metrics = {"E_rig", "E_str"};
  const UnfoldResult r = unfold_surface(input, options);
  SCOPED_TRACE(relative + " (route " + r.tet_report.route + ")");
  ASSERT_EQ(r.canonical.V.rows(), input.V.rows());
  EXPECT_EQ(r.canonical.faces, input.faces);
  EXPECT_TRUE(r.canonical.V.allFinite());
  EXPECT_GE(r.cascade.edge_ratio, 0.95);
  EXPECT_LE(r.cascade.edge_ratio, 1.05);
  EXPECT_GT(r.metrics.E_str, 0.05);
  // centaur3 ends at E_rig 1.14: the paper's cascade stops on a transient while
  // its back is still straightening (docs/tetrahedralization.md); finishing and
  // accelerating the iterations brings it to 0.905 but makes canonical forms
  // less pose-invariant, so configs/paper.yaml stays the paper's.
  EXPECT_LT(r.metrics.E_rig, relative == "tosca/centaur3.off" ? 1.2 : 1.0);
}

class RobustSharedData : public ::testing::TestWithParam<const char*> {};

TEST_P(RobustSharedData, UnfoldsWithThePapersSettings) { expect_unfolds(GetParam()); }

INSTANTIATE_TEST_SUITE_P(Meshes, RobustSharedData,
                         ::testing::Values("tosca/wolf0.off", "tosca/centaur0.off",
                                           "tosca/centaur1.off", "tosca/centaur2.off",
                                           "tosca/centaur3.off", "tosca/centaur4.off",
                                           "tosca/centaur5.off", "faust/tr_reg_000.off",
                                           "faust/tr_reg_001.off", "faust/tr_reg_002.off",
                                           "faust/tr_reg_003.off"));

TEST(RobustSharedDataCats, UnfoldWithThePapersSettings) {
  expect_unfolds("tosca/cat0.off");
  expect_unfolds("tosca/cat1.off");
}

// centaur3's E_rig above 1 is the paper's cascade stopping on a transient
// (docs/tetrahedralization.md): finished and accelerated, it goes under 1.
TEST(RobustSharedData, Centaur3UnderOneWithTheCascadeFinished) {
  const std::string path = test::shared_data("tosca/centaur3.off");
  if (path.empty()) GTEST_SKIP() << "shared data absent: tosca/centaur3.off";
  Options options = paper_options();
  options.cascade.break_in_band = false;
  options.cascade.anderson = 5;
  options.metrics = {"E_rig"};
  const UnfoldResult r = unfold_surface(read_surface_mesh(path), options);
  EXPECT_TRUE(r.cascade.reached_band);
  EXPECT_LT(r.metrics.E_rig, 1.0);
}

TEST(RobustSharedData, RobustIsAsGoodAsConformingOnACleanMesh) {
  const std::string path = test::shared_data("tosca/wolf0.off");
  if (path.empty()) GTEST_SKIP() << "shared data absent: tosca/wolf0.off";
  const SurfaceMesh input = read_surface_mesh(path);
  Options conforming, robust;  // both on the input's tets
  conforming.tet.route = "conforming";
  conforming.metrics = {"E_rig"};
  robust = conforming;
  robust.tet.route = "robust";
  robust.tet_shape = "input";
  const UnfoldResult c = unfold_surface(input, conforming);
  const UnfoldResult r = unfold_surface(input, robust);
  EXPECT_EQ(r.tet_report.route, "robust");
  EXPECT_LE(r.metrics.E_rig, 1.1 * c.metrics.E_rig);
}

}  // namespace
}  // namespace unfold
