"""unfold: a non-rigid 3D shape (numpy arrays) into its canonical pose.

    import unfold
    V, F = unfold.read_mesh("shape.off")          # or unfold.demo_shape()
    r = unfold.unfold(V, F, cascade={"k_iter": 20})
    unfold.write_mesh("canonical.off", r.vertices, r.faces)
    print(r.metrics["E_rig"])

The same library as the command-line tool `unfold`: same config keys, same
results, same metrics. Errors raise unfold.Error subclasses (ConfigError,
InputError, NumericalError, OutputError) with the command line's one-line
message. Progress goes to the logging module's "unfold" logger (silent unless
logging is configured): each stage's lines at INFO (e.g.
logging.basicConfig(level=logging.INFO)), each iteration's too at DEBUG.
"""

# The imports are private (underscored): dir(unfold) lists the API alone, __all__.
from __future__ import annotations as _annotations

import logging as _logging
import os as _os
from collections.abc import Sequence as _Sequence
from dataclasses import dataclass as _dataclass
from dataclasses import field as _field
from typing import Any as _Any
from typing import Union as _Union

import numpy as _np
import numpy.typing as _npt

from . import _arrays, _config, _core, metrics
from ._core import ConfigError, Error, InputError, NumericalError, OutputError

__all__ = ["Error", "ConfigError", "InputError", "NumericalError", "OutputError", "Result",
           "read_mesh", "write_mesh", "read_vts", "demo_shape", "unfold", "compare", "config_keys",
           "metrics", "correspond"]

_logging.getLogger("unfold").addHandler(_logging.NullHandler())

# os.PathLike bare: Python 3.8 cannot subscript it, and a string annotation
# inside the alias would be looked up in whichever module uses it.
_PathLike = _Union[str, _os.PathLike]


@_dataclass(frozen=True)
class Result:
    """One unfolding; arrays are numpy.

    vertices: (n, 3) canonical positions of the surface's vertices, in input
        order (of the simplified surface with simplify.target_vertices).
    faces: (m, 3) int32 faces (the input's, triangulated).
    metrics: the command line's metrics JSON (--metrics_json) as a dict: same
        keys, same values.
    tet_vertices: (N, 3) canonical positions of every tet vertex; the first n
        are the surface's vertices.
    tets: (T, 4) int32 tetrahedra.
    rest_tet_vertices: (N, 3) rest positions of every tet vertex.
    unfolded_tet_vertices: (N, 3) where the tets were made when that is not
        the rest (the unfolded shape's tets, the default), else (0, 3): given
        back with tets and rest_tet_vertices, they unfold as they did.
    tet_vertex_fields, tet_fields: per tet vertex (rigidity_error,
        stretch_ratio, edge_damage) and per tet (volume_ratio, rigidity), as written to
        --tet_output x.vtu.
    skeleton_nodes, skeleton_edges, canonical_skeleton_nodes: method="scf"
        only (else empty): the input's curve skeleton, (k, 3) nodes and (b, 2)
        int32 bones, and its straightened nodes placed like vertices (as
        --skeleton_output and --canonical_skeleton_output).
    """

    vertices: _np.ndarray
    faces: _np.ndarray
    metrics: dict[str, _Any]
    tet_vertices: _np.ndarray
    tets: _np.ndarray
    rest_tet_vertices: _np.ndarray
    unfolded_tet_vertices: _np.ndarray = _field(repr=False)
    tet_vertex_fields: dict[str, _np.ndarray] = _field(repr=False)
    tet_fields: dict[str, _np.ndarray] = _field(repr=False)
    skeleton_nodes: _np.ndarray = _field(repr=False)
    skeleton_edges: _np.ndarray = _field(repr=False)
    canonical_skeleton_nodes: _np.ndarray = _field(repr=False)

    @property
    def rigidity_error(self) -> _np.ndarray:
        """(n,) E_rig's term of each surface vertex."""
        return self.tet_vertex_fields["rigidity_error"][: len(self.vertices)]

    @property
    def stretch_ratio(self) -> _np.ndarray:
        """(n,) mean canonical/rest length ratio of each surface vertex's edges."""
        return self.tet_vertex_fields["stretch_ratio"][: len(self.vertices)]

    @property
    def edge_damage(self) -> _np.ndarray:
        """(n,) the largest |ln r| of each surface vertex's surface edges, r the
        edge's canonical/rest length ratio at the rest area (the damage measure:
        metrics["damaged_edges_percent"] etc.; past ln 3 = 1.0986 an edge is damaged)."""
        return self.tet_vertex_fields["edge_damage"][: len(self.vertices)]


