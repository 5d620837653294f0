// The oriented boundary chain: empty for closed, consistently oriented
// surfaces (self-intersecting ones too), a hole's rim once, a seam between
// patches oriented against each other twice.
#include "mesh/boundary_chain.h"

#include <gtest/gtest.h>

#include "test_meshes.h"

namespace unfold {
namespace {

TEST(BoundaryChain, EmptyForClosedSurfacesEvenSelfIntersecting) {
  EXPECT_TRUE(boundary_chain(triangulate_faces(test::uv_sphere(8, 12))).empty());
  EXPECT_TRUE(boundary_chain(triangulate_faces(test::two_interpenetrating_octahedra())).empty());
  EXPECT_TRUE(boundary_chain(triangulate_faces(test::cube())).empty());
}

TEST(BoundaryChain, AHolesRimOnceAlongItsFaces) {
  const SurfaceMesh sphere = test::uv_sphere(8, 12);
  Eigen::MatrixX3i F = triangulate_faces(sphere);
  // The north pole's fan (its first 12 faces are {0, at(1, s), at(1, s + 1)}, one
  // a segment) removed: the rim is the first ring, each edge once, in the
  // direction the remaining faces use it.
  Eigen::MatrixX3i open(F.rows(), 3);
  int rows = 0;
  for (Eigen::Index t = 0; t < F.rows(); ++t)
    if ((F.row(t).array() != 0).all()) open.row(rows++) = F.row(t);
  open.conservativeResize(rows, 3);
  const std::vector<ChainEdge> chain = boundary_chain(open);
  ASSERT_EQ(chain.size(), 12u);
  for (const ChainEdge& e : chain) {
    EXPECT_EQ(e.multiplicity, 1);
    EXPECT_GE(e.from, 1);
    EXPECT_LE(e.from, 12);
    bool used = false;  // some remaining face has from -> to
    for (Eigen::Index t = 0; t < open.rows(); ++t)
      for (int k = 0; k < 3; ++k)
        used = used || (open(t, k) == e.from && open(t, (k + 1) % 3) == e.to);
    EXPECT_TRUE(used);
  }
}

TEST(BoundaryChain, ASeamBetweenPatchesOrientedApartTwice) {
  // The octahedron with its upper four faces turned over: the equator, where
  // both halves now run the same way, twice; no other edge.
  const SurfaceMesh octahedron = test::octahedron();
  Eigen::MatrixX3i F = triangulate_faces(octahedron);
  for (Eigen::Index t = 0; t < F.rows(); ++t)
    if ((F.row(t).array() == 4).any()) std::swap(F(t, 1), F(t, 2));
  const std::vector<ChainEdge> chain = boundary_chain(F);
  ASSERT_EQ(chain.size(), 4u);
  for (const ChainEdge& e : chain) {
    EXPECT_EQ(e.multiplicity, 2);
    EXPECT_LT(e.from, 4);
    EXPECT_LT(e.to, 4);
  }
}

TEST(BoundaryChain, DegenerateCornersBoundNothing) {
  Eigen::MatrixX3i F = triangulate_faces(test::tetrahedron());
  F.conservativeResize(F.rows() + 2, 3);
  F.row(F.rows() - 2) << 0, 0, 1;
  F.row(F.rows() - 1) << 2, 2, 2;
  EXPECT_TRUE(boundary_chain(F).empty());
}

}  // namespace
}  // namespace unfold
