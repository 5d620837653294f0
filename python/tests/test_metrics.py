"""unfold.metrics: the library's metric functions, equal to a run's metrics."""

import numpy as np
import pytest

import unfold
from unfold import metrics


@pytest.fixture(scope="module")
def small_result(demo):
    return unfold.unfold(*demo, simplify={"target_vertices": 400})


def rotation(angle):
    c, s = np.cos(angle), np.sin(angle)
    return np.array([[c, -s, 0], [s, c, 0], [0, 0, 1]])


def solve_edges(r):
    """The edges the default measures on: the tets' and the surface's (integrate.surface_edges)."""
    T, F = np.asarray(r.tets), np.asarray(r.faces)
    pairs = [T[:, [a, b]] for a in range(4) for b in range(a + 1, 4)]
    pairs += [F[:, [a, (a + 1) % 3]] for a in range(3)]
    return np.vstack(pairs)


def test_metrics_equal_the_runs_metrics(small_result):
    r = small_result
    P, Q = r.rest_tet_vertices, r.tet_vertices
    E = solve_edges(r)
    assert metrics.e_rig(P, Q, E) == pytest.approx(r.metrics["E_rig"], rel=1e-12)
    assert metrics.e_str(P, Q) == pytest.approx(r.metrics["E_str"], rel=1e-12)
    assert metrics.e_geo(P, Q, E) == pytest.approx(r.metrics["E_geo"], rel=1e-12)
    # Over the surface alone: its own edges' geodesics, the canonical surface's distances.
    n = len(r.vertices)
    assert metrics.e_geo(P[:n], r.vertices, r.faces) == pytest.approx(r.metrics["E_geo_surface"],
                                                                        rel=1e-12)
    # The tets alone leave some of the surface's edges out: another number.
    assert metrics.e_rig(P, Q, r.tets) != pytest.approx(r.metrics["E_rig"], rel=1e-6)


def test_metrics_of_known_motions(small_result):
    r = small_result
    P, T = r.rest_tet_vertices, r.tets
    moved = P @ rotation(0.7).T + [1.0, -2.0, 3.0]
    assert metrics.e_rig(P, moved, T) == pytest.approx(0, abs=1e-9)
    assert metrics.e_str(P, 1.5 * P) == pytest.approx(0.5, rel=1e-12)
    assert metrics.e_geo(P, P, T) > 0.01  # straight lines are shorter than edge paths
    assert metrics.e_geo(P, 2 * moved, T) == pytest.approx(metrics.e_geo(P, P, T), rel=1e-9)
    assert metrics.e_str(P, 1.5 * P, exact_limit=0, samples=1000) == pytest.approx(0.5)


DAMAGE_KEYS = ("damaged_edges_percent", "surface_edge_ratio_p999", "surface_edge_ratio_max",
               "surface_edge_ratio_min", "damaged_surface_edges", "surface_edges_measured",
               "zero_length_surface_edges")


def test_surface_damage_equals_the_runs_metrics(small_result):
    r = small_result
    n = len(r.vertices)
    d = metrics.surface_damage(r.rest_tet_vertices[:n], r.vertices, r.faces)
    for key in DAMAGE_KEYS:
        assert np.isfinite(r.metrics[key]), key
        assert d[key] == pytest.approx(r.metrics[key], rel=1e-12), key
    np.testing.assert_allclose(d["per_vertex"], r.edge_damage, rtol=1e-12, atol=0)
    assert r.metrics["surface_edges_measured"] > len(r.faces)


def unique_edges(F):
    E = np.sort(np.concatenate([F[:, [0, 1]], F[:, [1, 2]], F[:, [2, 0]]]), axis=1)
    return np.unique(E, axis=0)


