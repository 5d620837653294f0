#include "metrics/surface_folds.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "core/errors.h"
#include "core/nearest_rank.h"

namespace unfold {
namespace {

constexpr double kPi = 3.14159265358979323846;

// The signed dihedral angle at edge (a, b) between triangles with normals n1, n2.
double dihedral(const Eigen::Vector3d& n1, const Eigen::Vector3d& n2, const Eigen::Vector3d& e) {
  return std::atan2(n1.cross(n2).dot(e), n1.dot(n2));
}

}  // namespace

SurfaceFolds surface_folds(const Eigen::MatrixX3d& V_in, const Eigen::MatrixX3d& V_out,
                           const Eigen::MatrixX3i& F, double bound) {
  const Eigen::Index n = V_in.rows();
  if (V_out.rows() != n)
    throw UsageError("surface_folds: " + std::to_string(n) + " input and " +
                     std::to_string(V_out.rows()) + " output vertices");
  if (!(bound > 0 && bound < kPi)) throw UsageError("surface_folds: the bound must be in (0, pi)");
  if (F.size() > 0 && (F.minCoeff() < 0 || F.maxCoeff() >= n))
    throw UsageError("surface_folds: a triangle's vertex is not one of the " + std::to_string(n) +
                     " vertices");
  // Unit normals per triangle in both positions (zero where degenerate).
  const auto normals = [&](const Eigen::MatrixX3d& V) {
    Eigen::MatrixX3d N(F.rows(), 3);
    for (Eigen::Index t = 0; t < F.rows(); ++t) {
      const Eigen::Vector3d a = V.row(F(t, 0)), b = V.row(F(t, 1)), c = V.row(F(t, 2));
      const Eigen::Vector3d m = (b - a).cross(c - a);
      const double length = m.norm();
      N.row(t) = length > 0 && std::isfinite(length) ? Eigen::Vector3d(m / length)
                                                     : Eigen::Vector3d::Zero();
    }
    return N;
  };
  const Eigen::MatrixX3d N_in = normals(V_in), N_out = normals(V_out);
  // (edge key, triangle) pairs sorted: each edge's triangles are adjacent.
  std::vector<std::pair<uint64_t, int>> sides;
  sides.reserve(size_t(3 * F.rows()));
  for (Eigen::Index t = 0; t < F.rows(); ++t)
    for (int k = 0; k < 3; ++k) {
      int a = F(t, k), b = F(t, (k + 1) % 3);
      if (a > b) std::swap(a, b);
      sides.emplace_back((uint64_t(uint32_t(a)) << 32) | uint32_t(b), int(t));
    }
  std::sort(sides.begin(), sides.end());
  SurfaceFolds out;
  out.per_vertex = Eigen::VectorXd::Zero(n);
  std::vector<double> changes;
  for (size_t s = 0; s < sides.size();) {
    size_t end = s;
    while (end < sides.size() && sides[end].first == sides[s].first) ++end;
    if (end - s == 2) {
      const int t1 = sides[s].second, t2 = sides[s + 1].second;
      const int a = int(sides[s].first >> 32), b = int(sides[s].first & 0xffffffffu);
      if (N_in.row(t1).squaredNorm() > 0 && N_in.row(t2).squaredNorm() > 0 &&
          N_out.row(t1).squaredNorm() > 0 && N_out.row(t2).squaredNorm() > 0) {
        const Eigen::Vector3d e_in = (V_in.row(b) - V_in.row(a)).normalized();
        const Eigen::Vector3d e_out = (V_out.row(b) - V_out.row(a)).normalized();
        const double change =
            std::max(0.0, std::abs(dihedral(N_out.row(t1), N_out.row(t2), e_out)) -
                              std::abs(dihedral(N_in.row(t1), N_in.row(t2), e_in)));
        const double degrees = change * 180 / kPi;
        changes.push_back(degrees);
        out.folded_edges += change > bound;
        out.per_vertex[a] = std::max(out.per_vertex[a], degrees);
        out.per_vertex[b] = std::max(out.per_vertex[b], degrees);
      }
    }
    s = end;
  }
  out.edges = int(changes.size());
  if (out.edges == 0) return out;
  out.folded_edges_percent = 100.0 * out.folded_edges / out.edges;
  out.dihedral_change_max = *std::max_element(changes.begin(), changes.end());
  out.dihedral_change_p999 = nearest_rank(&changes, 999);
  return out;
}

}  // namespace unfold
