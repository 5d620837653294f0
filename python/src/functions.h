// The groups of functions of the _core extension module, one file each.
#pragma once

#include <pybind11/pybind11.h>

namespace unfold::python {

/// read_mesh, write_mesh, read_vts, demo_shape.
void def_mesh_functions(pybind11::module_& m);
/// config_keys, unfold, compare, fixed_beta_overrides.
void def_unfold_functions(pybind11::module_& m);
/// e_rig, e_str, e_geo, surface_damage, surface_area, pose_distance(_on_rows),
/// retrieval_distance.
void def_metric_functions(pybind11::module_& m);
/// correspond.
void def_match_functions(pybind11::module_& m);

}  // namespace unfold::python
