"""The solve releases the GIL and logs through Python's logging, not stderr:
the stages' lines at INFO, the iterations' at DEBUG (the command line's -v, -vv)."""

import logging
import threading
import time

import numpy as np

import unfold


def subdivided(V, F):
    """Each triangle cut into four at its edges' midpoints: the same surface, four times the
    triangles."""
    edges = np.sort(np.concatenate([F[:, [0, 1]], F[:, [1, 2]], F[:, [2, 0]]]), axis=1)
    unique, index = np.unique(edges, axis=0, return_inverse=True)
    ab, bc, ca = len(V) + index.reshape(3, -1)
    a, b, c = F.T
    faces = [np.c_[a, ab, ca], np.c_[ab, b, bc], np.c_[ca, bc, c], np.c_[ab, bc, ca]]
    return np.vstack([V, V[unique].mean(axis=1)]), np.vstack(faces)


def test_another_thread_runs_python_during_a_solve():
    # Long enough a solve to tell, even idle: about 16,000 vertices, from the stored
    # default shape (meshing one that fine would take seconds more than the solve).
    V, F = subdivided(*unfold.demo_shape("1"))
    done = threading.Event()
    solver = threading.Thread(target=lambda: (unfold.unfold(V, F), done.set()))
    start = time.perf_counter()
    solver.start()
    ticks, last, worst_gap = 0, start, 0.0
    while not done.is_set():
        time.sleep(0.001)
        now = time.perf_counter()
        ticks, worst_gap, last = ticks + 1, max(worst_gap, now - last), now
    solver.join()
    solve_seconds = time.perf_counter() - start
    assert solve_seconds > 0.5, "the solve is too short to tell"
    # With the GIL held for the solve this thread would stop for all of it.
    assert worst_gap < 0.25 * solve_seconds
    assert ticks > 100


def test_progress_goes_to_the_unfold_logger_and_not_to_stderr(demo, caplog, capfd):
    with caplog.at_level(logging.INFO, logger="unfold"):
        unfold.unfold(*demo, simplify={"target_vertices": 400})
    messages = [r.getMessage() for r in caplog.records if r.name == "unfold"]
    assert any("cascade" in m for m in messages), messages
    captured = capfd.readouterr()
    assert captured.err == "" and captured.out == ""


def unfold_records(caplog, level, demo):
    with caplog.at_level(level, logger="unfold"):
        unfold.unfold(*demo, simplify={"target_vertices": 400})
    return [(r.levelno, r.getMessage()) for r in caplog.records if r.name == "unfold"]


def test_stage_lines_at_info_and_iteration_lines_at_debug(demo, caplog):
    records = unfold_records(caplog, logging.DEBUG, demo)
    iterations = [level for level, m in records if m.startswith("iteration ")]
    assert iterations and set(iterations) == {logging.DEBUG}, records
    stages = [level for level, m in records if m.startswith("stage ")]
    assert stages and set(stages) == {logging.INFO}, records


def test_no_iteration_lines_above_debug(demo, caplog):
    records = unfold_records(caplog, logging.INFO, demo)
    assert any(m.startswith("stage ") for _, m in records), records
    assert not any(level < logging.INFO for level, _ in records), records


def test_silent_by_default(demo, capfd):
    unfold.unfold(*demo, simplify={"target_vertices": 400})
    assert capfd.readouterr().err == ""