def test_surface_damage_of_known_motions(small_result):
    r = small_result
    n = len(r.vertices)
    P, F = r.rest_tet_vertices[:n], r.faces
    moved = 2.5 * P @ rotation(0.7).T + [1.0, -2.0, 3.0]
    d = metrics.surface_damage(P, moved, F)
    assert d["damaged_edges_percent"] == 0 and d["damaged_surface_edges"] == 0
    assert d["surface_edge_ratio_max"] == pytest.approx(1, abs=1e-12)
    assert d["surface_edge_ratio_min"] == pytest.approx(1, abs=1e-12)
    assert d["scale"] == pytest.approx(1 / 2.5, rel=1e-12)
    assert d["per_vertex"].shape == (n,) and d["per_vertex"].max() < 1e-12
    # One vertex pulled 30 mean edge lengths out: exactly its edges are damaged.
    E = unique_edges(F)
    mean_edge = np.linalg.norm(P[E[:, 0]] - P[E[:, 1]], axis=1).mean()
    pulled = P.copy()
    pulled[17] += 30 * mean_edge * np.array([0.6, 0.0, 0.8])
    d = metrics.surface_damage(P, pulled, F)
    incident = int(np.count_nonzero((E == 17).any(axis=1)))
    assert d["damaged_surface_edges"] == incident
    assert d["surface_edges_measured"] == len(E)
    assert d["damaged_edges_percent"] == pytest.approx(100 * incident / len(E))
    assert d["surface_edge_ratio_max"] > 3
    assert d["per_vertex"][17] == d["per_vertex"].max()  # its neighbours may tie
    # A bound just past the largest distortion either way: none damaged.
    loose = 1.01 * max(d["surface_edge_ratio_max"], 1 / d["surface_edge_ratio_min"])
    assert metrics.surface_damage(P, pulled, F, bound=loose)["damaged_surface_edges"] == 0


def test_surface_damage_refuses_bad_input(small_result):
    r = small_result
    n = len(r.vertices)
    P, F = r.rest_tet_vertices[:n], r.faces
    with pytest.raises(unfold.InputError):
        metrics.surface_damage(P, P[:-1], F)
    bad = F.copy()
    bad[0, 0] = n
    with pytest.raises(unfold.InputError):
        metrics.surface_damage(P, P, bad)
    with pytest.raises(unfold.ConfigError):
        metrics.surface_damage(P, P, F, bound=1.0)
    with pytest.raises(unfold.NumericalError):
        metrics.surface_damage(P, np.zeros_like(P), F)


def test_pose_and_retrieval_distances(small_result, demo):
    r = small_result
    V = r.vertices
    area = metrics.surface_area(V, r.faces)
    assert area > 0
    assert metrics.surface_area(2 * V, r.faces) == pytest.approx(4 * area)
    moved = V @ rotation(1.1).T + 5.0
    assert metrics.pose_distance(V, moved, r.faces) == pytest.approx(0, abs=1e-9)
    assert metrics.pose_distance(V, 3 * moved, r.faces) == pytest.approx(0, abs=1e-9)
    assert metrics.pose_distance(V, r.rest_tet_vertices[: len(V)], r.faces) > 0.01
    with pytest.raises(unfold.ConfigError):  # the library's size check
        metrics.pose_distance(V, V[:-1], r.faces)
    assert metrics.retrieval_distance(V, moved) == pytest.approx(0, abs=1e-6)
    other = unfold.demo_shape("2", resolution=40)[0]
    assert metrics.retrieval_distance(V, other, sample_points=200) > 0


def test_metric_arguments_are_checked(small_result):
    r = small_result
    with pytest.raises(unfold.InputError, match="elements must hold integers"):
        metrics.e_rig(r.rest_tet_vertices, r.tet_vertices, r.tets.astype(float))
    with pytest.raises(unfold.InputError, match=r"deformed must be an \(n, 3\) array"):
        metrics.e_str(r.rest_tet_vertices, r.tet_vertices[:, :2])
    with pytest.raises(unfold.ConfigError):  # the library's size check
        metrics.e_str(r.rest_tet_vertices, r.tet_vertices[:10])


