"""unfold.unfold: the same run as the command line, configs in every form, every error."""

import re

import numpy as np
import pytest
from conftest import SOURCE_DIR, cli_unfold, run_cli, without_timings

import unfold

BAD_INPUTS = SOURCE_DIR / "tests" / "bad_inputs"
SMALL = {"simplify": {"target_vertices": 400}}


@pytest.fixture(scope="module")
def demo_result(demo):
    return unfold.unfold(*demo)


def test_result_equals_the_command_line_on_the_demo_shape(tmp_path, demo, demo_file, demo_result):
    out, _, metrics = cli_unfold(demo_file, tmp_path)
    V, F = unfold.read_mesh(out)
    r = demo_result
    np.testing.assert_allclose(r.vertices, V, rtol=0, atol=1e-9)
    np.testing.assert_array_equal(r.faces, F)
    assert without_timings(r.metrics) == without_timings(metrics)
    assert list(r.metrics) == list(metrics)  # same keys, same order


def test_result_arrays_fit_together(demo, demo_result):
    V, F = demo
    r = demo_result
    n, N = len(V), r.metrics["tet_vertices"]
    assert r.vertices.shape == (n, 3) and r.faces.shape == F.shape
    assert r.tet_vertices.shape == (N, 3) and r.rest_tet_vertices.shape == (N, 3)
    assert r.tets.shape == (r.metrics["tets"], 4)
    np.testing.assert_array_equal(r.rest_tet_vertices[:n], V)  # surface vertices come first
    np.testing.assert_array_equal(r.tet_vertices[:n], r.vertices)
    assert r.rigidity_error.shape == (n,) and r.stretch_ratio.shape == (n,)
    assert r.edge_damage.shape == (n,) and np.all(r.tet_vertex_fields["edge_damage"][n:] == 0)
    assert set(r.tet_fields) == {"volume_ratio", "rigidity"}
    assert all(len(v) == len(r.tets) for v in r.tet_fields.values())
    assert r.metrics["E_rig"] == pytest.approx(r.tet_vertex_fields["rigidity_error"].mean())
    assert np.all(np.abs(r.stretch_ratio - 1) < 0.5)


def test_config_forms_give_the_same_run(tmp_path, demo):
    (tmp_path / "c.yaml").write_text("simplify:\n  target_vertices: 400\ncascade:\n  k_iter: 3\n")
    runs = [
        unfold.unfold(*demo, config=tmp_path / "c.yaml"),
        unfold.unfold(*demo, config=str(tmp_path / "c.yaml")),
        unfold.unfold(*demo, {"simplify": {"target_vertices": 400}, "cascade": {"k_iter": 3}}),
        unfold.unfold(*demo, **SMALL, cascade={"k_iter": 3}),
        unfold.unfold(*demo, **{"simplify.target_vertices": 400, "cascade.k_iter": 3}),
        unfold.unfold(*demo, target_vertices=np.int64(400), k_iter=3),  # flag names
        unfold.unfold(*demo, config={"cascade": {"k_iter": 9}}, **SMALL, k_iter=3),
    ]
    assert len(runs[0].vertices) < 500
    assert max(r.metrics["iterations"] for r in runs) <= 3 * runs[0].metrics["cascades"]
    for r in runs[1:]:
        np.testing.assert_array_equal(r.vertices, runs[0].vertices)


def test_float32_and_strided_inputs_give_the_run_of_their_float64_values(demo):
    V, F = demo
    V32 = np.asfortranarray(V.astype(np.float32))  # column-major: rows are strided
    F64 = np.ascontiguousarray(F.astype(np.int64)[::-1])[::-1]  # a reversed view
    assert not V32.flags.c_contiguous and not F64.flags.c_contiguous
    r = unfold.unfold(V32, F64, **SMALL)
    expected = unfold.unfold(V32.astype(np.float64), F, **SMALL)
    np.testing.assert_array_equal(r.vertices, expected.vertices)


