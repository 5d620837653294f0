#include <tetgen.h>

#include <sstream>
#include <vector>

#include "core/errors.h"
#include "tetra/tetrahedralize.h"

namespace unfold {
namespace {

std::string tetgen_error_name(int code) {
  switch (code) {
    case 1:
      return "out of memory";
    case 2:
      return "internal error";
    case 3:
      return "the surface intersects itself";
    case 4:
      return "a feature is too small for the tolerance";
    case 5:
      return "two facets are too close to each other";
    case 10:
      return "duplicated input points";
    default:
      return "error code " + std::to_string(code);
  }
}

}  // namespace

TetMesh tetrahedralize_conforming(const SurfaceMesh& surface, double quality) {
  const int n = int(surface.V.rows());
  tetgenio in, out;
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
  std::string s = switches.str();
  tetgenbehavior behavior;
  if (!behavior.parse_commandline(s.data())) throw UsageError("bad TetGen switches '" + s + "'");
  try {
    ::tetrahedralize(&behavior, &in, &out);
  } catch (int code) {
    throw NumericalError("TetGen (conforming route) failed: " + tetgen_error_name(code));
  }

  if (out.numberofpoints < n || out.numberoftetrahedra == 0)
    throw NumericalError("TetGen (conforming route) produced no usable tetrahedra");
  TetMesh tets;
  tets.num_surface_vertices = n;
  tets.V.resize(out.numberofpoints, 3);
  for (int i = 0; i < out.numberofpoints; ++i)
    for (int k = 0; k < 3; ++k) tets.V(i, k) = out.pointlist[3 * i + k];
  // TetGen keeps input points first and in order; a merged duplicate would break that.
  if ((tets.V.topRows(n) - surface.V).cwiseAbs().maxCoeff() != 0.0)
    throw NumericalError("TetGen (conforming route) moved or reordered surface vertices");
  tets.T.resize(out.numberoftetrahedra, 4);
  std::vector<char> used(size_t(out.numberofpoints), 0);
  for (int t = 0; t < out.numberoftetrahedra; ++t)
    for (int k = 0; k < 4; ++k) {
      tets.T(t, k) = out.tetrahedronlist[4 * t + k];
      used[size_t(tets.T(t, k))] = 1;
    }
  for (int i = 0; i < n; ++i)
    if (!used[size_t(i)])
      throw NumericalError("TetGen (conforming route) left surface vertex " + std::to_string(i) +
                           " out of every tetrahedron");
  return tets;
}

}  // namespace unfold
