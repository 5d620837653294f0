// Rectilinearity of a triangle mesh (Lian, Rosin and Sun, "Rectilinearity of
// 3D meshes", IJCV 2010) and the orientation that maximises it, one half of the
// PCA-plus-rectilinearity pose normalisation that ORT retrieval uses.
//
// A face of area a and unit normal n projects onto the three coordinate planes
// with total area a |n|_1, between a and sqrt(3) a; the ratio of the surface
// area to the total projected area is 1 exactly when every face is parallel to
// a coordinate plane. Rectilinearity rescales it to [0, 1]:
//   rect(R) = (A / sum_f a_f |R n_f|_1 - 1/sqrt(3)) / (1 - 1/sqrt(3)),
// and a mesh's rectilinearity is its largest value over rotations R.
#pragma once

#include <Eigen/Core>

namespace unfold {

/// rect(R) of the file comment for the mesh (V, F) rotated by R.
/// @throws UsageError for a mesh of zero area
double rectilinearity(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F,
                      const Eigen::Matrix3d& R);

/// The rotation R maximising rect(R): the best of 512 rotations spread
/// uniformly over SO(3) (a super-Fibonacci spiral, Alexa 2022), each of the
/// best 3 refined by coordinate descent over small rotations about the axes
/// down to 1e-7 rad. Defined up to the 24 rotations of a cube.
/// @throws UsageError for a mesh of zero area
Eigen::Matrix3d rectilinearity_orientation(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F);

}  // namespace unfold
