"""Shared fixtures: the command-line tools, the demo shape, ../shared/data.

ctest sets UNFOLD_BIN_DIR, UNFOLD_SOURCE_DIR and UNFOLD_SHARED_DATA (see
python/CMakeLists.txt); run by hand, the defaults assume build/ in the source tree.
"""

import json
import os
import subprocess
from pathlib import Path

import pytest

SOURCE_DIR = Path(os.environ.get("UNFOLD_SOURCE_DIR", Path(__file__).resolve().parents[2]))
BIN_DIR = Path(os.environ.get("UNFOLD_BIN_DIR", SOURCE_DIR / "build" / "bin"))
SHARED_DATA = Path(os.environ.get("UNFOLD_SHARED_DATA", SOURCE_DIR.parent / "shared" / "data"))


def run_cli(app, *args):
    """Runs a command-line tool; returns its CompletedProcess (text output)."""
    return subprocess.run([str(BIN_DIR / app), *map(str, args)], capture_output=True, text=True)


def cli_unfold(input_path, tmp_path, *flags):
    """The CLI's canonical surface file, tet mesh file and metrics for input_path."""
    out, vtu, js = tmp_path / "cli.off", tmp_path / "cli.vtu", tmp_path / "cli.json"
    run = run_cli("unfold", "--input", input_path, "--output", out, "--tet_output", vtu,
                  "--metrics_json", js, *flags)
    assert run.returncode == 0, run.stderr
    return out, vtu, json.loads(js.read_text())


def without_timings(metrics):
    """The metrics with every "seconds..." entry and the stages' seconds taken out (they
    differ run to run)."""
    if isinstance(metrics, dict):
        return {
            k: without_timings(v)
            for k, v in metrics.items()
            if not k.startswith("seconds") and k != "stages"
        }
    if isinstance(metrics, list):
        return [without_timings(v) for v in metrics]
    return metrics


@pytest.fixture(scope="session")
def demo():
    """The demo animal in pose 1, coarser than the command line's (faster)."""
    import unfold
    return unfold.demo_shape("1", resolution=40)


@pytest.fixture(scope="session")
def demo_file(tmp_path_factory, demo):
    import unfold
    path = tmp_path_factory.mktemp("demo") / "demo1.off"
    unfold.write_mesh(path, *demo)
    return path


@pytest.fixture
def wolf0():
    path = SHARED_DATA / "tosca" / "wolf0.off"
    if not path.exists():
        pytest.skip(f"{path} not found (the TOSCA meshes of ../shared/data)")
    return path
