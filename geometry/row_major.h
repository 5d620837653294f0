// Row-major n x 3 matrices: each vertex is 3 contiguous doubles, as the Ceres
// functors take them (floats in the AMG's single-precision V-cycle).
#pragma once

#include <Eigen/Core>

namespace unfold {

template <typename Scalar>
using RowMatrixX3 = Eigen::Matrix<Scalar, Eigen::Dynamic, 3, Eigen::RowMajor>;
using RowMatrixX3d = RowMatrixX3<double>;
using RowMatrixX3f = RowMatrixX3<float>;

}  // namespace unfold
