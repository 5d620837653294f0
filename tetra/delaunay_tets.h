// The Delaunay tetrahedralization of a point set, which the robust route
// carves (tetra/tetrahedralize.h). CGAL's, in this process: unlike TetGen's
// (tetra/run_tetgen.h) it cannot fail on a valid point set, so it needs no
// child process, whose fork costs more than the triangulation on small shapes.
#pragma once

#include <Eigen/Core>

namespace unfold {

/// The Delaunay tetrahedralization of the rows of `points`. Four or more
/// cospherical points are split by CGAL's symbolic perturbation.
/// @param points n x 3, finite and pairwise distinct, not all coplanar
/// @return one row per tet: 0-based rows of points, each tet positively
///         oriented (det(b - a, c - a, d - a) > 0); every point is in some tet
/// @throws NumericalError if points coincide (one would be in no tet), or all
///         lie in a plane, or some coordinate is not finite
Eigen::MatrixX4i delaunay_tets(const Eigen::MatrixX3d& points);

}  // namespace unfold
