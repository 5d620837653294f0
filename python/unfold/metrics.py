"""The quality metrics of the paper and of the evaluation, on numpy arrays.

The same functions that fill Result.metrics and the batch reports:
E_rig (Eq. 8), E_str (Eq. 9), E_geo (Eq. 10), the surface damage measure
(edge length ratios at the input's area: their tail), pose distance (two canonical
forms of one shape), retrieval distances (two shapes' canonical forms: ICP and
ORT; CMBOF over a set of shapes) and the retrieval measures of a dissimilarity matrix (NN, FT, ST, E, DCG,
precision-recall), as retrieval.csv reports them.
"""

# The imports are private (underscored): dir(unfold.metrics) lists the functions alone, __all__.
from __future__ import annotations as _annotations

from collections.abc import Sequence as _Sequence
from typing import Any as _Any

import numpy as _np
import numpy.typing as _npt

from . import _arrays, _core

__all__ = ["e_rig", "e_str", "e_geo", "surface_damage", "surface_folds", "surface_area",
           "pose_distance", "retrieval_distance", "ort_distance", "cmbof_matrix",
           "retrieval_measures"]


def _set(**options: _Any) -> dict[str, _Any]:
    return {name: value for name, value in options.items() if value is not None}


def e_rig(rest: _npt.ArrayLike, deformed: _npt.ArrayLike, elements: _npt.ArrayLike) -> float:
    """E_rig: mean over vertices of how far each cell's motion is from a rotation.

    rest, deformed: (n, 3) positions; elements: (m, k) vertex indices (tets or
    triangles) whose edges are the cells. 0 for any rigid motion.
    """
    P = _arrays.vertices(rest, "rest")
    return _core.e_rig(P, _arrays.vertices(deformed, "deformed"),
                       _arrays.elements(elements, len(P), None, "elements"))


def e_str(rest: _npt.ArrayLike, deformed: _npt.ArrayLike, exact_limit: int | None = None,
          samples: int | None = None) -> float:
    """E_str: mean relative change of pairwise distances (s - 1 for a scale by s).

    Exact up to exact_limit vertices, else estimated from `samples` random
    pairs (None: the defaults of metrics.stretch_exact_limit and
    metrics.stretch_samples).
    """
    return _core.e_str(_arrays.vertices(rest, "rest"), _arrays.vertices(deformed, "deformed"),
                       **_set(exact_limit=exact_limit, samples=samples))


def e_geo(rest: _npt.ArrayLike, deformed: _npt.ArrayLike, elements: _npt.ArrayLike,
          exact_limit: int | None = None, landmarks: int | None = None) -> float:
    """E_geo: deformed Euclidean distances against rest geodesics along the elements' edges.

    Exact up to exact_limit vertices, else from `landmarks` source vertices
    (None: the defaults of metrics.geodesic_exact_limit and
    metrics.geodesic_landmarks).
    """
    P = _arrays.vertices(rest, "rest")
    return _core.e_geo(P, _arrays.vertices(deformed, "deformed"),
                       _arrays.elements(elements, len(P), None, "elements"),
                       **_set(exact_limit=exact_limit, landmarks=landmarks))


def surface_damage(rest: _npt.ArrayLike, deformed: _npt.ArrayLike, F: _npt.ArrayLike,
                   bound: float | None = None) -> dict[str, _Any]:
    """Damage of a deformed surface (e.g. a canonical form) against its rest shape.

    rest, deformed: (n, 3) positions of one surface; F: (m, k) faces, k >= 3
    (polygons: their sides are the edges). Over the unique edges of nonzero
    rest length, r = s |deformed edge| / |rest edge| with s =
    sqrt(area(rest) / area(deformed)), so r = 1 for every edge of a rotated,
    scaled and moved copy. Returns a dict with the metrics JSON's keys:
    damaged_edges_percent (edges with r outside [1/bound, bound], bound 3 by
    default, in percent), surface_edge_ratio_p999 (nearest rank: the k-th
    smallest r, k = ceil(0.999 m)), surface_edge_ratio_max (most stretched),
    surface_edge_ratio_min (most crushed), damaged_surface_edges,
    surface_edges_measured, zero_length_surface_edges (skipped); and scale (s)
    and per_vertex ((n,) the largest |ln r| of each vertex's edges). A run's
    metrics hold the same figures for its surface and canonical form.
    Raises InputError for bad arrays, ConfigError for bound <= 1,
    NumericalError for a non-finite or zero-area deformed surface.
    """
    P = _arrays.vertices(rest, "rest")
    Q = _arrays.vertices(deformed, "deformed")
    if len(Q) != len(P):
        raise _core.InputError(f"deformed has {len(Q)} vertices, rest {len(P)}")
    result = _core.surface_damage(P, Q, _arrays.elements(F, len(P), None, "F"),
                                  **_set(bound=bound))
    result["per_vertex"] = _np.asarray(result["per_vertex"])
    return result


