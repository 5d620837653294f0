#include "metrics/rectilinearity.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <vector>

#include "core/errors.h"

namespace unfold {
namespace {

// Rows: each face's area times its unit normal (half the cross product).
Eigen::MatrixX3d area_normals(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F) {
  Eigen::MatrixX3d N(F.rows(), 3);
  for (Eigen::Index f = 0; f < F.rows(); ++f) {
    const Eigen::Vector3d a = V.row(F(f, 0)), b = V.row(F(f, 1)), c = V.row(F(f, 2));
    N.row(f) = 0.5 * (b - a).cross(c - a);
  }
  if (N.rowwise().norm().sum() <= 0) throw UsageError("rectilinearity: the mesh has zero area");
  return N;
}

// sum_f a_f |R n_f|_1: the total area projected onto the coordinate planes.
double projected_area(const Eigen::MatrixX3d& N, const Eigen::Matrix3d& R) {
  return (N * R.transpose()).cwiseAbs().sum();
}

}  // namespace

double rectilinearity(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F,
                      const Eigen::Matrix3d& R) {
  const Eigen::MatrixX3d N = area_normals(V, F);
  const double inv_sqrt3 = 1 / std::sqrt(3.0);
  return (N.rowwise().norm().sum() / projected_area(N, R) - inv_sqrt3) / (1 - inv_sqrt3);
}

Eigen::Matrix3d rectilinearity_orientation(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F) {
  const Eigen::MatrixX3d N = area_normals(V, F);
  // Super-Fibonacci spiral: n quaternions spread uniformly over S^3.
  const int n = 512;
  const double phi = std::sqrt(2.0), psi = 1.533751168755204288118041;
  std::vector<std::pair<double, Eigen::Matrix3d>> candidates;
  for (int i = 0; i < n; ++i) {
    const double s = i + 0.5, r = std::sqrt(s / n), R = std::sqrt(1 - s / n);
    const double alpha = 2 * M_PI * s / phi, beta = 2 * M_PI * s / psi;
    const Eigen::Matrix3d rotation = Eigen::Quaterniond(R * std::cos(beta), r * std::sin(alpha),
                                                        r * std::cos(alpha), R * std::sin(beta))
                                         .toRotationMatrix();
    candidates.emplace_back(projected_area(N, rotation), rotation);
  }
  std::partial_sort(candidates.begin(), candidates.begin() + 3, candidates.end(),
                    [](const auto& a, const auto& b) { return a.first < b.first; });
  std::pair<double, Eigen::Matrix3d> best = candidates[0];
  for (int c = 0; c < 3; ++c) {
    auto [value, rotation] = candidates[size_t(c)];
    for (double step = 0.05; step > 1e-7;) {
      bool improved = false;
      for (int axis = 0; axis < 3; ++axis)
        for (double sign : {-1.0, 1.0}) {
          const Eigen::Matrix3d trial =
              Eigen::AngleAxisd(sign * step, Eigen::Vector3d::Unit(axis)).toRotationMatrix() *
              rotation;
          const double v = projected_area(N, trial);
          if (v < value) value = v, rotation = trial, improved = true;
        }
      if (!improved) step /= 2;
    }
    if (value < best.first) best = {value, rotation};
  }
  return best.second;
}

}  // namespace unfold
