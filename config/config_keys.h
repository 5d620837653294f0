// Every configuration key, once: its command-line flag, its YAML path, the
// Options member it sets and its help text. The library's config reader and
// the apps' gflags definitions are both generated from this list, so a key
// cannot exist in one and not the other.
#pragma once

// X(flag, yaml path, member of unfold::Options, help)
#define UNFOLD_CONFIG_KEYS(X)                                                                  \
  X(method, "method", method, "solver: local_global")                                          \
  X(target_vertices, "simplify.target_vertices", target_vertices,                              \
    "simplify the surface to about this many vertices first; 0 keeps all")                     \
  X(tet_route, "tetrahedralize.route", tet.route, "tetrahedralization route: conforming")      \
  X(tet_quality, "tetrahedralize.quality", tet.quality,                                        \
    "TetGen radius-edge quality bound (-q); 0 turns quality refinement off")                   \
  X(fallback_surface_graph, "tetrahedralize.fallback_surface_graph", fallback_surface_graph,   \
    "when no tet mesh can be made (TetGen fails, open surface), unfold on the surface's own "  \
    "edge graph with a warning instead of failing")                                            \
  X(components, "components", components,                                                      \
    "several connected components: refuse (error naming the count) or separately (each "       \
    "unfolded on its own, put back together in input order)")                                  \
  X(beta_mode, "beta.mode", beta_mode,                                                         \
    "relative: beta = value * n / lambda_2(L); absolute: beta = value")                        \
  X(beta, "beta.value", beta_value, "starting beta (see beta.mode)")                           \
  X(beta_raise, "beta.raise_to_bound", raise_beta_to_bound,                                    \
    "raise a starting beta below the boundedness bound n/lambda_2 - 1 to just above it")       \
  X(k_iter, "cascade.k_iter", cascade.k_iter, "iterations per cascade at most")                \
  X(epsilon, "cascade.epsilon", cascade.epsilon,                                               \
    "a cascade ends when the relative energy change is below this")                            \
  X(num_cascades, "cascade.num", cascade.num_cascades, "cascades at most")                     \
  X(beta_growth, "cascade.growth", cascade.growth, "beta factor from one cascade to the next") \
  X(edge_ratio_band, "cascade.edge_ratio_band", cascade.edge_ratio_band,                       \
    "stop when the mean edge-length ratio is inside [low, high]")                              \
  X(stretch_exact_limit, "metrics.stretch_exact_limit", stretch_metric.exact_limit,            \
    "E_str over all pairs up to this many vertices, sampled above")                            \
  X(stretch_samples, "metrics.stretch_samples", stretch_metric.sample_pairs,                   \
    "random pairs for E_str above the exact limit")                                            \
  X(geodesic_exact_limit, "metrics.geodesic_exact_limit", geodesic_metric.exact_limit,         \
    "E_geo from all-pairs geodesics up to this many vertices")                                 \
  X(geodesic_landmarks, "metrics.geodesic_landmarks", geodesic_metric.sources,                 \
    "geodesic source vertices for E_geo above the exact limit")                                \
  X(threads, "threads", threads, "worker threads; 0 uses every core")