def surface_folds(rest: _npt.ArrayLike, deformed: _npt.ArrayLike, F: _npt.ArrayLike,
                  bound_degrees: float | None = None) -> dict[str, _Any]:
    """Folds of a deformed surface (e.g. a canonical form) against its rest shape.

    rest, deformed: (n, 3) positions of one surface; F: (m, k) faces, k >= 3
    (fan-triangulated). At each edge between two triangles of nonzero area in
    both positions, how much sharper it bends deformed than at rest,
    max(0, |theta_deformed| - |theta_rest|) with theta the signed dihedral
    angle (0: flat), in [0, 180) degrees: 0 for every edge of a rotated, scaled
    and moved copy and where a rest crease opens, large where the surface
    turned over, even with every length kept (which surface_damage cannot
    see). An edge is folded when its bend sharpens by more than bound_degrees
    (90 by default). Returns a dict with the
    metrics JSON's keys: folded_edges_percent, folded_surface_edges,
    dihedral_change_p999_degrees (nearest rank), dihedral_change_max_degrees,
    surface_edges_measured; and per_vertex ((n,) the largest sharpening of each
    vertex's measured edges, degrees). A run's metrics hold the same figures
    for its surface and canonical form.
    Raises InputError for bad arrays, ConfigError for a bound outside (0, 180).
    """
    P = _arrays.vertices(rest, "rest")
    Q = _arrays.vertices(deformed, "deformed")
    if len(Q) != len(P):
        raise _core.InputError(f"deformed has {len(Q)} vertices, rest {len(P)}")
    bound = None if bound_degrees is None else float(bound_degrees) * _np.pi / 180
    result = _core.surface_folds(P, Q, _arrays.elements(F, len(P), None, "F"),
                                 **_set(bound=bound))
    result["per_vertex"] = _np.asarray(result["per_vertex"])
    return result


def surface_area(V: _npt.ArrayLike, F: _npt.ArrayLike) -> float:
    """Total area of the triangles F of V."""
    return _core.surface_area(*_arrays.surface(V, F))


def pose_distance(A: _npt.ArrayLike, B: _npt.ArrayLike, F: _npt.ArrayLike,
                  F_B: _npt.ArrayLike | None = None, rows_a: _npt.ArrayLike | None = None,
                  rows_b: _npt.ArrayLike | None = None) -> float:
    """Mean distance of corresponding points of A and B, each scaled to its own
    unit surface area, after the best rigid alignment: zero for forms that
    differ by a rigid motion and a scale.

    Without rows: A and B are one surface in two poses (corresponding rows,
    triangles F). For two meshings of a shape (e.g. independently remeshed
    scans), F is A's triangles, F_B B's, and rows_a[k], rows_b[k] are the
    zero-based vertices of A and B that are the same point (unfold.read_vts).
    """
    A, F = _arrays.surface(A, F)
    B = _arrays.vertices(B, "B")
    if rows_a is None and rows_b is None and F_B is None:
        return _core.pose_distance(A, B, F)
    if rows_a is None or rows_b is None:
        raise _core.InputError("pose_distance: give both rows_a and rows_b, or neither")
    F_B = F if F_B is None else F_B
    return _core.pose_distance_on_rows(A, F, _arrays.indices(rows_a, len(A), "rows_a"), B,
                                       _arrays.elements(F_B, len(B), 3, "F_B"),
                                       _arrays.indices(rows_b, len(B), "rows_b"))


def retrieval_distance(A: _npt.ArrayLike, B: _npt.ArrayLike, sample_points: int | None = None,
                       icp_iterations: int | None = None) -> float:
    """Dissimilarity of two shapes (rows need not correspond), as in the retrieval
    tables: normalised samples, best principal-axis flip, ICP, mean nearest-point distance."""
    return _core.retrieval_distance(_arrays.vertices(A, "A"), _arrays.vertices(B, "B"),
                                    **_set(sample_points=sample_points,
                                           icp_iterations=icp_iterations))


def ort_distance(A: _npt.ArrayLike, FA: _npt.ArrayLike, B: _npt.ArrayLike, FB: _npt.ArrayLike,
                 sample_points: int | None = None, icp_iterations: int | None = None) -> float:
    """ORT dissimilarity of two surfaces (rows need not correspond), as in the
    retrieval tables: each centred, scaled to unit area and oriented by PCA or
    rectilinearity; then the mean squared nearest-vertex error after the best
    cube rotation and ICP."""
    A, FA = _arrays.surface(A, FA)
    B, FB = _arrays.surface(B, FB)
    return _core.ort_distance(A, FA, B, FB, **_set(sample_points=sample_points,
                                                    icp_iterations=icp_iterations))


def cmbof_matrix(shapes: _Sequence[tuple[_npt.ArrayLike, _npt.ArrayLike]],
                 view_subdivisions: int | None = None, image_size: int | None = None,
                 words: int | None = None) -> _np.ndarray:
    """CM-BOF dissimilarity matrix (n, n) of surfaces (V, F), as in the
    retrieval tables (Lian et al. 2013): each normalised like ORT and seen as
    depth images from the view sphere (66 views), SIFT features quantised over
    a vocabulary learned by k-means on this set, views compared by histogram
    intersection, minimised over the 24 rotations of the view sphere."""
    surfaces = [_arrays.surface(V, F) for V, F in shapes]
    return _core.cmbof_matrix(surfaces, **_set(view_subdivisions=view_subdivisions,
                                               image_size=image_size, words=words))


def retrieval_measures(D: _npt.ArrayLike, classes: list[str]) -> dict[str, _Any]:
    """The retrieval measures of a dissimilarity matrix D (n, n; smaller = more
    similar) with a class per shape, each query leaving itself out: nn,
    first_tier, second_tier, e_measure (first 32), dcg (normalised), queries,
    and the interpolated precision at recall 0.05, ..., 1 ("recall",
    "precision"); docs/evaluation.md gives the formulas."""
    matrix = _np.asarray(D, dtype=_np.float64)
    if matrix.ndim != 2 or matrix.shape[0] != matrix.shape[1]:
        raise _core.InputError(f"D must be a square matrix, got shape {matrix.shape}")
    return _core.retrieval_measures(_np.ascontiguousarray(matrix), [str(c) for c in classes])
