"""unfold.correspond: a dense map between two surfaces, as unfold_match."""

import numpy as np
import pytest

import unfold


def chiral_blob(rings, segments):
    """A closed surface without mirror symmetry (as tests/unfold_match_test.cpp's)."""
    theta = np.linspace(0, np.pi, rings + 1)[1:-1]
    phi = np.linspace(0, 2 * np.pi, segments, endpoint=False)
    t, p = np.meshgrid(theta, phi, indexing="ij")
    u = np.stack([np.sin(t) * np.cos(p), np.sin(t) * np.sin(p), np.cos(t)], -1).reshape(-1, 3)
    u = np.vstack([[0, 0, 1], u, [0, 0, -1]])
    faces = []
    n = len(u)
    ring = lambda r, s: 1 + r * segments + s % segments
    for s in range(segments):
        faces.append([0, ring(0, s), ring(0, s + 1)])
        faces.append([n - 1, ring(rings - 2, s + 1), ring(rings - 2, s)])
        for r in range(rings - 2):
            faces.append([ring(r, s), ring(r + 1, s), ring(r + 1, s + 1)])
            faces.append([ring(r, s), ring(r + 1, s + 1), ring(r, s + 1)])
    bumps = np.array([[0.8, 0.5, 0.3], [-0.6, 0.1, 0.8], [0.1, -0.9, -0.4]])
    bumps /= np.linalg.norm(bumps, axis=1, keepdims=True)
    radius = 1 + sum(h * np.exp(-np.sum((u - b) ** 2, 1) / 0.08)
                     for h, b in zip([0.6, 0.4, 0.25], bumps))
    return (radius[:, None] * u) * [1.8, 1.0, 0.8], np.array(faces)


def test_correspond_maps_a_moved_copy_onto_itself():
    V, F = chiral_blob(20, 40)
    angle = 0.7
    R = np.array([[np.cos(angle), -np.sin(angle), 0], [np.sin(angle), np.cos(angle), 0], [0, 0, 1]])
    moved = V @ R.T + [0.3, -1.0, 2.0]
    m = unfold.correspond(V, F, moved, F)
    assert m.dtype == np.int64 and m.shape == (len(V),)
    assert m.min() >= 0 and m.max() < len(V)
    area = 0.5 * np.linalg.norm(np.cross(V[F[:, 1]] - V[F[:, 0]], V[F[:, 2]] - V[F[:, 0]]), axis=1).sum()
    error = np.linalg.norm(V[m] - V, axis=1).mean() / np.sqrt(area)
    assert error < 0.02


def test_correspond_refuses_a_bad_key():
    V, F = chiral_blob(8, 16)
    with pytest.raises(unfold.ConfigError, match="match.refine"):
        unfold.correspond(V, F, V, F, match={"refine": "icp"})


def test_correspond_says_how_sure_its_placement_is():
    V, F = chiral_blob(20, 40)
    m, decision = unfold.correspond(V, F, V @ np.diag([-1.0, -1.0, 1.0]), F, return_decision=True)
    assert m.shape == (len(V),)
    assert set(decision) == {"margin", "sure", "mirrored", "ambiguous", "decision"}
    # A shape without symmetry turned half round: the turn is found, and sure.
    assert decision["sure"] and decision["margin"] > 1.05 and not decision["mirrored"]
    assert np.linalg.norm(V[m] - V, axis=1).mean() < 0.05
    plain = unfold.correspond(V, F, V, F, match={"placement": "residual"}, return_decision=True)[1]
    assert plain["margin"] == np.inf and plain["sure"]
