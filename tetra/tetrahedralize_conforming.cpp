#include <sstream>
#include <vector>

#include "core/errors.h"
#include "tetra/run_tetgen.h"
#include "tetra/tetrahedralize.h"

namespace unfold {

TetMesh tetrahedralize_conforming(const SurfaceMesh& surface, double quality, double max_volume,
                                  const std::function<bool()>& give_up) {
  const int n = int(surface.V.rows());
  tetgenio in;
  in.firstnumber = 0;
  in.numberofpoints = n;
  in.pointlist = new REAL[size_t(n) * 3];
  for (int i = 0; i < n; ++i)
    for (int k = 0; k < 3; ++k) in.pointlist[3 * i + k] = surface.V(i, k);
  in.numberoffacets = int(surface.faces.size());
  in.facetlist = new tetgenio::facet[surface.faces.size()];
  for (size_t f = 0; f < surface.faces.size(); ++f) {
    tetgenio::facet& facet = in.facetlist[f];
    tetgenio::init(&facet);
    facet.numberofpolygons = 1;
    facet.polygonlist = new tetgenio::polygon[1];
    tetgenio::init(&facet.polygonlist[0]);
    facet.polygonlist[0].numberofvertices = int(surface.faces[f].size());
    facet.polygonlist[0].vertexlist = new int[surface.faces[f].size()];
    for (size_t k = 0; k < surface.faces[f].size(); ++k)
      facet.polygonlist[0].vertexlist[k] = surface.faces[f][k];
  }

  // p: PLC, Y: no Steiner points on the surface, z: 0-based, Q: quiet.
  std::ostringstream switches;
  switches << "pYzQ";
  if (quality > 0) switches << "q" << quality;
  if (max_volume > 0) switches << "a" << max_volume;
  TetgenOutput out =
      run_tetgen(switches.str(), in, "tetrahedralization (conforming route)", give_up);
  if (out.points.rows() < n || out.tets.rows() == 0)
    throw NumericalError("TetGen (conforming route) produced no usable tetrahedra");
  TetMesh tets;
  tets.num_surface_vertices = n;
  tets.V = std::move(out.points);
  // TetGen keeps input points first and in order; a merged duplicate would break that.
  if ((tets.V.topRows(n) - surface.V).cwiseAbs().maxCoeff() != 0.0)
    throw NumericalError("TetGen (conforming route) moved or reordered surface vertices");
  tets.T = std::move(out.tets);
  std::vector<char> used(size_t(tets.V.rows()), 0);
  for (Eigen::Index t = 0; t < tets.T.rows(); ++t)
    for (int k = 0; k < 4; ++k) used[size_t(tets.T(t, k))] = 1;
  for (int i = 0; i < n; ++i)
    if (!used[size_t(i)])
      throw NumericalError("TetGen (conforming route) left surface vertex " + std::to_string(i) +
                           " out of every tetrahedron");
  return tets;
}

}  // namespace unfold
