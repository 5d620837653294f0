// Every configuration key, once: its command-line flag, its YAML path, the
// Options member it sets and its help text. The library's config reader and
// the apps' gflags definitions are both generated from this list, so a key
// cannot exist in one and not the other.
#pragma once

// X(flag, yaml path, member of unfold::Options, help)
#define UNFOLD_CONFIG_KEYS(X)                                                                      \
  X(method, "method", method,                                                                      \
    "local_global (the paper's), ceres (L-BFGS); baselines dpmu, lsmds, scf (docs/baselines.md)")  \
  X(target_vertices, "simplify.target_vertices", target_vertices,                                  \
    "simplify the surface to about this many vertices first; 0 keeps all")                         \
  X(surface_solve_hops, "simplify.surface_solve_hops", surface_solve_hops,                         \
    "domain surface: solve the surface stages on clusters of the surface's vertices this many "    \
    "edges across (1: about a quarter of the vertices, 2: a tenth) and carry the solution to the " \
    "whole surface; 0 solves on the whole surface")                                                \
  X(surface_solve_vertices, "simplify.surface_solve_vertices", surface_solve_vertices,             \
    "domain surface with surface_solve_hops 0: a surface of more vertices than this is solved on " \
    "clusters, the fewest edges across that leave at most this many (faster, and more "            \
    "pose-invariant on large scans: docs/performance.md); 0: the whole surface at any size")       \
  X(tet_route, "tetrahedralize.route", tet.route,                                                  \
    "tetrahedralization route: auto (conforming unless the surface intersects itself, else "       \
    "robust), conforming, robust")                                                                 \
  X(tet_quality, "tetrahedralize.quality", tet.quality,                                            \
    "TetGen radius-edge quality bound (-q); 0 turns quality refinement off")                       \
  X(tet_max_volume, "tetrahedralize.max_volume", tet.max_volume,                                   \
    "TetGen bound on tetrahedron volume (-a), mesh units cubed; 0: no bound")                      \
  X(fallback_surface_graph, "tetrahedralize.fallback_surface_graph", fallback_surface_graph,       \
    "when no tet mesh can be made (TetGen fails, open surface), unfold on the surface's own "      \
    "edge graph with a warning instead of failing")                                                \
  X(tet_shape, "tetrahedralize.shape", tet_shape,                                                  \
    "domain: surface: tetrahedralize the input, or the surface solve's unfolded shape and put "    \
    "its interior back into the input (unfolded: parts touching in the input stay apart); auto: "  \
    "unfolded wherever there is a surface solve and the route is not conforming, else input; "     \
    "contact: unfolded where the input's tets bridge a contact, else input")                       \
  X(unfolded_min_quality, "tetrahedralize.unfolded_min_quality", tet.unfolded_min_quality,         \
    "the unfolded shape's tets: those flatter than this (6 sqrt(2) volume / rms edge^3, 1 for a "  \
    "regular tet) put back into the input are dropped like inverted ones; 0: only inverted")       \
  X(contact_geodesic, "tetrahedralize.contact_geodesic", contact_geodesic,                         \
    "shape contact: a tet edge bridges a contact when its ends are farther apart along the "       \
    "surface than this times sqrt(area) and 4 times their distance (docs/method.md, contact)")     \
  X(components, "components", components,                                                          \
    "several connected components: refuse (error naming the count) or separately (each "           \
    "unfolded on its own, put back together in input order)")                                      \
  X(domain, "domain", domain,                                                                      \
    "volume: the energy on the tet mesh (the paper's); surface: on the surface's vertices and "    \
    "triangle edges, the interior following by ARAP (more pose-invariant, docs/method.md)")        \
  X(integrate_iterations, "integrate.iterations", integrate.iterations,                            \
    "after the cascade: ARAP steps on the whole tet mesh integrating its rotation field into a "   \
    "shape with the input's local detail (pose invariance, docs/method.md); 0: off")               \
  X(integrate_anchor, "integrate.anchor", integrate.anchor,                                        \
    "integrate.iterations: anchor of the steps after the first, in units of lambda_2 of the "      \
    "surface's graph Laplacian (modes stiffer than this get the input's detail back, softer "      \
    "ones keep the integrated pose)")                                                              \
  X(integrate_anchor_weights, "integrate.anchor_weights", integrate.anchor_weights,                \
    "integrate.iterations: how the anchor is shared: uniform (alike on every vertex) or "          \
    "stiffness (in proportion to each vertex's own ARAP stiffness: finely meshed faces and "       \
    "hands keep their own detail as coarse parts do, docs/method.md)")                             \
  X(integrate_tolerance, "integrate.tolerance", integrate.tolerance,                               \
    "integrate.iterations: stop when a step moves every vertex less than this times the radius")   \
  X(integrate_lbfgs, "integrate.lbfgs", integrate.lbfgs,                                           \
    "integrate.iterations: L-BFGS window of the anchored steps (quasi-Newton steps, one solve "    \
    "each, far fewer to converge: docs/performance.md); 0: local-global steps")                    \
  X(integrate_multigrid_vertices, "integrate.multigrid_vertices", integrate.multigrid_vertices,    \
    "integrate.lbfgs > 0: from this many tet vertices the anchored steps solve with one AMG "      \
    "V-cycle instead of a factorization (docs/performance.md, large scans)")                       \
  X(integrate_weights, "integrate.weights", integrate.weights,                                     \
    "integrate.iterations: edge weights of the steps: uniform, or inverse_length (a spring's "     \
    "stiffness: a tet mesh's long chords do not stiffen its bending, docs/method.md)")             \
  X(integrate_surface_edges, "integrate.surface_edges", integrate.surface_edges,                   \
    "integrate.iterations: the surface's edges that no tet has join the steps, weighted by this "  \
    "times their inverse length (the unfolded shape's tets leave some out, and without them "      \
    "detail tears: docs/method.md); 0: the tets' edges alone")                                     \
  X(integrate_pose_pull, "integrate.pose_pull", integrate.pose_pull,                               \
    "integrate.iterations: how far (0 to 1) the anchored steps start toward the surface "          \
    "solve's own shape, its pose alone (low-pass filtered by the steps' anchor): more "            \
    "pose-invariant, higher E_rig (docs/method.md, pose pull); 0: off")                            \
  X(soften_scale, "soften.scale", soften.scale,                                                    \
    "soft joints: solve again from the solution with each ARAP edge's weight times "               \
    "1 / (1 + (k / (scale * median k))^2), k the turn of the solution's rotation field per unit "  \
    "length along the edge (the input's joints straighten, docs/method.md); 0: off")               \
  X(soften_floor, "soften.floor", soften.floor,                                                    \
    "soften.scale: no edge's weight factor below this (in (0, 1])")                                \
  X(soften_filter, "soften.filter", soften.filter,                                                 \
    "soften.scale: the second solve's change from the first, its rotations low-pass filtered at "  \
    "this length times sqrt(area): joints straighten, faces are not squashed (docs/method.md, "    \
    "soft joints); 0: kept whole")                                                                 \
  X(soften_filter_stretch, "soften.filter_stretch", soften.filter_stretch,                         \
    "soften.scale: the same change's stretch (the rest of it) filtered at this length times "      \
    "sqrt(area); 0: kept whole")                                                                   \
  X(soften_epsilon, "soften.epsilon", soften.epsilon,                                              \
    "soften.scale: the relative energy change that ends the second solve (its fine scale is "      \
    "filtered out anyway); 0: cascade.epsilon")                                                    \
  X(untangle_sweeps, "untangle.sweeps", untangle.sweeps,                                           \
    "after the solve: passes that push the canonical tet mesh's inverted tets back out by "        \
    "moving their corners a little (mesh/untangle_tets.h, docs/method.md, detail); 0: off")        \
  X(untangle_max_move, "untangle.max_move", untangle.max_move,                                     \
    "untangle.sweeps: how far a vertex may move, times the shortest tet edge at it at rest")       \
  X(beta_mode, "beta.mode", beta_mode,                                                             \
    "relative: beta = value * n / lambda_2(L); absolute: beta = value")                            \
  X(beta, "beta.value", beta_value, "starting beta (see beta.mode)")                               \
  X(beta_raise, "beta.raise_to_bound", raise_beta_to_bound,                                        \
    "raise a starting beta below the boundedness bound n/lambda_2 - 1 to just above it")           \
  X(k_iter, "cascade.k_iter", cascade.k_iter, "iterations per cascade at most")                    \
  X(epsilon, "cascade.epsilon", cascade.epsilon,                                                   \
    "a cascade ends when the relative energy change is below this")                                \
  X(num_cascades, "cascade.num", cascade.num_cascades, "cascades at most")                         \
  X(beta_growth, "cascade.growth", cascade.growth, "beta factor from one cascade to the next")     \
  X(edge_ratio_band, "cascade.edge_ratio_band", cascade.edge_ratio_band,                           \
    "stop when the mean edge-length ratio is inside [low, high]")                                  \
  X(break_in_band, "cascade.break_in_band", cascade.break_in_band,                                 \
    "true: stop at the first iterate inside the band (the paper's Algorithm 1); false: finish "    \
    "that cascade first (local_global)")                                                           \
  X(anderson, "cascade.anderson", cascade.anderson,                                                \
    "Anderson acceleration window of the local_global iterations; 0: plain iterations")            \
  X(linear_solver, "linear_solver.method", linear_solver.method,                                   \
    "global step: direct (sparse LDL^T), iterative (AMG-preconditioned CG) or auto "               \
    "(iterative when one factorization would cost more than linear_solver.direct_max_gflop)")      \
  X(direct_max_gflop, "linear_solver.direct_max_gflop", linear_solver.direct_max_gflop,            \
    "auto: the direct solver while one factorization (AMD ordering) costs at most this many "      \
    "GFlop")                                                                                       \
  X(cg_tolerance, "linear_solver.cg_tolerance", linear_solver.cg_tolerance,                        \
    "iterative: relative residual each global step reaches")                                       \
  X(cg_forcing, "linear_solver.cg_forcing", linear_solver.cg_forcing,                              \
    "iterative: or each global step reduces its warm start's residual by this factor "             \
    "(0: always cg_tolerance)")                                                                    \
  X(cg_max_iterations, "linear_solver.cg_max_iterations", linear_solver.cg_max_iterations,         \
    "iterative: CG iterations per global step at most")                                            \
  X(stretch_weight, "stretch.weight", energy.stretch_weight,                                       \
    "weight k of the stretch term (paper: 1)")                                                     \
  X(stretch_masses, "stretch.masses", energy.stretch_masses,                                       \
    "stretch term's vertex weights: uniform (paper) or lumped (each vertex's share of the "        \
    "volume or, with domain: surface, of the area: independent of where the mesh is dense)")       \
  X(stretch_mass_power, "stretch.mass_power", energy.stretch_mass_power,                           \
    "stretch.masses lumped: the shares to this power, in [0, 1] (below 1 densely meshed parts "    \
    "weigh more: humans' arms out, lower E_geo, less meshing-independent; docs/method.md)")        \
  X(stretch_local, "stretch.local", energy.stretch_local,                                          \
    "share in [0, 1) of the spread taken within soft geodesic regions instead of about the "       \
    "centroid: limbs splay instead of lining up, lower E_rig and E_geo (docs/method.md); 0: off")  \
  X(stretch_local_radius, "stretch.local_radius", energy.stretch_local_radius,                     \
    "stretch.local: the regions' Gaussian width, times the geodesic diameter")                     \
  X(stretch_local_regions, "stretch.local_regions", energy.stretch_local_regions,                  \
    "stretch.local: how many regions (farthest-point landmarks)")                                  \
  X(stretch_distance, "stretch.distance", energy.stretch_distance,                                 \
    "weight >= 0 of a spread by distances between clusters (-sum M_a M_b |c_a - c_b|), relative "  \
    "to the paper's squared spread's pull at the rest shape's radius: near parts push apart as "   \
    "much as far ones, limbs splay (docs/method.md, spread by distances); 0: off")                 \
  X(stretch_distance_clusters, "stretch.distance_clusters", energy.stretch_distance_clusters,      \
    "stretch.distance: how many clusters (graph-Voronoi cells of farthest-point seeds)")           \
  X(arap_weight, "arap.weight", energy.arap_weight, "ARAP weight relative to beta (paper: 1)")     \
  X(arap_weights, "arap.weights", energy.arap_weights,                                             \
    "ARAP edge weights w_ij: uniform (paper) or cotangent")                                        \
  X(user_pairs, "user_pairs.file", energy.user_pairs_file,                                         \
    "pair constraints (Eq. 11), CSV or YAML rows i, j, tx, ty, tz; empty: none")                   \
  X(user_pairs_gamma, "user_pairs.gamma", energy.user_pairs_gamma,                                 \
    "weight gamma of the pair constraints relative to beta (paper: 1)")                            \
  X(volume_weight, "volume.weight", energy.volume_weight,                                          \
    "tet volume preservation relative to beta; 0 = off; needs method: ceres")                      \
  X(edge_length_weight, "edge_length.weight", energy.edge_length_weight,                           \
    "edge-length springs relative to beta (DPMU); 0 = off; needs method: ceres or dpmu")           \
  X(lsmds_exact_limit, "lsmds.exact_limit", lsmds.exact_limit,                                     \
    "method lsmds: all-pairs stress up to this many tet vertices, landmarks above")                \
  X(lsmds_landmarks, "lsmds.landmarks", lsmds.landmarks,                                           \
    "method lsmds: landmark geodesic rows above the exact limit")                                  \
  X(lsmds_max_iterations, "lsmds.max_iterations", lsmds.max_iterations,                            \
    "method lsmds: Guttman transforms at most")                                                    \
  X(lsmds_tolerance, "lsmds.tolerance", lsmds.tolerance,                                           \
    "method lsmds: stop when the relative stress decrease is below this")                          \
  X(scf_quality_speed_tradeoff, "scf.quality_speed_tradeoff", scf.skeleton.quality_speed_tradeoff, \
    "method scf: CGAL skeleton w_H (larger: finer and slower)")                                    \
  X(scf_medially_centered_speed_tradeoff, "scf.medially_centered_speed_tradeoff",                  \
    scf.skeleton.medially_centered_speed_tradeoff,                                                 \
    "method scf: CGAL skeleton w_M (larger: better centred)")                                      \
  X(scf_max_iterations, "scf.max_iterations", scf.skeleton.max_iterations,                         \
    "method scf: skeleton contraction steps at most")                                              \
  X(scf_min_edge_length, "scf.min_edge_length", scf.skeleton.min_edge_length,                      \
    "method scf: skeleton edges shorter than this times the diameter collapse")                    \
  X(scf_mds_iterations, "scf.mds_iterations", scf.mds_iterations,                                  \
    "method scf: Guttman transforms on the skeleton at most")                                      \
  X(scf_blend_radius, "scf.blend_radius", scf.blend_radius,                                        \
    "method scf: skinning blend radius along the skeleton, times the diameter")                    \
  X(scf_arap_anchor, "scf.arap_anchor", scf.arap_anchor,                                           \
    "method scf: ARAP refinement's pull to the skinned positions")                                 \
  X(scf_arap_iterations, "scf.arap_iterations", scf.arap_iterations,                               \
    "method scf: ARAP refinement steps at most; 0: skinning alone")                                \
  X(ceres_line_search_direction_type, "ceres.line_search_direction_type",                          \
    ceres.line_search_direction_type,                                                              \
    "LBFGS, BFGS, NONLINEAR_CONJUGATE_GRADIENT or STEEPEST_DESCENT")                               \
  X(ceres_max_num_iterations, "ceres.max_num_iterations", ceres.max_num_iterations,                \
    "Ceres iterations per cascade at most")                                                        \
  X(ceres_function_tolerance, "ceres.function_tolerance", ceres.function_tolerance,                \
    "Ceres stops when the relative cost change is below this")                                     \
  X(ceres_gradient_tolerance, "ceres.gradient_tolerance", ceres.gradient_tolerance,                \
    "Ceres stops when the max gradient norm is below this")                                        \
  X(ceres_parameter_tolerance, "ceres.parameter_tolerance", ceres.parameter_tolerance,             \
    "Ceres stops when the relative step is below this")                                            \
  X(ceres_max_lbfgs_rank, "ceres.max_lbfgs_rank", ceres.max_lbfgs_rank,                            \
    "L-BFGS memory (Ceres max_lbfgs_rank)")                                                        \
  X(metrics, "metrics.compute", metrics,                                                           \
    "metrics to compute: a list of E_rig, E_str, E_geo (E_geo costs the most), all or none; "      \
    "one not computed is null in the metrics JSON and empty in results.csv")                       \
  X(stretch_exact_limit, "metrics.stretch_exact_limit", stretch_metric.exact_limit,                \
    "E_str over all pairs up to this many vertices, sampled above")                                \
  X(stretch_samples, "metrics.stretch_samples", stretch_metric.sample_pairs,                       \
    "random pairs for E_str above the exact limit")                                                \
  X(geodesic_exact_limit, "metrics.geodesic_exact_limit", geodesic_metric.exact_limit,             \
    "E_geo from all-pairs geodesics up to this many vertices")                                     \
  X(geodesic_landmarks, "metrics.geodesic_landmarks", geodesic_metric.sources,                     \
    "geodesic source vertices for E_geo above the exact limit")                                    \
  X(geodesic_max_vertices, "metrics.geodesic_max_vertices", geodesic_max_vertices,                 \
    "E_geo left out above this many tet vertices (0: no limit; unfold: 20000 unless --metrics "    \
    "is given)")                                                                                   \
  X(match_mirror, "match.mirror", match.mirror,                                                    \
    "unfold_match: auto: the mirror image of the rigid map only when it fits clearly better "      \
    "(match.mirror_margin), else the rotation's; off: whichever fits best")                        \
  X(match_mirror_margin, "match.mirror_margin", match.mirror_margin,                               \
    "unfold_match: the mirror image wins below (1 - margin) times the rotation's ICP residual; "   \
    "within the margin the decision is reported as ambiguous")                                     \
  X(match_placement, "match.placement", match.placement,                                           \
    "unfold_match: descriptor: among the best rotation and its half turns, the placement whose "   \
    "refined map best keeps the surfaces' curvature (front told from back); residual: the best "   \
    "fit")                                                                                         \
  X(match_sure_margin, "match.sure_margin", match.sure_margin,                                     \
    "unfold_match: a placement whose runner-up disagrees less than this many times as much is "    \
    "reported unsure")                                                                             \
  X(match_synchronize, "match.synchronize", match.synchronize,                                     \
    "unfold_match --pairs: an unsure pair's rotation that disagrees with the one its cycles "      \
    "through sure pairs imply is replaced by it")                                                  \
  X(match_refine, "match.refine", match.refine,                                                    \
    "unfold_match: zoomout (ZoomOut on the input surfaces' Laplace-Beltrami bases) or none")       \
  X(match_spectral_size, "match.spectral_size", match.spectral_size,                               \
    "unfold_match: eigenfunctions per shape, ZoomOut's final basis size")                          \
  X(threads, "threads", threads, "worker threads; 0 uses every core")
