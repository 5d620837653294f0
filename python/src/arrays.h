// The numpy layouts the binding exchanges: row-major (n, 3) float64 vertices
// and (m, k) int32 element indices. The Python side (unfold/_arrays.py) checks
// and converts user arrays to these before they get here.
#pragma once

#include <pybind11/eigen.h>

#include <Eigen/Core>
#include <utility>

#include "mesh/surface_mesh.h"

namespace unfold::python {

using Vertices = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;
using Elements = Eigen::Matrix<int, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

/// A surface from vertices and faces (one face per row).
SurfaceMesh make_surface(const Vertices& V, const Elements& F);

/// The vertices and the fan-triangulated faces of mesh.
std::pair<Vertices, Elements> to_arrays(const SurfaceMesh& mesh);

}  // namespace unfold::python
