# Copyright (c) 2026 The PR-star octree project.
# SPDX-License-Identifier: LGPL-3.0-or-later
"""prstar.validate and prstar.simplify against the prstar tool on the same files (every key of their
--json, the mesh the tool writes) and against brute-force numpy computations (signed volumes, faces
and edges counted by sorting, vertex links, dihedral angles)."""

from __future__ import annotations

import itertools
import json
import math
from pathlib import Path
from typing import Dict, List, Optional, Tuple

import numpy as np
import pytest

import prstar

# ---------------------------------------------------------------------------------------------
# Helpers: a tiny Medit reader/writer, brute-force geometry and topology
# ---------------------------------------------------------------------------------------------


def read_medit(path: Path) -> Tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(points, tetrahedra 0-based, labels) of a Medit .mesh as the tool writes it."""
    tokens = Path(path).read_text().split()
    i = tokens.index("Vertices")
    n = int(tokens[i + 1])
    v = np.array(tokens[i + 2:i + 2 + 4 * n], dtype=float).reshape(n, 4)
    j = tokens.index("Tetrahedra")
    m = int(tokens[j + 1])
    t = np.array(tokens[j + 2:j + 2 + 5 * m], dtype=np.int64).reshape(m, 5)
    return v[:, :3], t[:, :4] - 1, t[:, 4].astype(np.int32)


def write_medit(path: Path, points: np.ndarray, tetrahedra: np.ndarray, labels: Optional[np.ndarray] = None) -> None:
    labels = np.ones(len(tetrahedra), int) if labels is None else labels
    lines = ["MeshVersionFormatted 2", "Dimension 3", "Vertices", str(len(points))]
    lines += [f"{x!r} {y!r} {z!r} 0" for x, y, z in np.asarray(points, float).tolist()]
    lines += ["Tetrahedra", str(len(tetrahedra))]
    lines += [" ".join(str(int(i) + 1) for i in t) + f" {int(l)}" for t, l in zip(tetrahedra, labels)]
    lines.append("End")
    Path(path).write_text("\n".join(lines) + "\n")


def signed_volumes(points: np.ndarray, tets: np.ndarray) -> np.ndarray:
    p = np.asarray(points, float)[np.asarray(tets, np.int64)]
    return np.linalg.det(np.stack([p[:, 1] - p[:, 0], p[:, 2] - p[:, 0], p[:, 3] - p[:, 0]], axis=1)) / 6


def min_dihedral_degrees(points: np.ndarray, tets: np.ndarray) -> np.ndarray:
    """The smallest of the six dihedral angles of each tetrahedron, from the normals of its faces."""
    p = np.asarray(points, float)[np.asarray(tets, np.int64)]
    normals = []
    for k in range(4):  # the face opposite vertex k, its normal pointing away from vertex k
        a, b, c = (p[:, i] for i in range(4) if i != k)
        n = np.cross(b - a, c - a)
        n *= np.where(np.einsum("ij,ij->i", n, p[:, k] - a) > 0, -1.0, 1.0)[:, None]
        normals.append(n / np.linalg.norm(n, axis=1)[:, None])
    angles = [np.degrees(np.pi - np.arccos(np.clip(np.einsum("ij,ij->i", normals[k], normals[l]), -1, 1)))
              for k, l in itertools.combinations(range(4), 2)]
    return np.min(angles, axis=0)


def grid_mesh(n: int = 3) -> Tuple[np.ndarray, np.ndarray]:
    """A cube of n^3 unit cells on integer coordinates, each cell cut into 6 tetrahedra around its
    diagonal, all positively oriented (exact volumes: integer coordinates)."""
    ids = np.arange((n + 1) ** 3).reshape(n + 1, n + 1, n + 1)
    points = np.array(list(itertools.product(range(n + 1), repeat=3)), dtype=float)
    tets = []
    for i, j, k in itertools.product(range(n), repeat=3):
        corner = lambda d: ids[i + d[0], j + d[1], k + d[2]]  # noqa: E731
        for perm in itertools.permutations(range(3)):
            path = [(0, 0, 0)]
            for axis in perm:
                step = list(path[-1])
                step[axis] = 1
                path.append(tuple(step))
            tets.append([corner(d) for d in path])
    tets = np.array(tets, dtype=np.int64)
    negative = signed_volumes(points, tets) < 0
    tets[negative] = tets[negative][:, [1, 0, 2, 3]]
    return points, tets


class UnionFind:
    def __init__(self, n: int) -> None:
        self.parent = list(range(n))

    def find(self, a: int) -> int:
        while self.parent[a] != a:
            self.parent[a] = self.parent[self.parent[a]]
            a = self.parent[a]
        return a

    def unite(self, a: int, b: int) -> None:
        self.parent[self.find(a)] = self.find(b)


def link_is_sphere_or_disc(triangles: List[Tuple[int, int, int]]) -> bool:
    """A vertex's link (its triangles) is a sphere or a disc: every edge in 1 or 2 triangles, the
    triangles connected through edges, Euler characteristic 2 without boundary or 1 with one."""
    edges: Dict[Tuple[int, int], List[int]] = {}
    for f, t in enumerate(triangles):
        for a, b in ((t[0], t[1]), (t[1], t[2]), (t[0], t[2])):
            edges.setdefault((min(a, b), max(a, b)), []).append(f)
    if any(len(fs) > 2 for fs in edges.values()):
        return False
    uf = UnionFind(len(triangles))
    for fs in edges.values():
        for f in fs[1:]:
            uf.unite(f, fs[0])
    if len({uf.find(f) for f in range(len(triangles))}) != 1:
        return False
    vertices = {v for t in triangles for v in t}
    chi = len(vertices) - len(edges) + len(triangles)
    boundary = any(len(fs) == 1 for fs in edges.values())
    return chi == (1 if boundary else 2)


def brute_force_validity(points: np.ndarray, tets: np.ndarray) -> dict:
    """Everything `validate` reports, computed independently (exact for integer coordinates)."""
    tets = np.asarray(tets, np.int64)
    n, m = len(points), len(tets)
    vol = signed_volumes(points, tets)
    flat = np.flatnonzero(vol == 0)
    pos, neg = np.flatnonzero(vol > 0), np.flatnonzero(vol < 0)
    inverted = neg if len(neg) <= len(pos) else pos  # the minority, the negative ones on a tie
    faces = np.sort(tets[:, [[1, 2, 3], [0, 2, 3], [0, 1, 3], [0, 1, 2]]].reshape(-1, 3), axis=1)
    face_tet = np.repeat(np.arange(m), 4)
    unique_faces, inverse, count = np.unique(faces, axis=0, return_inverse=True, return_counts=True)
    inverse = inverse.ravel()
    nm_triangles = unique_faces[count >= 3]
    nm_tets = [np.sort(face_tet[inverse == f]) for f in np.flatnonzero(count >= 3)]
    boundary = unique_faces[count == 1]
    edges = np.unique(np.sort(tets[:, [[0, 1], [0, 2], [0, 3], [1, 2], [1, 3], [2, 3]]].reshape(-1, 2), axis=1),
                      axis=0)
    referenced = np.unique(tets)
    unreferenced = np.setdiff1d(np.arange(n), referenced)
    # boundary components: boundary triangles joined through their edges
    uf = UnionFind(len(boundary))
    by_edge: Dict[Tuple[int, int], int] = {}
    for f, (a, b, c) in enumerate(boundary.tolist()):
        for e in ((a, b), (b, c), (a, c)):
            if e in by_edge:
                uf.unite(f, by_edge[e])
            else:
                by_edge[e] = f
    components = len({uf.find(f) for f in range(len(boundary))})
    nm_vertices = []
    for v in referenced.tolist():
        link = [tuple(int(x) for x in t if x != v) for t in tets[(tets == v).any(axis=1)].tolist()]
        if not link_is_sphere_or_disc(link):
            nm_vertices.append(v)
    counts = {
        "valid": bool(len(inverted) == 0 and len(flat) == 0 and len(nm_triangles) == 0 and not nm_vertices),
        "tetrahedra": m,
        "inverted": len(inverted),
        "degenerate": len(flat),
        "nonmanifold_triangles": len(nm_triangles),
        "nonmanifold_vertices": len(nm_vertices),
        "unreferenced_vertices": len(unreferenced),
        "euler_characteristic": len(referenced) - len(edges) + len(unique_faces) - m,
        "boundary_triangles": len(boundary),
        "boundary_components": components,
    }
    return {"counts": counts, "inverted": inverted, "flat": flat, "nm_triangles": nm_triangles,
            "nm_tets": nm_tets, "nm_vertices": np.array(nm_vertices, np.int64), "unreferenced": unreferenced}


def without_seconds(d: dict) -> dict:
    return {k: v for k, v in d.items() if k not in ("seconds", "output", "problems")}


# ---------------------------------------------------------------------------------------------
# validate
# ---------------------------------------------------------------------------------------------

MEDIT_MESHES = ["cube.mesh", "sphere.mesh", "torus.mesh", "sphere_tetgen.mesh"]


@pytest.mark.parametrize("name", MEDIT_MESHES)
def test_validate_equals_cli(cli, data_dir, name):
    expected = cli.json("validate", data_dir / name)
    points, tets, labels = read_medit(data_dir / name)
    r = prstar.validate(prstar.Mesh(points, tets, labels))
    assert without_seconds(r.counts) == without_seconds(expected)
    assert set(r.counts) == set(expected) - {"problems"}
    assert r.problems() == expected["problems"]
    assert r.valid is expected["valid"] and bool(r) is r.valid
    assert r.euler_characteristic == expected["euler_characteristic"]
    assert r.boundary_components == expected["boundary_components"]


def test_validate_vtu_equals_cli(cli, data_dir):
    meshio = pytest.importorskip("meshio")
    m = meshio.read(data_dir / "cube_tetgen.vtu")
    expected = cli.json("validate", data_dir / "cube_tetgen.vtu")
    r = prstar.validate((m.points, m.get_cells_type("tetra")), bucket_size=math.inf, threads=1)
    assert without_seconds(r.counts) == without_seconds(expected)


def test_validate_grid_equals_brute_force():
    points, tets = grid_mesh(3)
    truth = brute_force_validity(points, tets)
    assert truth["counts"]["valid"] and truth["counts"]["euler_characteristic"] == 1
    r = prstar.validate((points, tets), bucket_size=4)
    assert without_seconds(r.counts) == truth["counts"]
    assert r.positive == len(tets) and r.negative == 0


def _broken_meshes() -> Dict[str, Tuple[np.ndarray, np.ndarray]]:
    points, tets = grid_mesh(3)
    cases: Dict[str, Tuple[np.ndarray, np.ndarray]] = {}
    t = tets.copy()
    t[[5, 40]] = t[[5, 40]][:, [1, 0, 2, 3]]  # two tetrahedra listed the other way
    cases["inverted"] = (points, t)
    t = tets[:, [1, 0, 2, 3]].copy()
    t[[3, 7]] = tets[[3, 7]]  # the majority negative: the two positive ones are the inverted ones
    cases["inverted_majority_negative"] = (points, t)
    t = tets.copy()
    t[: len(t) // 2] = t[: len(t) // 2][:, [1, 0, 2, 3]]  # as many negative as positive: the negative ones
    cases["inverted_tie"] = (points, t)
    flat_points = np.array([[10, 0, 0], [11, 0, 0], [10, 1, 0], [11, 1, 0]], float)  # coplanar
    n = len(points)
    cases["flat"] = (np.vstack([points, flat_points]), np.vstack([tets, [[n, n + 1, n + 2, n + 3]]]))
    corner = 0  # a corner of the cube, and a tetrahedron outside touching it there only
    out = np.array([[-1, -1, -2], [-2, -1, -1], [-1, -2, -1]], float)
    t = np.vstack([tets, [[corner, n, n + 2, n + 1]]])  # positively oriented
    cases["pinch_on_grid"] = (np.vstack([points, out]), t)
    pinch_points = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1], [-1, 0, 0], [0, -1, 0], [0, 0, -1]], float)
    cases["pinch"] = (pinch_points, np.array([[0, 1, 2, 3], [0, 4, 6, 5]]))
    fin_points = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1], [0, 0, -1], [1, 1, 1]], float)
    cases["nonmanifold_triangle"] = (fin_points, np.array([[0, 1, 2, 3], [0, 2, 1, 4], [0, 1, 2, 5]]))
    cases["duplicate_unreferenced"] = (np.vstack([points, points[21:22]]), tets)
    # an interior vertex duplicated, the copy used by one of its tetrahedra: a crack inside
    v = 21
    t = tets.copy()
    first = np.flatnonzero((t == v).any(axis=1))[0]
    t[first][t[first] == v] = n
    cases["duplicate_referenced"] = (np.vstack([points, points[v:v + 1]]), t)
    return cases


BROKEN = _broken_meshes()


@pytest.mark.parametrize("case", sorted(BROKEN))
def test_validate_broken_equals_brute_force(case):
    points, tets = BROKEN[case]
    truth = brute_force_validity(points, tets)
    r = prstar.validate((points, tets), bucket_size=2)  # several leaves even on small meshes
    assert without_seconds(r.counts) == truth["counts"]
    assert r.valid == truth["counts"]["valid"]
    np.testing.assert_array_equal(r.inverted_tetrahedra, truth["inverted"])
    np.testing.assert_array_equal(r.flat_tetrahedra, truth["flat"])
    np.testing.assert_array_equal(r.nonmanifold_triangles.reshape(-1, 3), truth["nm_triangles"].reshape(-1, 3))
    assert len(r.nonmanifold_triangle_tetrahedra) == len(truth["nm_tets"])
    for a, b in zip(r.nonmanifold_triangle_tetrahedra, truth["nm_tets"]):
        np.testing.assert_array_equal(a, b)
    np.testing.assert_array_equal(r.nonmanifold_vertices, truth["nm_vertices"])
    np.testing.assert_array_equal(r.unreferenced_vertices, truth["unreferenced"])
    assert r.positive + r.negative + len(truth["flat"]) == len(tets)
    # each case shows the problem it was built for
    expected_kind = {"inverted": "inverted", "inverted_majority_negative": "inverted", "inverted_tie": "inverted",
                     "flat": "degenerate", "pinch_on_grid": "nonmanifold_vertices",
                     "pinch": "nonmanifold_vertices", "nonmanifold_triangle": "nonmanifold_triangles",
                     "duplicate_unreferenced": "unreferenced_vertices", "duplicate_referenced": None}[case]
    if expected_kind is not None:
        assert r.counts[expected_kind] > 0
    text = str(r)
    assert ("valid" if r.valid else "INVALID") in text.split()[0]


def test_validate_broken_cases_are_what_they_claim():
    # the brute force itself, on what each case was made for
    assert brute_force_validity(*BROKEN["inverted"])["inverted"].tolist() == [5, 40]
    assert brute_force_validity(*BROKEN["inverted_majority_negative"])["inverted"].tolist() == [3, 7]
    n = len(grid_mesh(3)[0])
    assert brute_force_validity(*BROKEN["flat"])["flat"].tolist() == [len(grid_mesh(3)[1])]
    assert brute_force_validity(*BROKEN["pinch"])["nm_vertices"].tolist() == [0]
    assert 0 in brute_force_validity(*BROKEN["pinch_on_grid"])["nm_vertices"].tolist()
    assert brute_force_validity(*BROKEN["nonmanifold_triangle"])["nm_triangles"].tolist() == [[0, 1, 2]]
    assert brute_force_validity(*BROKEN["duplicate_unreferenced"])["unreferenced"].tolist() == [n]
    assert brute_force_validity(*BROKEN["inverted_tie"])["inverted"].tolist() == list(range(len(grid_mesh(3)[1]) // 2))
    crack = brute_force_validity(*BROKEN["duplicate_referenced"])["counts"]  # a crack: more boundary
    assert crack["boundary_triangles"] > brute_force_validity(*grid_mesh(3))["counts"]["boundary_triangles"]


@pytest.mark.parametrize("case", ["inverted", "inverted_majority_negative", "flat", "pinch", "nonmanifold_triangle",
                                  "duplicate_unreferenced", "duplicate_referenced"])
def test_validate_broken_equals_cli(cli, tmp_path, case):
    points, tets = BROKEN[case]
    path = tmp_path / f"{case}.mesh"
    write_medit(path, points, tets)
    expected = cli.json("validate", path, statuses=[0, 3])
    r = prstar.validate((points, tets))
    assert without_seconds(r.counts) == without_seconds(expected)
    assert r.problems() == expected["problems"]


def test_validate_octree_and_progress():
    points, tets = BROKEN["pinch_on_grid"]
    tree = prstar.Octree(points, tets, bucket_size=3)
    calls = []
    r = prstar.validate(tree, progress=lambda done, total: calls.append((done, total)))
    np.testing.assert_array_equal(r.nonmanifold_vertices, brute_force_validity(points, tets)["nm_vertices"])
    assert calls and calls[-1][0] == calls[-1][1] == 2 * tree.number_of_leaves

    class Stop(Exception):
        pass

    def stop(done, total):
        raise Stop()

    with pytest.raises(Stop):
        prstar.validate(tree, progress=stop)
    with pytest.raises(ValueError, match="bucket_size"):
        prstar.validate(tree, bucket_size=10)


def test_validate_errors():
    points, tets = grid_mesh(1)
    with pytest.raises(ValueError, match="points: shape"):
        prstar.validate((points[:, :2], tets))
    with pytest.raises(ValueError, match="tetrahedra: shape"):
        prstar.validate((points, tets[:, :3]))
    with pytest.raises(ValueError, match="tetrahedra: dtype"):
        prstar.validate((points, tets.astype(float)))
    bad = tets.copy()
    bad[0, 0] = len(points)
    with pytest.raises(prstar.InvalidMeshError):
        prstar.validate((points, bad))
    with pytest.raises(TypeError):
        prstar.validate("mesh.vtu")


# ---------------------------------------------------------------------------------------------
# simplify
# ---------------------------------------------------------------------------------------------

# (file, Python options, the same for the tool)
SIMPLIFY_CASES = [
    ("sphere.mesh", {"target": 0.5}, ["--target", "0.5"]),
    ("cube.mesh", {"keep": "30%", "priority": "quadric", "placement": "optimal"},
     ["--keep", "30%", "--priority", "quadric", "--placement", "optimal"]),
    ("cube.mesh", {"max_length": 0.05, "max_error": None, "bucket_size": math.inf, "min_radius_ratio": 0.1},
     ["--max-length", "0.05", "--max-error", "none", "--kv", "inf", "--min-radius-ratio", "0.1"]),
    ("sphere.mesh", {"target": "60%", "max_error": 0.01, "min_dihedral": 8, "feature_angle": 60, "bucket_size": 20},
     ["--target", "60%", "--max-error", "0.01", "--min-dihedral", "8", "--feature-angle", "60", "--kv", "20"]),
    ("cube.mesh", {"target": 0.99}, ["--target", "0.99"]),  # stops before the target (exit status 4)
]


def _cli_statistics(expected: dict) -> dict:
    """The tool's JSON in the module's terms: "inf" and null (no bound) as math.inf."""
    d = without_seconds(expected)
    if d["kv"] == "inf":
        d["kv"] = math.inf
    if d["boundary_error"]["bound"] is None:
        d["boundary_error"] = dict(d["boundary_error"], bound=math.inf)
    return d


@pytest.mark.parametrize("name,options,args", SIMPLIFY_CASES)
def test_simplify_equals_cli(cli, data_dir, tmp_path, name, options, args):
    out = tmp_path / "out.mesh"
    p = cli.run("simplify", data_dir / name, *args, "-o", out, "--json")
    assert p.returncode in (0, 4), p.stderr
    expected = json.loads(p.stdout)
    points, tets, labels = read_medit(data_dir / name)
    r = prstar.simplify(prstar.Mesh(points, tets, labels), **options)
    assert without_seconds(r.statistics) == _cli_statistics(expected)
    assert set(r.statistics) == set(expected) - {"output"}
    assert r.stop == expected["stop"]
    assert r.target_reached == (p.returncode == 0)
    if not r.target_reached:
        assert r.message and r.message in p.stderr
    # the mesh the tool wrote, read back
    q, t, l = read_medit(out)
    np.testing.assert_array_equal(r.mesh.points, q)
    np.testing.assert_array_equal(r.mesh.tetrahedra, t)
    np.testing.assert_array_equal(r.mesh.labels, l)
    assert r.mesh.points.dtype == np.float64 and r.mesh.points.shape == (len(q), 3)
    assert r.mesh.tetrahedra.dtype == np.uint32 and r.mesh.labels.dtype == np.int32
    # independent checks of the result
    floor = options.get("min_dihedral", 5)
    _check_result(points, tets, r, None if "min_radius_ratio" in options else floor)


def _check_result(points, tets, r, floor: Optional[float]) -> None:
    m = r.mesh
    assert m.tetrahedra.min() >= 0 and m.tetrahedra.max() < len(m.points)
    assert len(np.unique(m.tetrahedra)) == len(m.points)  # compacted: every vertex used
    assert np.all(signed_volumes(m.points, m.tetrahedra) > 0)
    if floor is not None:  # the input is far above the floor: no new tetrahedron under it
        assert min_dihedral_degrees(points, tets).min() > floor
        assert min_dihedral_degrees(m.points, m.tetrahedra).min() >= floor - 1e-9
    s = r.statistics
    assert (s["output_vertices"], s["output_tetrahedra"]) == (len(m.points), len(m.tetrahedra))
    assert s["removed_tetrahedra"] == s["input_tetrahedra"] - s["output_tetrahedra"]
    assert math.isclose(s["output_quality"]["min_dihedral"], min_dihedral_degrees(m.points, m.tetrahedra).min(),
                        rel_tol=1e-9)
    # the volume stays close (the surface moves by at most the error bound)
    v_in, v_out = abs(signed_volumes(points, tets)).sum(), signed_volumes(m.points, m.tetrahedra).sum()
    assert abs(v_out - v_in) < 0.02 * v_in
    assert len(r.input_vertex) == len(m.points) and len(r.input_tetrahedron) == len(m.tetrahedra)


def _labelled_cube(data_dir):
    points, tets, _ = read_medit(data_dir / "cube.mesh")
    centroid = points[tets].mean(axis=1)
    labels = np.where(centroid[:, 0] < 0.05, 3, 7).astype(np.int32)
    return points, tets, labels


def test_simplify_labels_and_data_carried(data_dir):
    points, tets, labels = _labelled_cube(data_dir)
    field = points[:, 0] * 2 + points[:, 1]
    cell = np.arange(len(tets), dtype=float)
    mesh = prstar.Mesh(points, tets, labels, point_data={"f": field}, cell_data={"c": cell},
                       label_names={3: "left", 7: "right"})
    r = prstar.simplify(mesh, target=0.6, optimize=0)
    assert r.target_reached and r.stop == "target_reached"
    out = r.mesh
    assert set(np.unique(out.labels)) == {3, 7}
    np.testing.assert_array_equal(out.labels, labels[r.input_tetrahedron])
    np.testing.assert_array_equal(out.points, points[r.input_vertex])  # half-edge, no smoothing: no vertex moves
    np.testing.assert_array_equal(out.point_data["f"], field[r.input_vertex])
    np.testing.assert_array_equal(out.cell_data["c"], cell[r.input_tetrahedron])
    assert out.label_names == {3: "left", 7: "right"}
    # each label keeps its volume (its interface is kept as a surface)
    vol_in, vol_out = abs(signed_volumes(points, tets)), signed_volumes(out.points, out.tetrahedra)
    for label in (3, 7):
        a, b = vol_in[labels == label].sum(), vol_out[out.labels == label].sum()
        assert abs(a - b) < 0.02 * a
    _check_result(points, tets, r, 5)


def test_simplify_inputs_agree(data_dir):
    points, tets, labels = _labelled_cube(data_dir)
    by_mesh = prstar.simplify(prstar.Mesh(points, tets, labels), target=0.4)
    # an Octree: its arrays in the user's numbering, so the same result; its bucket size by default
    tree = prstar.Octree(points, tets, labels=labels, field=points[:, 2])
    by_tree = prstar.simplify(tree, target=0.4)
    np.testing.assert_array_equal(by_tree.mesh.points, by_mesh.mesh.points)
    np.testing.assert_array_equal(by_tree.mesh.tetrahedra, by_mesh.mesh.tetrahedra)
    np.testing.assert_array_equal(by_tree.mesh.labels, by_mesh.mesh.labels)
    np.testing.assert_array_equal(by_tree.mesh.point_data["scalar"], points[by_tree.input_vertex, 2])
    assert without_seconds(by_tree.statistics) == without_seconds(by_mesh.statistics)
    # a pair of arrays of other dtypes and layouts (read in place): no labels
    pair = prstar.simplify((np.asfortranarray(points), tets.astype(np.int32)), target=0.4, threads=1)
    assert pair.mesh.labels is None
    plain = prstar.simplify((points, tets), target=0.4)
    np.testing.assert_array_equal(pair.mesh.tetrahedra, plain.mesh.tetrahedra)


def test_simplify_progress(data_dir):
    points, tets, _ = read_medit(data_dir / "cube.mesh")
    calls = []
    r = prstar.simplify((points, tets), target=0.5, progress=lambda d, t: calls.append((d, t)))
    to_remove = math.ceil(0.5 * len(tets))
    assert calls and all(t == to_remove for _, t in calls)
    assert calls[-1] == (to_remove, to_remove) and r.target_reached
    assert [d for d, _ in calls] == sorted(d for d, _ in calls)

    class Stop(Exception):
        pass

    def stop(done, total):
        raise Stop()

    with pytest.raises(Stop):
        prstar.simplify((points, tets), target=0.5, progress=stop)


@pytest.mark.parametrize("options,message", [
    ({}, "give target, keep or max_length"),
    ({"target": 0.5, "keep": 0.5}, "not both"),
    ({"target": 0}, "target must be a fraction"),
    ({"target": 1}, "target must be a fraction"),
    ({"target": 1.5}, "target must be a fraction"),
    ({"target": "150%"}, "target must be a fraction"),
    ({"target": -0.2}, "target must be a fraction"),
    ({"target": "half"}, "is not a fraction"),
    ({"target": "nan"}, "is not a fraction"),
    ({"keep": 0}, "keep must be a fraction"),
    ({"keep": "100%"}, "keep must be a fraction"),
    ({"max_length": 0}, "max_length must be positive"),
    ({"max_length": -1.0}, "max_length must be positive"),
    ({"target": 0.5, "min_dihedral": 80}, r"min_dihedral must be in \[0, 70.5\]"),
    ({"target": 0.5, "min_dihedral": -1}, r"min_dihedral must be in"),
    ({"target": 0.5, "min_radius_ratio": 1.5}, r"min_radius_ratio must be in \[0, 1\]"),
    ({"target": 0.5, "feature_angle": 200}, r"feature_angle must be in \[0, 180\]"),
    ({"target": 0.5, "max_error": "abc"}, "max_error must be a distance"),
    ({"target": 0.5, "max_error": "1%%"}, "max_error must be a distance"),
    ({"target": 0.5, "max_error": "-1"}, "max_error must be a distance"),
    ({"target": 0.5, "max_error": -0.5}, "max_error must be a distance"),
    ({"target": 0.5, "max_error": math.nan}, "max_error must be a distance"),
    ({"target": 0.5, "priority": "fast"}, "priority must be 'length' or 'quadric'"),
    ({"target": 0.5, "placement": "middle"}, "placement must be 'half-edge' or 'optimal'"),
    ({"target": 0.5, "bucket_size": 0}, "bucket_size"),
    ({"target": 0.5, "threads": 0}, "threads"),
])
def test_simplify_bad_options(options, message):
    points, tets = grid_mesh(2)
    with pytest.raises(ValueError, match=message):
        prstar.simplify((points, tets), **options)


def test_simplify_cli_refuses_the_same(cli, data_dir, tmp_path):
    # the tool's usage errors (exit status 2) for options the module refuses above
    for args in (["--target", "0.5", "--keep", "0.5"], ["--target", "1"], ["--priority", "fast", "--target", "0.5"],
                 ["--max-error", "abc", "--target", "0.5"], ["--min-dihedral", "80", "--target", "0.5"]):
        p = cli.run("simplify", data_dir / "cube.mesh", *args, "-o", tmp_path / "x.mesh")
        assert p.returncode == 2, args


def test_simplify_max_error_forms(data_dir):
    points, tets, _ = read_medit(data_dir / "sphere.mesh")
    diagonal = np.linalg.norm(points.max(axis=0) - points.min(axis=0))
    r = prstar.simplify((points, tets), target=0.3, max_error="0.5%")
    assert math.isclose(r.statistics["boundary_error"]["bound"], 0.005 * diagonal, rel_tol=1e-12)
    assert r.statistics["boundary_error"]["relative"] * diagonal <= 0.005 * diagonal * 1.05
    for none in (None, "none", "inf", math.inf):
        assert prstar.simplify((points, tets), target=0.3, max_error=none).statistics["boundary_error"]["bound"] == math.inf
    assert prstar.simplify((points, tets), target=0.3, max_error="0.01").statistics["boundary_error"]["bound"] == 0.01


def test_simplify_bad_arrays():
    points, tets = grid_mesh(2)
    with pytest.raises(ValueError, match="points: shape"):
        prstar.simplify((points[:, :2], tets), target=0.5)
    with pytest.raises(ValueError, match="tetrahedra: shape"):
        prstar.simplify((points, tets[:, :3]), target=0.5)
    with pytest.raises(ValueError, match="tetrahedra: dtype"):
        prstar.simplify((points, tets.astype(np.float64)), target=0.5)
    with pytest.raises(ValueError, match="points: dtype"):
        prstar.simplify((points.astype(str), tets), target=0.5)
    with pytest.raises(ValueError, match="labels"):
        prstar.simplify(prstar.Mesh(points, tets, np.zeros(3, np.int32)), target=0.5)
    bad = tets.copy()
    bad[0, 0] = -1
    with pytest.raises(prstar.InvalidMeshError):
        prstar.simplify((points, bad), target=0.5)
    with pytest.raises(TypeError):
        prstar.simplify(points, target=0.5)
    with pytest.raises(TypeError):
        prstar.simplify((points, tets), target=[0.5])
