"""Checks and converts user arrays to the layouts the extension takes.

Any array-like is accepted (lists, float32, non-contiguous views, int64
faces); wrong shapes and types are refused here with a message that names
the argument, instead of pybind11's generic "incompatible arguments".
"""

from __future__ import annotations

import numpy as np
import numpy.typing as npt

from ._core import InputError

_INT32_LIMIT = 2**31


def vertices(array: npt.ArrayLike, name: str = "V") -> np.ndarray:
    """``array`` as a C-contiguous float64 (n, 3) array."""
    a = np.asarray(array)
    if a.ndim != 2 or a.shape[1] != 3:
        raise InputError(f"{name} must be an (n, 3) array of positions, got shape {a.shape}")
    if not (np.issubdtype(a.dtype, np.floating) or np.issubdtype(a.dtype, np.integer)):
        raise InputError(f"{name} must hold real numbers, got dtype {a.dtype}")
    return np.ascontiguousarray(a, dtype=np.float64)


def elements(array: npt.ArrayLike, num_vertices: int, corners: int | None = 3,
             name: str = "F") -> np.ndarray:
    """``array`` as a C-contiguous int32 (m, corners) array of indices below
    num_vertices (any corners >= 2 if corners is None)."""
    a = np.asarray(array)
    if a.ndim != 2 or (corners is not None and a.shape[1] != corners) or a.shape[1] < 2:
        want = f"(m, {corners})" if corners is not None else "(m, k)"
        raise InputError(f"{name} must be an {want} array of vertex indices, got shape {a.shape}")
    if not np.issubdtype(a.dtype, np.integer):
        raise InputError(f"{name} must hold integers (vertex indices), got dtype {a.dtype}")
    if a.size and (a.min() < 0 or a.max() >= num_vertices or a.max() >= _INT32_LIMIT):
        bad = a.min() if a.min() < 0 else a.max()
        raise InputError(f"{name} refers to vertex {bad}, but there are {num_vertices} vertices")
    return np.ascontiguousarray(a, dtype=np.int32)


def indices(array: npt.ArrayLike, num_vertices: int, name: str) -> np.ndarray:
    """``array`` as a C-contiguous int32 (k,) array of vertex indices below num_vertices."""
    a = np.asarray(array)
    if a.ndim != 1 or not np.issubdtype(a.dtype, np.integer):
        raise InputError(f"{name} must be a 1-D integer array of vertex indices, "
                         f"got shape {a.shape} and dtype {a.dtype}")
    if a.size and (a.min() < 0 or a.max() >= num_vertices):
        bad = a.min() if a.min() < 0 else a.max()
        raise InputError(f"{name} refers to vertex {bad}, but there are {num_vertices} vertices")
    return np.ascontiguousarray(a, dtype=np.int32)


def surface(V: npt.ArrayLike, F: npt.ArrayLike) -> tuple[np.ndarray, np.ndarray]:
    """Vertices and triangles: vertices(V) and elements(F, len(V))."""
    V = vertices(V)
    return V, elements(F, len(V))
