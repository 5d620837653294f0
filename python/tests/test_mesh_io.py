"""read_mesh / write_mesh: numpy round trips and the arrays they accept or refuse."""

import numpy as np
import pytest

import unfold


@pytest.mark.parametrize("ext", [".off", ".obj", ".ply"])
def test_text_formats_round_trip_exactly(tmp_path, demo, ext):
    V, F = demo
    unfold.write_mesh(tmp_path / f"m{ext}", V, F)
    V2, F2 = unfold.read_mesh(tmp_path / f"m{ext}")
    assert V2.dtype == np.float64 and V2.shape == V.shape
    assert F2.dtype == np.int32
    np.testing.assert_array_equal(V2, V)
    np.testing.assert_array_equal(F2, F)


def test_stl_round_trip_keeps_float_precision(tmp_path, demo):
    V, F = demo
    unfold.write_mesh(tmp_path / "m.stl", V, F)
    V2, F2 = unfold.read_mesh(tmp_path / "m.stl")
    assert len(F2) == len(F)
    np.testing.assert_allclose(V2[F2], V[F], rtol=1e-6, atol=1e-6)


def test_float32_noncontiguous_and_int64_inputs_are_converted(tmp_path, demo):
    V, F = demo
    wide = np.zeros((len(V), 6), dtype=np.float32)
    wide[:, ::2] = V  # a strided, float32 view
    unfold.write_mesh(tmp_path / "m.off", wide[:, ::2], F.astype(np.int64)[:, [0, 1, 2]])
    V2, F2 = unfold.read_mesh(tmp_path / "m.off")
    np.testing.assert_array_equal(V2, V.astype(np.float32).astype(np.float64))
    np.testing.assert_array_equal(F2, F)


@pytest.mark.parametrize(
    "V, F, message",
    [
        (np.zeros((4, 2)), [[0, 1, 2]],
         r"V must be an \(n, 3\) array of positions, got shape \(4, 2\)"),
        (np.zeros(12), [[0, 1, 2]], r"got shape \(12,\)"),
        (np.zeros((4, 3)), [[0, 1, 2, 3]], r"F must be an \(m, 3\) array .* got shape \(1, 4\)"),
        (np.zeros((4, 3)), [[0.0, 1.0, 2.0]], "F must hold integers"),
        (np.zeros((4, 3)), [[0, 1, 4]], "F refers to vertex 4, but there are 4 vertices"),
        (np.zeros((4, 3)), [[0, -1, 2]], "F refers to vertex -1"),
        (np.array([["a"] * 3] * 4), [[0, 1, 2]], "V must hold real numbers"),
    ],
)
def test_wrong_arrays_are_refused_with_a_clear_message(tmp_path, V, F, message):
    with pytest.raises(unfold.InputError, match=message):
        unfold.write_mesh(tmp_path / "m.off", V, F)
    with pytest.raises(unfold.InputError, match=message):
        unfold.unfold(V, F)
    assert not (tmp_path / "m.off").exists()


def test_missing_file_raises_input_error_naming_it(tmp_path):
    with pytest.raises(unfold.InputError, match="missing.off"):
        unfold.read_mesh(tmp_path / "missing.off")


def test_unwritable_output_raises_output_error(tmp_path, demo):
    with pytest.raises(unfold.OutputError, match=r"\.xyz"):
        unfold.write_mesh(tmp_path / "m.xyz", *demo)
    with pytest.raises(OSError, match="no_dir"):
        unfold.write_mesh(tmp_path / "no_dir" / "m.off", *demo)
