// Several connected components unfolded one by one and put back into one
// result (options.components == "separately").
#pragma once

#include "config/options.h"
#include "mesh/surface_mesh.h"
#include "pipeline/unfold_surface.h"

namespace unfold {

/// Unfolds each connected component of `surface` on its own (unfold_surface)
/// and merges the results. Without simplification the merged surface is the
/// input (vertices and faces in input order); with it, the simplified
/// components follow one another in the order of their lowest input vertex.
/// The tet mesh keeps all surface vertices first; every per-vertex field
/// (positions, metrics.rigidity_per_vertex) is the parts' fields put in those
/// places. Combined figures: E_rig the mean of the merged per-vertex terms,
/// the edge ratio an edge-weighted mean, E_str and E_geo means weighted by tet
/// vertices (pairs across components are not compared), the damage measure
/// (metrics.damage) computed anew on the merged surface, lambda2 and
/// beta_start the smallest of the parts, iterations, inverted tets and times
/// sums; each part's warnings are listed with its component number.
/// @param surface a surface that passes check_surface_mesh(surface, false)
/// @param options validated options
/// @throws what unfold_surface throws for any component, naming the component
UnfoldResult unfold_components_separately(const SurfaceMesh& surface, const Options& options);

}  // namespace unfold