def remeshed(V, F, seed):
    """Another meshing of the surface (V, F): every other triangle split at its
    centroid, the vertices shuffled. Returns (V2, F2, ids): ids[k] is the new
    index of vertex k."""
    centroids = V[F[::2]].mean(axis=1)
    n, m = len(V), len(centroids)
    points = np.vstack([V, centroids])
    a, b, c = F[::2].T
    mid = n + np.arange(m)
    faces = np.vstack([F[1::2], np.c_[a, b, mid], np.c_[b, c, mid], np.c_[c, a, mid]])
    order = np.random.default_rng(seed).permutation(len(points))  # new index of old vertex
    V2 = np.empty_like(points)
    V2[order] = points
    return V2, order[faces], order[:n]


def test_read_vts_and_pose_distance_on_correspondences(tmp_path):
    V, F = unfold.demo_shape("0", resolution=20)
    W = unfold.demo_shape("2", resolution=20)[0]
    R, G, ids = remeshed(W, F, seed=4)
    (tmp_path / "r.vts").write_text("# template\n" + "".join(f"{i + 1}\n" for i in ids))
    read = unfold.read_vts(tmp_path / "r.vts", len(R), rows=len(V))
    assert read.dtype == np.int32
    np.testing.assert_array_equal(read, ids)
    identity = np.arange(len(V))
    d = metrics.pose_distance(V, W, F)
    assert d > 0.01
    # Shared connectivity and identity rows: the vertex-order distance.
    assert metrics.pose_distance(V, W, F, rows_a=identity, rows_b=identity) == pytest.approx(
        d, abs=1e-12)
    # The same pose meshed otherwise, moved and scaled: zero; another pose: d.
    moved = 0.2 * R @ rotation(0.4).T + 3.0
    assert metrics.pose_distance(W, moved, F, F_B=G, rows_a=identity,
                                 rows_b=read) == pytest.approx(0, abs=1e-9)
    assert metrics.pose_distance(V, moved, F, F_B=G, rows_a=identity,
                                 rows_b=read) == pytest.approx(d, abs=1e-7)
    with pytest.raises(unfold.InputError, match="give both rows_a and rows_b"):
        metrics.pose_distance(V, R, F, F_B=G, rows_a=identity)
    with pytest.raises(unfold.InputError, match="rows_b refers to vertex"):
        metrics.pose_distance(V, W, F, rows_a=identity, rows_b=identity + 1)
    with pytest.raises(unfold.InputError,
                       match=r"r.vts': line \d+: vertex id \d+ is outside 1\.\.10"):
        unfold.read_vts(tmp_path / "r.vts", 10)
    with pytest.raises(unfold.InputError, match="expected 3"):
        unfold.read_vts(tmp_path / "r.vts", len(R), rows=3)


def test_retrieval_measures_of_a_hand_made_matrix():
    # Classes a a a b b; the ranked lists and values worked out in
    # tests/retrieval_test.cpp (HandMadeMatrixGivesTheHandComputedValues).
    D = [[0, 3, 1, 2, 4], [3, 0, 5, 1, 6], [1, 5, 0, 7, 8], [2, 1, 7, 0, 9], [4, 6, 8, 9, 0]]
    m = metrics.retrieval_measures(D, ["a", "a", "a", "b", "b"])
    assert m["queries"] == 5
    assert m["nn"] == pytest.approx(0.4)
    assert m["first_tier"] == pytest.approx(0.4)
    assert m["second_tier"] == pytest.approx(0.6)
    assert len(m["recall"]) == len(m["precision"]) == 20
    assert m["recall"][-1] == 1
    assert m["precision"][-1] == pytest.approx((2 / 3 + 2 / 3 + 1 + 0.25 + 0.25) / 5)
    with pytest.raises(unfold.InputError, match="square"):
        metrics.retrieval_measures([[0, 1]], ["a"])
    with pytest.raises(unfold.ConfigError, match="no class has two shapes"):
        metrics.retrieval_measures(D, ["a", "b", "c", "d", "e"])


def test_ort_distance_is_invariant_to_a_rigid_motion_and_a_scale(demo):
    V, F = demo
    moved = 2.5 * V @ rotation(0.4).T - 1.0
    assert metrics.ort_distance(V, F, moved, F, sample_points=300) == pytest.approx(0, abs=1e-9)
    other, G = unfold.demo_shape("2", resolution=40)
    assert metrics.ort_distance(V, F, other, G, sample_points=300) > 1e-4


