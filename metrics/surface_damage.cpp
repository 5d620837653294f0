#include "metrics/surface_damage.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>

#include "core/errors.h"
#include "core/nearest_rank.h"

namespace unfold {
namespace {

// Area of the fan-triangulated faces (as triangulate_faces splits them).
double fan_area(const Eigen::MatrixX3d& V, const std::vector<std::vector<int>>& faces) {
  double area = 0;
  for (const std::vector<int>& face : faces) {
    const Eigen::Vector3d a = V.row(face[0]);
    for (size_t k = 1; k + 1 < face.size(); ++k) {
      const Eigen::Vector3d b = V.row(face[k]), c = V.row(face[k + 1]);
      area += 0.5 * (b - a).cross(c - a).norm();
    }
  }
  return area;
}

}  // namespace

SurfaceDamage surface_damage(const Eigen::MatrixX3d& V_in, const Eigen::MatrixX3d& V_out,
                             const std::vector<std::vector<int>>& faces, double bound) {
  const Eigen::Index n = V_in.rows();
  if (V_out.rows() != n)
    throw UsageError("surface_damage: " + std::to_string(n) + " input and " +
                     std::to_string(V_out.rows()) + " output vertices");
  if (!(bound > 1)) throw UsageError("surface_damage: the bound must be above 1");
  if (faces.empty()) throw InputError("surface_damage: the surface has no face");
  std::vector<std::pair<int, int>> edges;
  for (size_t f = 0; f < faces.size(); ++f) {
    const std::vector<int>& face = faces[f];
    if (face.size() < 3)
      throw InputError("surface_damage: face " + std::to_string(f) + " has " +
                       std::to_string(face.size()) + " vertices");
    for (size_t k = 0; k < face.size(); ++k) {
      const int i = face[k], j = face[(k + 1) % face.size()];
      if (i < 0 || i >= n)
        throw InputError("surface_damage: face " + std::to_string(f) + " refers to vertex " +
                         std::to_string(i) + " of " + std::to_string(n));
      if (i != j) edges.emplace_back(std::min(i, j), std::max(i, j));
    }
  }
  if (!V_in.allFinite()) throw InputError("surface_damage: an input coordinate is not finite");
  if (!V_out.allFinite())
    throw NumericalError("surface_damage: an output coordinate is not finite");
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  const double area_in = fan_area(V_in, faces), area_out = fan_area(V_out, faces);
  if (!(area_in > 0)) throw InputError("surface_damage: the input surface has zero area");
  if (!(area_out > 0)) throw NumericalError("surface_damage: the output surface has zero area");

  SurfaceDamage d;
  d.scale = std::sqrt(area_in / area_out);
  d.per_vertex = Eigen::VectorXd::Zero(n);
  d.per_vertex_ratio = Eigen::VectorXd::Ones(n);
  std::vector<double> ratios;
  ratios.reserve(edges.size());
  const double collapsed = -std::log(std::numeric_limits<double>::min());
  for (const auto& [i, j] : edges) {
    const double rest = (V_in.row(i) - V_in.row(j)).norm();
    if (rest == 0) {
      ++d.zero_length_edges;
      continue;
    }
    const double r = d.scale * (V_out.row(i) - V_out.row(j)).norm() / rest;
    ratios.push_back(r);
    if (r < 1 / bound || r > bound) ++d.damaged_edges;
    const double damage = r > 0 ? std::abs(std::log(r)) : collapsed;
    for (const int v : {i, j})
      if (damage > d.per_vertex[v]) {
        d.per_vertex[v] = damage;
        d.per_vertex_ratio[v] = r;
      }
  }
  d.edges = int(ratios.size());
  if (ratios.empty()) return d;
  d.damaged_edges_percent = 100.0 * d.damaged_edges / d.edges;
  const auto [low, high] = std::minmax_element(ratios.begin(), ratios.end());
  d.ratio_min = *low;
  d.ratio_max = *high;
  d.ratio_p999 = nearest_rank(&ratios, 999);
  return d;
}

SurfaceDamage surface_damage(const Eigen::MatrixX3d& V_in, const Eigen::MatrixX3d& V_out,
                             const Eigen::MatrixXi& F, double bound) {
  std::vector<std::vector<int>> faces(size_t(F.rows()));
  for (Eigen::Index f = 0; f < F.rows(); ++f)
    for (Eigen::Index c = 0; c < F.cols(); ++c) faces[size_t(f)].push_back(F(f, c));
  return surface_damage(V_in, V_out, faces, bound);
}

}  // namespace unfold