def read_mesh(path: _PathLike) -> tuple[_np.ndarray, _np.ndarray]:
    """Reads a surface mesh (.off .obj .ply .stl, as the command line).

    Returns (V, F): float64 (n, 3) positions and int32 (m, 3) faces (polygons
    fan-triangulated). Raises InputError naming the file and the problem.
    """
    return _core.read_mesh(_os.fspath(path))


def write_mesh(path: _PathLike, V: _npt.ArrayLike, F: _npt.ArrayLike) -> None:
    """Writes a surface mesh (.off .obj .ply .stl, as the command line), atomically.

    V: (n, 3) numbers; F: (m, 3) integer indices into V. Raises InputError for
    bad arrays, OutputError naming the file when it cannot be written.
    """
    _core.write_mesh(_os.fspath(path), *_arrays.surface(V, F))


def read_vts(path: _PathLike, vertex_count: int, rows: int | None = None) -> _np.ndarray:
    """Reads a .vts correspondence file (as in FAUST/SHREC remeshings): one
    one-based vertex id per line, row k the same point in every pose's file.

    Returns the ids as a zero-based int32 (k,) array, for
    metrics.pose_distance(rows_a=..., rows_b=...). vertex_count: the mesh's
    number of vertices (ids above it are refused); rows: the number of ids
    the file must hold (None: any). Raises InputError naming the file and line.
    """
    return _core.read_vts(_os.fspath(path), vertex_count, -1 if rows is None else rows)


def demo_shape(pose: str = "0", resolution: int | None = None) -> tuple[_np.ndarray, _np.ndarray]:
    """The command line's built-in demo animal (--demo_pose): pose "rest", "0", "1" or "2".

    resolution: edges along the body, about resolution**2 vertices, in [16, 128]
    (None: the command line's, about 4000 vertices).
    """
    return _core.demo_shape(pose, **({} if resolution is None else {"resolution": resolution}))


def unfold(V: _npt.ArrayLike, F: _npt.ArrayLike, config: _config.Config = None, *,
           tets: _npt.ArrayLike | None = None, tet_vertices: _npt.ArrayLike | None = None,
           unfolded_tet_vertices: _npt.ArrayLike | None = None, **overrides: _Any) -> Result:
    """Unfolds a closed triangle surface into its canonical pose.

    V: (n, 3) positions (any real dtype and layout); F: (m, 3) integer faces.
    config: a YAML file path (as --config) or a dict of config keys, nested
    ({"cascade": {"k_iter": 20}}) or dotted ({"cascade.k_iter": 20}).
    overrides: config keys on top of config, as keywords: method="ceres",
    cascade={"k_iter": 20}, **{"beta.value": 2.0}, or a flag name of the
    command line (k_iter=20, beta=2.0). Every key: unfold.config_keys().
    The baselines and backends are methods: method="local_global" (default),
    "ceres", "dpmu", "lsmds", "scf".

    tets, tet_vertices: a tet mesh to unfold instead of tetrahedralizing the
    surface ((k, 4) indices into the (p, 3) tet_vertices, e.g. from TetWild or
    meshio): its boundary must be the surface (same positions), else
    InputError; the Result's tets are then these, the surface's vertices first.
    unfolded_tet_vertices: with them, where they were made (a Result's
    unfolded_tet_vertices, as --rest_tet_output's "unfolded" array): the
    default then unfolds them as the run that made them did.

    Returns a Result. Raises ConfigError (bad key or value), InputError (bad
    arrays or surface), NumericalError (the solve failed). The GIL is released
    while it runs, so other Python threads go on.
    """
    V, F = _arrays.surface(V, F)
    path, flat = _config.split(config, overrides)
    if (tets is None) != (tet_vertices is None):
        raise InputError("tets and tet_vertices go together: give both or neither")
    if tets is not None:
        tet_vertices = _arrays.vertices(tet_vertices, "tet_vertices")
        tets = _arrays.elements(tets, len(tet_vertices), 4, "tets")
    if unfolded_tet_vertices is not None:
        if tets is None:
            raise InputError("unfolded_tet_vertices goes with tets and tet_vertices")
        unfolded_tet_vertices = _arrays.vertices(unfolded_tet_vertices, "unfolded_tet_vertices")
        if len(unfolded_tet_vertices) != len(tet_vertices):
            raise InputError(f"unfolded_tet_vertices has {len(unfolded_tet_vertices)} rows, "
                             f"tet_vertices {len(tet_vertices)}")
    return Result(**_core.unfold(V, F, path, flat, tets, tet_vertices, unfolded_tet_vertices))