def test_cmbof_matrix_is_zero_on_a_moved_copy_and_separates_poses_from_a_box(demo):
    V, F = demo
    moved = 2.5 * V @ rotation(0.4).T - 1.0
    box_V = np.array([[x, y, z] for x in (0, 2) for y in (0, 1) for z in (0, 0.5)], float)
    box_F = np.array([[0, 1, 3], [0, 3, 2], [4, 6, 7], [4, 7, 5], [0, 4, 5], [0, 5, 1],
                      [2, 3, 7], [2, 7, 6], [0, 2, 6], [0, 6, 4], [1, 5, 7], [1, 7, 3]])
    D = metrics.cmbof_matrix([(V, F), (moved, F), (box_V, box_F)], view_subdivisions=1,
                             image_size=128, words=32)
    assert D.shape == (3, 3)
    assert np.allclose(D, D.T) and np.all(np.diag(D) == 0)
    assert D[0, 1] < 0.5 * D[0, 2]
    with pytest.raises(unfold.ConfigError, match="at least 2"):
        metrics.cmbof_matrix([(V, F)])


FOLD_KEYS = ("folded_edges_percent", "folded_surface_edges", "dihedral_change_p999_degrees",
             "dihedral_change_max_degrees")


def test_surface_folds_equal_the_runs_metrics_and_see_a_fold_that_keeps_lengths(small_result):
    r = small_result
    n = len(r.vertices)
    P, F = r.rest_tet_vertices[:n], r.faces
    f = metrics.surface_folds(P, r.vertices, F)
    for key in FOLD_KEYS:
        assert f[key] == pytest.approx(r.metrics[key], rel=1e-12), key
    assert f["per_vertex"].shape == (n,)
    assert f["per_vertex"].max() == pytest.approx(f["dihedral_change_max_degrees"], rel=1e-12)
    # A similarity bends nothing.
    moved = 2.5 * P @ rotation(0.7).T + [1.0, -2.0, 3.0]
    still = metrics.surface_folds(P, moved, F)
    assert still["folded_surface_edges"] == 0 and still["dihedral_change_max_degrees"] < 1e-6
    # A flat sheet folded over along a line keeps every length: no damage, but
    # the edges on the line turn by 150 degrees, folded at any bound below that.
    x, y = np.meshgrid(np.arange(7.0), np.arange(6.0))
    sheet = np.column_stack([x.ravel(), y.ravel(), np.zeros(x.size)])
    quads = [(j * 7 + i, j * 7 + i + 1, (j + 1) * 7 + i + 1, (j + 1) * 7 + i)
             for j in range(5) for i in range(6)]
    S = np.array(quads)
    folded = sheet.copy()
    right = sheet[:, 0] > 3
    angle = np.radians(150)
    d = sheet[right, 0] - 3
    folded[right, 0] = 3 + d * np.cos(angle)
    folded[right, 2] = d * np.sin(angle)
    assert metrics.surface_damage(sheet, folded, S)["damaged_surface_edges"] == 0
    crease = metrics.surface_folds(sheet, folded, S)
    assert crease["dihedral_change_max_degrees"] == pytest.approx(150, abs=1e-9)
    assert crease["folded_surface_edges"] == 5  # the fold line's inner edges
    assert metrics.surface_folds(sheet, folded, S, bound_degrees=160)["folded_surface_edges"] == 0
    np.testing.assert_allclose(crease["per_vertex"][sheet[:, 0] == 3], 150, atol=1e-9)
    assert crease["per_vertex"][~(sheet[:, 0] == 3)].max() < 1e-9


def test_surface_folds_refuses_bad_input(small_result):
    r = small_result
    n = len(r.vertices)
    P, F = r.rest_tet_vertices[:n], r.faces
    with pytest.raises(unfold.InputError):
        metrics.surface_folds(P, P[:-1], F)
    with pytest.raises(unfold.ConfigError):
        metrics.surface_folds(P, P, F, bound_degrees=180)
