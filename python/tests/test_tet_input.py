"""A tet mesh given instead of made: every format meshio writes that the
command line reads (--tet_input), and unfold.unfold(V, F, tets=, tet_vertices=),
all unfolding to the canonical form of the run whose --rest_tet_output it was."""

import numpy as np
import pytest
from conftest import run_cli

import unfold

meshio = pytest.importorskip("meshio", reason="needs python3-meshio")


@pytest.fixture(scope="module")
def first_run(tmp_path_factory, demo_file):
    """The demo's run on the input's tets with its rest tet mesh kept: (canonical
    vertices, rest .vtu). Given tets unfold as the input's do."""
    tmp = tmp_path_factory.mktemp("tet_input")
    out, rest = tmp / "first.off", tmp / "rest.vtu"
    run = run_cli("unfold", "--input", demo_file, "--output", out, "--rest_tet_output", rest,
                  "--tet_shape", "input")
    assert run.returncode == 0, run.stderr
    return unfold.read_mesh(out)[0], rest


@pytest.mark.parametrize("name, options", [
    ("tets.vtu", {"file_format": "vtu", "binary": False}),
    ("tets.node", {"file_format": "tetgen"}),
    ("tets22.msh", {"file_format": "gmsh22", "binary": False}),
    ("tets41.msh", {"file_format": "gmsh", "binary": False}),
    ("tets.mesh", {"file_format": "medit"}),
])
def test_every_format_meshio_writes_unfolds_to_the_same_canonical_form(
        tmp_path, first_run, name, options):
    canonical, rest = first_run
    tets = meshio.read(rest)
    path = tmp_path / name
    meshio.write(path, meshio.Mesh(tets.points, [("tetra", tets.cells[0].data)]), **options)
    out = tmp_path / "canonical.off"
    run = run_cli("unfold", "--tet_input", path, "--output", out)
    assert run.returncode == 0, run.stderr
    np.testing.assert_allclose(unfold.read_mesh(out)[0], canonical, atol=1e-9)


def test_python_takes_the_tets_and_checks_the_boundary(first_run, demo):
    canonical, rest = first_run
    tets = meshio.read(rest)
    V, F = demo
    r = unfold.unfold(V, F, tets=tets.cells[0].data, tet_vertices=tets.points)
    np.testing.assert_allclose(r.vertices, canonical, atol=1e-9)
    np.testing.assert_array_equal(r.tets, tets.cells[0].data)
    assert r.metrics["tetrahedralization"]["route"] == "given"

    moved = tets.points.copy()
    moved[0] += 0.01  # a surface vertex no longer on the surface
    with pytest.raises(unfold.InputError, match="is not the surface"):
        unfold.unfold(V, F, tets=tets.cells[0].data, tet_vertices=moved)
    with pytest.raises(unfold.InputError, match="give both"):
        unfold.unfold(V, F, tets=tets.cells[0].data)


def test_the_defaults_tets_given_back_with_where_they_were_made_unfold_as_they_did(demo):
    V, F = demo
    first = unfold.unfold(V, F)
    assert first.unfolded_tet_vertices.shape == first.rest_tet_vertices.shape
    again = unfold.unfold(V, F, tets=first.tets, tet_vertices=first.rest_tet_vertices,
                          unfolded_tet_vertices=first.unfolded_tet_vertices)
    assert again.metrics["tetrahedralization"]["route"] == "given"
    np.testing.assert_allclose(again.vertices, first.vertices, atol=1e-12)
    np.testing.assert_array_equal(again.unfolded_tet_vertices, first.unfolded_tet_vertices)
    with pytest.raises(unfold.InputError, match="rows"):
        unfold.unfold(V, F, tets=first.tets, tet_vertices=first.rest_tet_vertices,
                      unfolded_tet_vertices=first.unfolded_tet_vertices[1:])
    volume = unfold.unfold(V, F, domain="volume")  # the input's tets: made at rest
    assert volume.unfolded_tet_vertices.shape == (0, 3)