def compare(V: _npt.ArrayLike, F: _npt.ArrayLike,
            configs: _Sequence[_config.Config | tuple[str, _config.Config]],
            fixed_beta: float | None = None) -> list[dict[str, _Any]]:
    """Several configs on one tet mesh, as the command line unfold_compare.

    configs: YAML paths (a row is named by the file's stem), dicts (named
    config1, config2, ...) or (name, path or dict) pairs. fixed_beta: if set,
    every config runs at this one beta (relative to n/lambda_2) to convergence.
    Returns one dict per config with the columns of unfold_compare's CSV.
    """
    V, F = _arrays.surface(V, F)
    if fixed_beta is not None and not fixed_beta > 0:
        raise ConfigError(f"fixed_beta must be > 0, got {fixed_beta}")
    fixed = _core.fixed_beta_overrides(fixed_beta) if fixed_beta is not None else {}
    runs = []
    for k, item in enumerate(configs):
        name, config = item if isinstance(item, tuple) else (None, item)
        path, flat = _config.split(config, {})
        if name is None:
            name = _os.path.splitext(_os.path.basename(path))[0] if path else f"config{k + 1}"
        runs.append((name, path, {**flat, **fixed}))
    return _core.compare(V, F, runs)


def correspond(source_V: _npt.ArrayLike, source_F: _npt.ArrayLike, target_V: _npt.ArrayLike,
               target_F: _npt.ArrayLike, config: _config.Config = None,
               return_decision: bool = False, **overrides: _Any) -> _Any:
    """A dense point-to-point map from one surface to another, as unfold_match.

    Each surface is unfolded into its canonical form; the forms are aligned
    rigidly, the map or its mirror image chosen, among the best rotation and
    its half turns the placement that best keeps the surfaces' curvature, and
    the map refined by ZoomOut (config keys match.*, e.g.
    match={"refine": "none"}). config and overrides as for unfold().

    Returns an (n_source,) int64 array: the 0-based target vertex of each
    source vertex; with return_decision=True, (map, decision) where decision
    is a dict: "margin" (the runner-up placement's curvature disagreement over
    the chosen one's; inf when there was no choice), "sure" (margin at least
    match.sure_margin: when False, look at the map), "mirrored", "ambiguous"
    (the mirror decision) and "decision" (the summary's words). Raises
    ConfigError, InputError or NumericalError.
    """
    VA, FA = _arrays.surface(source_V, source_F)
    VB, FB = _arrays.surface(target_V, target_F)
    path, flat = _config.split(config, overrides)
    result = _core.correspond(VA, FA, VB, FB, path, flat)
    mapping = _np.asarray(result.pop("map"), dtype=_np.int64)
    return (mapping, result) if return_decision else mapping


def config_keys() -> list[tuple[str, str, str]]:
    """Every config key as (command-line flag, YAML key, help)."""
    return _core.config_keys()


def _key_list() -> str:
    return "\n".join(f"    {path} (flag {flag}): {text}" for flag, path, text in config_keys())


unfold.__doc__ = f"{unfold.__doc__}\n    Config keys:\n{_key_list()}\n"
