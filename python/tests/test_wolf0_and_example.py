"""On a real mesh (TOSCA wolf0): the binding and its example give the CLI's output."""

import subprocess
import sys

import numpy as np
from conftest import SOURCE_DIR, cli_unfold, without_timings

import unfold

EXAMPLE = SOURCE_DIR / "examples" / "python" / "unfold_example.py"


def test_wolf0_equals_the_command_line_and_the_example_writes_the_same_file(tmp_path, wolf0):
    cli_out, _, cli_metrics = cli_unfold(wolf0, tmp_path)
    r = unfold.unfold(*unfold.read_mesh(wolf0))
    V, F = unfold.read_mesh(cli_out)
    np.testing.assert_allclose(r.vertices, V, rtol=0, atol=1e-9)
    np.testing.assert_array_equal(r.faces, F)
    assert without_timings(r.metrics) == without_timings(cli_metrics)

    out = tmp_path / "example.off"
    run = subprocess.run([sys.executable, str(EXAMPLE), str(wolf0), str(out)],
                         capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    assert out.read_bytes() == cli_out.read_bytes()
    assert run.stdout.startswith(f"E_rig {r.metrics['E_rig']:.4f}")