@pytest.mark.parametrize("method", ["local_global", "ceres", "lsmds", "dpmu", "scf"])
def test_every_method_runs_through_the_same_call(demo, method):
    config = SOURCE_DIR / "configs" / f"{method if method != 'local_global' else 'default'}.yaml"
    r = unfold.unfold(*demo, config=config, **SMALL)
    assert r.metrics["method"] == method
    assert r.vertices.shape == (r.metrics["surface_vertices"], 3)
    assert np.isfinite(r.vertices).all()
    moved = np.linalg.norm(r.vertices - r.rest_tet_vertices[: len(r.vertices)], axis=1)
    assert moved.max() > 0.1  # the legs moved
    if method == "scf":
        assert r.skeleton_edges.shape[1] == 2 and len(r.skeleton_edges) > 0
        assert r.canonical_skeleton_nodes.shape == r.skeleton_nodes.shape


def cli_error(*args):
    run = run_cli("unfold", *args)
    assert run.returncode != 0
    prefix = "unfold: error: "
    line = run.stderr.strip().splitlines()[-1]
    assert line.startswith(prefix)
    return line[len(prefix):]


def test_input_error_carries_the_command_lines_message():
    V, F = unfold.read_mesh(BAD_INPUTS / "open_surface.off")
    with pytest.raises(unfold.InputError) as error:
        unfold.unfold(V, F)
    assert str(error.value) == cli_error("--input", BAD_INPUTS / "open_surface.off")
    assert "the surface is open" in str(error.value)


def test_numerical_error_carries_the_command_lines_message():
    V, F = unfold.read_mesh(BAD_INPUTS / "self_intersecting.off")
    with pytest.raises(unfold.NumericalError, match="TetGen") as error:
        unfold.unfold(V, F, tetrahedralize={"route": "conforming", "shape": "input"})
    # The signal TetGen's crash ends with (SIGSEGV, SIGABRT) depends on the heap.
    def any_signal(message):
        return re.sub(r"stopped with [^;]*;", "stopped with <signal>;", message)
    assert any_signal(str(error.value)) == any_signal(
        cli_error("--input", BAD_INPUTS / "self_intersecting.off", "--tet_route", "conforming",
                  "--tet_shape", "input"))


@pytest.mark.parametrize(
    "config, overrides, message",
    [
        (None, {"no_such_key": 1}, "unknown config key 'no_such_key'"),
        (None, {"cascade": {"k_itr": 1}}, "unknown config key 'cascade.k_itr'"),
        ({"cascade": {"k_iter": 0}}, {}, "config key 'cascade.k_iter' must be at least 1"),
        (None, {"k_iter": "many"}, "config key 'cascade.k_iter' must be an integer"),
        (None, {"method": "magic"}, "must be local_global, ceres, dpmu, lsmds or scf, got 'magic'"),
        (None, {"method": None}, "config key 'method' cannot be set to None"),
        (BAD_INPUTS / "negative_beta.yaml", {}, "beta.value"),
        (42, {}, "config must be a YAML file path or a dict"),
    ],
)
def test_config_errors_name_the_key(demo, config, overrides, message):
    with pytest.raises(unfold.ConfigError, match=message):
        unfold.unfold(*demo, config, **overrides)


def test_config_error_from_a_file_carries_the_command_lines_message(demo):
    path = BAD_INPUTS / "negative_beta.yaml"
    with pytest.raises(unfold.ConfigError) as error:
        unfold.unfold(*demo, config=path)
    assert str(error.value) == cli_error("--config", path)


def test_strings_with_commas_stay_strings(demo, tmp_path):
    with pytest.raises(unfold.InputError, match="a,b.csv"):
        unfold.unfold(*demo, **SMALL, user_pairs={"file": str(tmp_path / "a,b.csv")})


def test_every_error_is_an_unfold_error_and_a_builtin_one():
    for error, builtin in [(unfold.ConfigError, ValueError), (unfold.InputError, ValueError),
                           (unfold.NumericalError, RuntimeError), (unfold.OutputError, OSError)]:
        assert issubclass(error, unfold.Error) and issubclass(error, builtin)


def test_help_shows_the_docstring_and_every_config_key():
    doc = unfold.unfold.__doc__
    assert "Unfolds a closed triangle surface" in doc
    for flag, path, _ in unfold.config_keys():
        assert f"{path} (flag {flag})" in doc
    assert ("k_iter", "cascade.k_iter") in [(f, p) for f, p, _ in unfold.config_keys()]
