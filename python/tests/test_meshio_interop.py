"""An independent reader (meshio) opens the CLI's .vtu and .ply outputs with every field."""

import numpy as np
import pytest
from conftest import run_cli

import unfold

meshio = pytest.importorskip("meshio", reason="needs python3-meshio")


def test_meshio_reads_the_tet_mesh_and_surface_with_their_fields(tmp_path, demo, demo_file):
    vtu, ply = tmp_path / "tets.vtu", tmp_path / "canonical.ply"
    run = run_cli("unfold", "--input", demo_file, "--output", ply, "--tet_output", vtu,
                  "--target_vertices", 400)
    assert run.returncode == 0, run.stderr
    r = unfold.unfold(*demo, target_vertices=400)

    tets = meshio.read(vtu)
    np.testing.assert_allclose(tets.points, r.tet_vertices, atol=1e-9)
    assert [block.type for block in tets.cells] == ["tetra"]
    np.testing.assert_array_equal(tets.cells[0].data, r.tets)
    assert set(tets.point_data) == {"rigidity_error", "stretch_ratio", "edge_damage"}
    for name, values in tets.point_data.items():
        assert len(values) == len(tets.points)
        np.testing.assert_allclose(values, r.tet_vertex_fields[name], rtol=1e-6)
    assert set(tets.cell_data) == {"volume_ratio", "rigidity"}
    for name, blocks in tets.cell_data.items():
        assert len(blocks[0]) == len(tets.cells[0].data)
        np.testing.assert_allclose(blocks[0], r.tet_fields[name], rtol=1e-6)

    surface = meshio.read(ply)
    np.testing.assert_allclose(surface.points, r.vertices, atol=1e-9)
    np.testing.assert_array_equal(surface.cells[0].data, r.faces)
