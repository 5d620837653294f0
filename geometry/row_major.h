// Row-major n x 3 matrices: each vertex is 3 contiguous doubles, as the Ceres
// functors take them.
#pragma once

#include <Eigen/Core>

namespace unfold {

using RowMatrixX3d = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;

}  // namespace unfold
