// A CGAL translation unit (compiled apart: CMakeLists.txt, unfold_cgal).
#include "tetra/delaunay_tets.h"

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include <string>
#include <utility>
#include <vector>

#include "core/errors.h"

namespace unfold {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using VertexBase = CGAL::Triangulation_vertex_base_with_info_3<int, Kernel>;
using CellBase = CGAL::Delaunay_triangulation_cell_base_3<Kernel>;
using Delaunay =
    CGAL::Delaunay_triangulation_3<Kernel,
                                   CGAL::Triangulation_data_structure_3<VertexBase, CellBase>>;

}  // namespace

Eigen::MatrixX4i delaunay_tets(const Eigen::MatrixX3d& points) {
  if (!points.allFinite())
    throw NumericalError("Delaunay tetrahedralization: a point coordinate is not finite");
  std::vector<std::pair<Kernel::Point_3, int>> indexed;
  indexed.reserve(size_t(points.rows()));
  for (int i = 0; i < int(points.rows()); ++i)
    indexed.emplace_back(Kernel::Point_3(points(i, 0), points(i, 1), points(i, 2)), i);
  // The range insertion sorts the points along a space-filling curve first.
  const Delaunay delaunay(indexed.begin(), indexed.end());
  if (delaunay.dimension() < 3)
    throw NumericalError("Delaunay tetrahedralization: the " + std::to_string(points.rows()) +
                         " points lie in a plane");
  if (int(delaunay.number_of_vertices()) != points.rows())
    throw NumericalError("Delaunay tetrahedralization: " +
                         std::to_string(points.rows() - int(delaunay.number_of_vertices())) +
                         " points coincide with others");
  Eigen::MatrixX4i tets(Eigen::Index(delaunay.number_of_finite_cells()), 4);
  Eigen::Index row = 0;
  // CGAL orders a cell's vertices positively (its orientation predicate).
  for (auto cell = delaunay.finite_cells_begin(); cell != delaunay.finite_cells_end();
       ++cell, ++row)
    for (int k = 0; k < 4; ++k) tets(row, k) = cell->vertex(k)->info();
  return tets;
}

}  // namespace unfold
