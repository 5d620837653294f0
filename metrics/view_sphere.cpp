#include "metrics/view_sphere.h"

#include <map>
#include <utility>

#include "core/errors.h"
#include "metrics/ort_dissimilarity.h"

namespace unfold {

Eigen::MatrixX3d view_sphere_directions(int subdivisions) {
  if (subdivisions < 0 || subdivisions > 3)
    throw UsageError("view sphere: subdivisions must be in [0, 3]");
  std::vector<Eigen::Vector3d> points = {{1, 0, 0},  {-1, 0, 0}, {0, 1, 0},
                                         {0, -1, 0}, {0, 0, 1},  {0, 0, -1}};
  std::vector<Eigen::Vector3i> faces;
  for (int x : {0, 1})
    for (int y : {2, 3})
      for (int z : {4, 5}) faces.emplace_back(x, y, z);
  for (int level = 0; level < subdivisions; ++level) {
    std::map<std::pair<int, int>, int> midpoint;
    const auto middle = [&](int a, int b) {
      const auto key = std::minmax(a, b);
      const auto found = midpoint.find(key);
      if (found != midpoint.end()) return found->second;
      points.push_back((points[size_t(a)] + points[size_t(b)]).normalized());
      return midpoint[key] = int(points.size()) - 1;
    };
    std::vector<Eigen::Vector3i> finer;
    for (const Eigen::Vector3i& f : faces) {
      const int ab = middle(f[0], f[1]), bc = middle(f[1], f[2]), ca = middle(f[2], f[0]);
      finer.emplace_back(f[0], ab, ca), finer.emplace_back(ab, f[1], bc);
      finer.emplace_back(ca, bc, f[2]), finer.emplace_back(ab, bc, ca);
    }
    faces = std::move(finer);
  }
  Eigen::MatrixX3d directions(Eigen::Index(points.size()), 3);
  for (size_t i = 0; i < points.size(); ++i) directions.row(Eigen::Index(i)) = points[i];
  return directions;
}

std::vector<std::vector<int>> view_sphere_rotations(const Eigen::MatrixX3d& directions) {
  std::vector<std::vector<int>> permutations;
  const Eigen::Index n = directions.rows();
  for (const Eigen::Matrix3d& R : cube_rotations()) {
    const Eigen::MatrixX3d rotated = directions * R.transpose();
    std::vector<int> p(static_cast<size_t>(n));
    for (Eigen::Index v = 0; v < n; ++v) {
      Eigen::Index nearest;
      const double d =
          (directions.rowwise() - rotated.row(v)).rowwise().squaredNorm().minCoeff(&nearest);
      if (d > 1e-12) throw UsageError("view sphere: a rotated direction is not a view");
      p[size_t(v)] = int(nearest);
    }
    permutations.push_back(std::move(p));
  }
  return permutations;
}

}  // namespace unfold
