#include "metrics/correspondence_error.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <string>

#include "core/errors.h"
#include "metrics/graph_geodesics.h"

namespace unfold {

GeodesicTable geodesic_table(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F,
                             const std::vector<int>& sources) {
  const int n = int(V.rows());
  double area = 0;
  for (Eigen::Index f = 0; f < F.rows(); ++f)
    area += 0.5 * (V.row(F(f, 1)) - V.row(F(f, 0))).cross(V.row(F(f, 2)) - V.row(F(f, 0))).norm();
  if (!(area > 0)) throw InputError("geodesic_table: the target surface has no area");
  GeodesicTable table;
  table.row_of_vertex.assign(n, -1);
  std::vector<int> unique;
  for (const int s : sources) {
    if (s < 0 || s >= n)
      throw UsageError("geodesic_table: source vertex " + std::to_string(s) + " out of range");
    if (table.row_of_vertex[s] < 0) {
      table.row_of_vertex[s] = int(unique.size());
      unique.push_back(s);
    }
  }
  const EdgeGraph graph = build_edge_graph(n, Eigen::MatrixXi(F));
  const NeighborLengths lengths = neighbor_lengths(graph, V);
  table.rows.resize(Eigen::Index(unique.size()), n);
  const double scale = 1 / std::sqrt(area);
#pragma omp parallel
  {
    std::vector<double> distance;
#pragma omp for schedule(dynamic, 16)
    for (int r = 0; r < int(unique.size()); ++r) {
      graph_geodesics(graph, lengths, unique[r], &distance);
      for (int j = 0; j < n; ++j) table.rows(r, j) = float(distance[j] * scale);
    }
  }
  return table;
}

Eigen::VectorXd correspondence_errors(const GeodesicTable& table, const Eigen::VectorXi& map,
                                      const Eigen::VectorXi& source_points,
                                      const Eigen::VectorXi& target_points,
                                      const Eigen::VectorXi& mirrored_points) {
  const int n_target = int(table.row_of_vertex.size());
  if (source_points.size() != target_points.size() ||
      (mirrored_points.size() != 0 && mirrored_points.size() != target_points.size()))
    throw UsageError("correspondence_errors: the truth files hold different numbers of points");
  const auto row = [&](int vertex) {
    if (vertex < 0 || vertex >= n_target || table.row_of_vertex[vertex] < 0)
      throw UsageError("correspondence_errors: target vertex " + std::to_string(vertex) +
                       " has no geodesic row");
    return table.row_of_vertex[vertex];
  };
  Eigen::VectorXd errors(source_points.size());
  for (Eigen::Index k = 0; k < source_points.size(); ++k) {
    const int s = source_points(k);
    if (s < 0 || s >= map.size())
      throw UsageError("correspondence_errors: source point " + std::to_string(s) +
                       " is outside the map");
    const int image = map(s);
    if (image < 0 || image >= n_target)
      throw UsageError("correspondence_errors: the map names target vertex " +
                       std::to_string(image) + " out of range");
    double e = table.rows(row(target_points(k)), image);
    if (mirrored_points.size() != 0)
      e = std::min(e, double(table.rows(row(mirrored_points(k)), image)));
    errors(k) = e;
  }
  return errors;
}

}  // namespace unfold
