# Copyright (c) 2026 The PR-star octree project.
# SPDX-License-Identifier: LGPL-3.0-or-later
"""prstar.critical_points and prstar.morse_complexes against the prstar tool (``critical --json``,
``morse --json --csv -o --arcs``, its files read back with VTK's Python bindings) on the same files
and fields, for several bucket sizes and thread counts; the critical types against a brute force in
numpy (lower and upper links from the tetrahedra, ties broken by the vertex index); the errors."""

from __future__ import annotations

import csv
import math
from pathlib import Path
from typing import Any, Dict, List, Optional, Tuple

import numpy as np
import pytest

import prstar

meshio = pytest.importorskip("meshio")

# ---------------------------------------------------------------------------------------------
# meshes and fields
# ---------------------------------------------------------------------------------------------

#: the generated meshes compared on (the small ones: the whole file runs in well under a minute)
MESHES = ["cube.mesh", "torus.mesh", "cube_tetgen.vtu", "sphere.mesh"]


def load(path: Path) -> prstar.Mesh:
    """The mesh as meshio reads it (the tetrahedra only), independently of the package's readers."""
    m = meshio.read(str(path))
    tets = np.concatenate([c.data for c in m.cells if c.type == "tetra"])
    return prstar.Mesh(np.asarray(m.points, dtype=np.float64), tets,
                       point_data={k: np.asarray(v, dtype=np.float64) for k, v in m.point_data.items()
                                   if np.asarray(v).ndim == 1})


def bumps(points: np.ndarray) -> np.ndarray:
    """A sum of Gaussian bumps, up and down, over the unit cube: several extrema and saddles."""
    centres = np.array([[0.2, 0.1, 0.0], [-0.25, 0.2, 0.1], [0.1, -0.3, -0.2], [-0.2, -0.2, 0.25],
                        [0.3, 0.3, -0.3]])
    heights = np.array([1.0, 0.8, -0.9, 0.6, -0.5])
    d2 = ((points[:, None, :] - centres[None, :, :]) ** 2).sum(axis=2)
    return (heights[None, :] * np.exp(-d2 / 0.03)).sum(axis=1)


@pytest.fixture(scope="session")
def bumps_vtu(data_dir: Path, tmp_path_factory) -> Path:
    """cube_tetgen.vtu with two point-data arrays written by meshio: 'bumps' (first, the default
    field) and 'waves'."""
    m = load(data_dir / "cube_tetgen.vtu")
    p = m.points
    waves = np.sin(7 * p[:, 0]) * np.cos(5 * p[:, 1]) + 0.3 * p[:, 2]
    path = tmp_path_factory.mktemp("topology") / "bumps.vtu"
    meshio.write(str(path), meshio.Mesh(p, [("tetra", m.tetrahedra)],
                                        point_data={"bumps": bumps(p), "waves": waves}))
    return path


def mesh_path(name: str, data_dir: Path, bumps_vtu: Path) -> Path:
    return bumps_vtu if name == "bumps.vtu" else data_dir / name


def cli_options(field: Optional[str], kv: Any, threads: Optional[int]) -> List[str]:
    args = [] if field is None else ["--field", field]
    args += ["--kv", "inf" if kv == math.inf else str(kv)]
    if threads is not None:
        args += ["--threads", str(threads)]
    return args


# ---------------------------------------------------------------------------------------------
# files of the CLI read back with VTK
# ---------------------------------------------------------------------------------------------


def read_vtu(path: Path) -> Dict[str, Any]:
    vtk_xml = pytest.importorskip("vtkmodules.vtkIOXML")
    from vtkmodules.util.numpy_support import vtk_to_numpy

    r = vtk_xml.vtkXMLUnstructuredGridReader()
    r.SetFileName(str(path))
    r.Update()
    g = r.GetOutput()
    cells = g.GetCells()
    conn = vtk_to_numpy(cells.GetConnectivityArray()).reshape(-1, 4)
    pd, cd = g.GetPointData(), g.GetCellData()
    return {
        "tetrahedra": conn,
        "point": {pd.GetArrayName(i): vtk_to_numpy(pd.GetArray(i)) for i in range(pd.GetNumberOfArrays())},
        "cell": {cd.GetArrayName(i): vtk_to_numpy(cd.GetArray(i)) for i in range(cd.GetNumberOfArrays())},
    }


def read_vtp(path: Path) -> Dict[str, Any]:
    vtk_xml = pytest.importorskip("vtkmodules.vtkIOXML")
    from vtkmodules.util.numpy_support import vtk_to_numpy

    r = vtk_xml.vtkXMLPolyDataReader()
    r.SetFileName(str(path))
    r.Update()
    p = r.GetOutput()
    lines = p.GetLines()
    cd = p.GetCellData()
    return {
        "points": vtk_to_numpy(p.GetPoints().GetData()) if p.GetNumberOfPoints() else np.zeros((0, 3)),
        "connectivity": vtk_to_numpy(lines.GetConnectivityArray()),
        "offsets": vtk_to_numpy(lines.GetOffsetsArray()),
        "cell": {cd.GetArrayName(i): vtk_to_numpy(cd.GetArray(i)) for i in range(cd.GetNumberOfArrays())},
    }


def user_order_of_written_tetrahedra(user_tets: np.ndarray, written: np.ndarray) -> np.ndarray:
    """For each tetrahedron of a file the CLI wrote (in the octree's order), the user's index of the
    same tetrahedron (matched by its vertex set)."""
    index = {tuple(t): i for i, t in enumerate(np.sort(np.asarray(user_tets, dtype=np.int64), axis=1).tolist())}
    return np.array([index[tuple(t)] for t in np.sort(written.astype(np.int64), axis=1).tolist()])


def normalise_kv(counts: Dict[str, Any]) -> Dict[str, Any]:
    c = dict(counts)
    if c.get("kv") == "inf":
        c["kv"] = math.inf
    return c


# ---------------------------------------------------------------------------------------------
# critical points against `prstar critical`
# ---------------------------------------------------------------------------------------------

# (mesh, field, bucket size, threads): every mesh with x at the CLI's defaults, and the bump field
# (the default: the file's first array) over the grid of bucket sizes and threads
CRITICAL_CASES = [(m, "x", 50, None) for m in MESHES] + [
    ("bumps.vtu", None, kv, th) for kv in (1, 8, 50, math.inf) for th in (1, 2)
] + [("bumps.vtu", "waves", 8, 2), ("cube.mesh", "z", 1, 2), ("torus.mesh", "y", math.inf, 1)]


@pytest.mark.parametrize("name,field,kv,threads", CRITICAL_CASES)
def test_critical_points_match_cli(cli, data_dir, bumps_vtu, tmp_path, name, field, kv, threads):
    path = mesh_path(name, data_dir, bumps_vtu)
    out = tmp_path / "critical.vtu"
    j = cli.json("critical", path, "--gradient", "-o", out, *cli_options(field, kv, threads))
    mesh = load(path)
    r = prstar.critical_points(mesh, field, gradient=True, bucket_size=kv, threads=threads)

    # the counts: every key of the CLI's --json but the timing, the files and the list of points
    expected = normalise_kv({k: v for k, v in j.items() if k not in ("seconds", "output", "critical_points")})
    assert r.counts == expected
    assert r.euler_characteristic == j["gradient"]["euler_characteristic"]

    # the critical points, one by one
    cps = j["critical_points"]
    assert r.vertices.tolist() == [c["vertex"] for c in cps]
    assert [prstar.CRITICAL_TYPE_NAMES[t] for t in r.types[r.vertices]] == [c["type"] for c in cps]
    assert r.lower_components.tolist() == [c["lower_components"] for c in cps]
    assert r.upper_components.tolist() == [c["upper_components"] for c in cps]
    assert r.on_boundary.tolist() == [c["boundary"] for c in cps]
    assert r.values.tolist() == [c["value"] for c in cps]
    assert r.types.dtype == np.int8 and r.types.shape == (mesh.number_of_vertices,)

    # per vertex, against the critical_type array of the mesh the CLI wrote (user's vertex order)
    written = read_vtu(out)
    np.testing.assert_array_equal(r.types, written["point"]["critical_type"].astype(np.int8))
    np.testing.assert_array_equal(r.lower_components, written["point"]["lower_components"][r.vertices])
    np.testing.assert_array_equal(r.upper_components, written["point"]["upper_components"][r.vertices])

    # the gradient's critical simplices: as many of each dimension as the counts say
    cs = r.critical_simplices
    g = j["gradient"]
    assert np.bincount(cs["dimension"], minlength=4).tolist() == [
        g["critical_vertices"], g["critical_edges"], g["critical_triangles"], g["critical_tetrahedra"]]
    assert ((cs["vertices"] >= 0).sum(axis=1) == cs["dimension"] + 1).all()


# ---------------------------------------------------------------------------------------------
# Morse complexes against `prstar morse`
# ---------------------------------------------------------------------------------------------

MORSE_CASES = [(m, "x", 50, None, 0) for m in MESHES] + [
    ("bumps.vtu", None, kv, th, "5%") for kv in (1, 8, 50, math.inf) for th in (1, 2)
] + [("bumps.vtu", "waves", 8, 2, "0%"), ("bumps.vtu", "waves", 50, 1, "12.5%"), ("cube.mesh", "x", 1, 2, "5%"),
     ("cube_tetgen.vtu", "z", math.inf, 1, "2%")]


def read_pairs_csv(path: Path) -> List[Dict[str, str]]:
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def check_morse(r: prstar.MorseResult, j: Dict[str, Any], mesh: prstar.Mesh, tmp_path: Path) -> None:
    """``r`` against the CLI's --json ``j`` and its files cells.vtu, pairs.csv, arcs.vtp in tmp_path."""
    expected = normalise_kv({k: v for k, v in j.items()
                             if k not in ("seconds", "output", "csv", "arcs_file", "pairs", "persistence")})
    got = {k: v for k, v in r.counts.items() if k != "persistence"}
    assert got == expected

    # the pairs, against the JSON (null for essential pairs) and the CSV (birth, death)
    p = r.pairs
    jp = j["pairs"]
    kind_name = ["minimum-saddle", "saddle-maximum"]
    assert [kind_name[k] for k in p["kind"]] == [q["type"] for q in jp]
    assert p["extremum"].tolist() == [q["extremum"] for q in jp]
    assert p["saddle"].tolist() == [-1 if q["saddle"] is None else q["saddle"] for q in jp]
    assert p["essential"].tolist() == [q["saddle"] is None for q in jp]
    assert p["extremum_value"].tolist() == [q["extremum_value"] for q in jp]
    assert [None if e else v for e, v in zip(p["essential"], p["saddle_value"].tolist())] == \
        [q["saddle_value"] for q in jp]
    assert [None if e else v for e, v in zip(p["essential"], p["persistence"].tolist())] == \
        [q["persistence"] for q in jp]
    rows = read_pairs_csv(tmp_path / "pairs.csv")
    assert len(rows) == len(jp)
    assert p["birth"].tolist() == [float(row["birth"]) for row in rows]
    assert p["death"].tolist() == [float(row["death"]) for row in rows]
    assert p["persistence"].tolist() == [float(row["persistence"]) for row in rows]
    assert np.isinf(p["persistence"][p["essential"]]).all()
    structured = r.pairs_array()
    assert structured.dtype.names == tuple(p) and (structured["extremum"] == p["extremum"]).all()

    # the cells, against the arrays of the mesh the CLI wrote (its tetrahedra in the octree's order)
    written = read_vtu(tmp_path / "cells.vtu")
    np.testing.assert_array_equal(r.ascending_cell, written["point"]["ascending_cell"].astype(np.int64))
    np.testing.assert_array_equal(r.critical_types, written["point"]["critical_type"].astype(np.int8))
    slot = user_order_of_written_tetrahedra(mesh.tetrahedra, written["tetrahedra"])
    assert sorted(slot.tolist()) == list(range(mesh.number_of_tetrahedra))
    np.testing.assert_array_equal(r.descending_cell[slot], written["cell"]["descending_cell"].astype(np.int64))
    assert r.ascending_cell.shape == (mesh.number_of_vertices,)
    assert r.descending_cell.shape == (mesh.number_of_tetrahedra,)
    # the cells are labelled by extrema: the ascending ones by minima, as many as the counts say
    cells = np.unique(r.ascending_cell[r.ascending_cell >= 0])
    assert len(cells) == j["ascending_cells"]
    assert (r.critical_types[cells] == prstar.MINIMUM).all()
    assert (r.descending_cell == -1).sum() == j["outflow_tetrahedra"]

    # the arcs, against the .vtp: the same polylines, with the same cell arrays
    a = r.arcs
    vtp = read_vtp(tmp_path / "arcs.vtp")
    assert len(a) == j["arcs"] == len(vtp["offsets"]) - 1
    np.testing.assert_array_equal(a.offsets, vtp["offsets"])
    np.testing.assert_array_equal(vtp["connectivity"], np.arange(len(a.points)))
    np.testing.assert_allclose(a.points, vtp["points"], rtol=1e-15, atol=0)
    for key in ("saddle_dimension", "saddle", "saddle_vertex", "extremum", "saddle_value"):
        np.testing.assert_array_equal(getattr(a, key), vtp["cell"][key], err_msg=key)
    if len(a):
        assert np.array_equal(a[0], a.points[a.offsets[0]:a.offsets[1]]) and len(list(a)) == len(a)
        cs = r.critical_simplices
        assert (cs["dimension"][a.saddle] == a.saddle_dimension).all()
        assert (cs["vertices"][a.saddle, 0] == a.saddle_vertex).all()


@pytest.mark.parametrize("name,field,kv,threads,persistence", MORSE_CASES)
def test_morse_complexes_match_cli(cli, data_dir, bumps_vtu, tmp_path, name, field, kv, threads, persistence):
    path = mesh_path(name, data_dir, bumps_vtu)
    j = cli.json("morse", path, "--persistence", str(persistence), "--csv", tmp_path / "pairs.csv",
                 "-o", tmp_path / "cells.vtu", "--arcs", tmp_path / "arcs.vtp", *cli_options(field, kv, threads))
    mesh = load(path)
    r = prstar.morse_complexes(mesh, field, persistence=persistence, bucket_size=kv, threads=threads)
    check_morse(r, j, mesh, tmp_path)
    assert r.counts["persistence"] == j["persistence"]
    # the same threshold given as an absolute number: the same complexes
    absolute = prstar.morse_complexes(mesh, field, threshold=j["threshold"], bucket_size=kv, threads=threads)
    assert absolute.threshold == j["threshold"]
    check_morse(absolute, j, mesh, tmp_path)


@pytest.mark.parametrize("name,field", [("bunny_sofa.vtu", "z"), ("armadillo_sofa.vtu", "x"),
                                        ("t13_data.1.ele", "z")])
def test_real_meshes_match_cli(cli, shared_data, tmp_path, name, field):
    """Real meshes of ../shared/data (skipped without it): both functions against the CLI.  They are
    rewritten as float64 .vtu first, so that both sides read the same coordinates (the CLI parses an
    ASCII Float32 array as doubles, meshio as float32)."""
    original = load(shared_data / name)
    path = tmp_path / "real.vtu"
    meshio.write(str(path), meshio.Mesh(original.points, [("tetra", original.tetrahedra)]))
    mesh = load(path)
    j = cli.json("critical", path, "--gradient", "--field", field, "--kv", "8")
    r = prstar.critical_points(mesh, field, gradient=True, bucket_size=8, threads=2)
    assert r.counts == normalise_kv({k: v for k, v in j.items() if k not in ("seconds", "critical_points")})
    assert r.vertices.tolist() == [c["vertex"] for c in j["critical_points"]]
    assert [prstar.CRITICAL_TYPE_NAMES[t] for t in r.types[r.vertices]] == [c["type"] for c in j["critical_points"]]
    j = cli.json("morse", path, "--field", field, "--persistence", "3%", "--csv", tmp_path / "pairs.csv",
                 "-o", tmp_path / "cells.vtu", "--arcs", tmp_path / "arcs.vtp")
    check_morse(prstar.morse_complexes(mesh, field, persistence="3%", threads=1), j, mesh, tmp_path)


def test_cancellation_merges_cells(data_dir, bumps_vtu):
    """Above a threshold, each cancelled minimum's cell is gone and the kept ones are those of the pairs
    at least that persistent (independent of the CLI: from the pairs of the full complexes)."""
    mesh = load(bumps_vtu)
    full = prstar.morse_complexes(mesh, "waves", arcs=False)
    assert full.arcs is None and "arcs" not in full.counts
    pers = np.sort(full.pairs["persistence"][(full.pairs["kind"] == prstar.MINIMUM_SADDLE)
                                             & ~full.pairs["essential"]])
    t = float(pers[len(pers) // 2]) if len(pers) else 0.0
    cut = prstar.morse_complexes(mesh, "waves", threshold=t, arcs=False)
    minima = full.pairs["kind"] == prstar.MINIMUM_SADDLE
    kept = full.pairs["extremum"][minima & ~(full.pairs["persistence"] < t)]
    assert sorted(np.unique(cut.ascending_cell).tolist()) == sorted(kept.tolist())
    # a cell after the cancellations is a union of cells before them
    for c in np.unique(full.ascending_cell):
        assert len(np.unique(cut.ascending_cell[full.ascending_cell == c])) == 1


# ---------------------------------------------------------------------------------------------
# brute force in numpy
# ---------------------------------------------------------------------------------------------


def kuhn_grid(n: int) -> Tuple[np.ndarray, np.ndarray]:
    """The unit cube cut into n^3 cubes of 6 tetrahedra each (Kuhn's subdivision)."""
    g = np.arange(n + 1)
    points = np.stack(np.meshgrid(g, g, g, indexing="ij"), axis=-1).reshape(-1, 3).astype(np.float64) / n
    idx = lambda i, j, k: (i * (n + 1) + j) * (n + 1) + k  # noqa: E731
    tets = []
    perms = [(0, 1, 2), (0, 2, 1), (1, 0, 2), (1, 2, 0), (2, 0, 1), (2, 1, 0)]
    for i in range(n):
        for j in range(n):
            for k in range(n):
                for p in perms:
                    c = [i, j, k]
                    t = [idx(*c)]
                    for axis in p:
                        c[axis] += 1
                        t.append(idx(*c))
                    tets.append(t)
    return points, np.array(tets, dtype=np.int64)


def brute_force_links(tets: np.ndarray, f: np.ndarray) -> Tuple[np.ndarray, np.ndarray]:
    """The numbers of connected components of the lower and upper link of every vertex: the link is
    the triangles opposite the vertex in its tetrahedra; a link vertex u is lower when (f[u], u) <
    (f[v], v)."""
    n = len(f)
    rank = np.empty(n, dtype=np.int64)
    rank[np.lexsort((np.arange(n), f))] = np.arange(n)
    link: List[List[Tuple[int, int, int]]] = [[] for _ in range(n)]
    for t in tets.tolist():
        for i in range(4):
            link[t[i]].append(tuple(t[:i] + t[i + 1:]))
    lower = np.zeros(n, dtype=np.int64)
    upper = np.zeros(n, dtype=np.int64)

    def components(triangles, keep) -> int:
        parent: Dict[int, int] = {}

        def find(x: int) -> int:
            while parent[x] != x:
                parent[x] = parent[parent[x]]
                x = parent[x]
            return x

        for tri in triangles:
            for u in tri:
                if keep(u):
                    parent.setdefault(u, u)
            for a, b in ((tri[0], tri[1]), (tri[1], tri[2]), (tri[0], tri[2])):
                if keep(a) and keep(b):
                    parent[find(a)] = find(b)
        return len({find(u) for u in parent})

    for v in range(n):
        lower[v] = components(link[v], lambda u: rank[u] < rank[v])
        upper[v] = components(link[v], lambda u: rank[u] > rank[v])
    return lower, upper


def classify(lower: int, upper: int) -> int:
    if lower == 0 and upper == 0:
        return prstar.REGULAR
    if lower == 0:
        return prstar.MINIMUM
    if upper == 0:
        return prstar.MAXIMUM
    if (lower, upper) == (1, 1):
        return prstar.REGULAR
    if (lower, upper) == (2, 1):
        return prstar.SADDLE1
    if (lower, upper) == (1, 2):
        return prstar.SADDLE2
    return prstar.DEGENERATE


def euler_characteristic(tets: np.ndarray) -> int:
    t = np.sort(tets, axis=1)
    faces = {tuple(x) for x in np.concatenate([t[:, [0, 1, 2]], t[:, [0, 1, 3]], t[:, [0, 2, 3]],
                                               t[:, [1, 2, 3]]]).tolist()}
    edges = {tuple(x) for x in np.concatenate([t[:, [a, b]] for a in range(4) for b in range(a + 1, 4)]).tolist()}
    return len(np.unique(t)) - len(edges) + len(faces) - len(t)


def boundary_vertices(tets: np.ndarray) -> np.ndarray:
    t = np.sort(tets, axis=1)
    faces = np.concatenate([t[:, [0, 1, 2]], t[:, [0, 1, 3]], t[:, [0, 2, 3]], t[:, [1, 2, 3]]])
    u, count = np.unique(faces, axis=0, return_counts=True)
    return np.unique(u[count == 1])


@pytest.mark.parametrize("case", ["grid_ties", "grid_random", "tetgen_rounded_x"])
def test_critical_types_brute_force(data_dir, case):
    rng = np.random.default_rng(21)
    if case.startswith("grid"):
        points, tets = kuhn_grid(5)
        # many ties (5 values): the order is (value, vertex index), simulation of simplicity
        f = rng.integers(0, 5, len(points)).astype(np.float64) if case == "grid_ties" else rng.normal(size=len(points))
        # a vertex in no tetrahedron: regular, counted apart
        points = np.vstack([points, [[2.0, 2.0, 2.0]]])
        f = np.append(f, 0.5)
    else:
        mesh = load(data_dir / "cube_tetgen.vtu")
        points, tets = mesh.points, mesh.tetrahedra.astype(np.int64)
        f = np.round(points[:, 0] * 4)  # plateaus
    lower, upper = brute_force_links(tets, f)
    expected = np.array([classify(a, b) for a, b in zip(lower, upper)], dtype=np.int8)
    for kv, threads in ((1, 1), (8, 2), (math.inf, 2)):
        r = prstar.critical_points((points, tets), f, gradient=True, bucket_size=kv, threads=threads)
        np.testing.assert_array_equal(r.types, expected)
        np.testing.assert_array_equal(r.vertices, np.flatnonzero(expected != prstar.REGULAR))
        np.testing.assert_array_equal(r.lower_components, lower[r.vertices])
        np.testing.assert_array_equal(r.upper_components, upper[r.vertices])
        np.testing.assert_array_equal(r.values, f[r.vertices])
        np.testing.assert_array_equal(r.on_boundary, np.isin(r.vertices, boundary_vertices(tets)))
        names = ["minima", "saddles_1", "saddles_2", "maxima", "degenerate"]
        referenced = np.zeros(len(f), dtype=bool)
        referenced[tets.ravel()] = True
        for code, key in enumerate(names):
            assert r.counts[key] == int((expected[referenced] == code).sum()), key
        assert r.counts["regular"] == int((expected[referenced] == prstar.REGULAR).sum())
        assert r.counts["unreferenced"] == int((~referenced).sum())
        assert r.counts["join_multiplicity"] == int(np.maximum(lower[referenced] - 1, 0).sum())
        assert r.counts["split_multiplicity"] == int(np.maximum(upper[referenced] - 1, 0).sum())
        assert r.counts["field_min"] == f[referenced].min() and r.counts["field_max"] == f[referenced].max()
        assert r.euler_characteristic == euler_characteristic(tets)
        g = r.counts["gradient"]
        assert g["alternating_sum"] == g["euler_characteristic"]
        m = prstar.morse_complexes((points, tets), f, bucket_size=kv, threads=threads)
        np.testing.assert_array_equal(m.critical_types, expected)
        # every referenced vertex is in the ascending cell of a minimum; the unreferenced in none
        assert (m.ascending_cell[~referenced] == -1).all()
        assert (expected[m.ascending_cell[referenced]] == prstar.MINIMUM).all()
        # a minimum is in its own cell
        minima = np.flatnonzero(expected == prstar.MINIMUM)
        np.testing.assert_array_equal(m.ascending_cell[minima], minima)


# ---------------------------------------------------------------------------------------------
# inputs: an Octree, arrays, names; errors
# ---------------------------------------------------------------------------------------------


def test_inputs_agree(data_dir, bumps_vtu):
    mesh = load(bumps_vtu)
    by_name = prstar.critical_points(mesh, "waves")
    by_array = prstar.critical_points((mesh.points, mesh.tetrahedra), mesh.point_data["waves"])
    np.testing.assert_array_equal(by_name.types, by_array.types)
    assert by_name.counts["field"] == "waves" and by_array.counts["field"] is None
    # any numeric dtype and layout, read as float64
    f32 = np.asfortranarray(np.stack([mesh.point_data["waves"]] * 2, axis=1).astype(np.float32))[:, 1]
    np.testing.assert_array_equal(prstar.critical_points(mesh, f32).types,
                                  prstar.critical_points(mesh, f32.astype(np.float64)).types)
    assert prstar.critical_points(mesh).counts["field"] == "bumps"  # the first array by default
    tree = prstar.Octree(mesh.points, mesh.tetrahedra, field=mesh.point_data["bumps"], bucket_size=8)
    own = prstar.critical_points(tree)
    np.testing.assert_array_equal(own.types, prstar.critical_points(mesh, "bumps").types)
    m1 = prstar.morse_complexes(tree, persistence="5%")
    m2 = prstar.morse_complexes(mesh, "bumps", persistence="5%", bucket_size=8)
    for key in ("ascending_cell", "descending_cell", "critical_types"):
        np.testing.assert_array_equal(getattr(m1, key), getattr(m2, key))
    x = prstar.critical_points(mesh, "x")
    np.testing.assert_array_equal(x.types, prstar.critical_points(mesh, mesh.points[:, 0].copy()).types)
    calls = []
    prstar.morse_complexes(mesh, "bumps", bucket_size=8, progress=lambda d, t: calls.append((d, t)))
    assert calls and calls[-1][0] == calls[-1][1]


def test_errors(data_dir, bumps_vtu):
    mesh = load(bumps_vtu)
    n = mesh.number_of_vertices
    nan = mesh.point_data["bumps"].copy()
    nan[7] = np.nan
    for function in (prstar.critical_points, prstar.morse_complexes):
        with pytest.raises(ValueError, match="vertex 7"):
            function(mesh, nan)
        with pytest.raises(ValueError, match="not finite"):
            function(mesh, np.where(np.arange(n) == 3, np.inf, 0.0))
        with pytest.raises(ValueError, match=f"{n - 1} values for {n} vertices"):
            function(mesh, np.zeros(n - 1))
        with pytest.raises(ValueError, match="no point-data array 'pressure'"):
            function(mesh, "pressure")
        with pytest.raises(ValueError, match="a name needs a prstar.Mesh"):
            function((mesh.points, mesh.tetrahedra), "bumps")
        with pytest.raises(ValueError, match="field"):
            function(mesh, np.zeros((n, 2)))
        with pytest.raises(ValueError, match="bucket_size"):
            function(mesh, "x", bucket_size=0)
        with pytest.raises(ValueError, match="threads"):
            function(mesh, "x", threads=0)
    tree = prstar.Octree(mesh.points, mesh.tetrahedra)
    with pytest.raises(ValueError, match="no field"):
        prstar.critical_points(tree)
    for bad in ("5", "abc%", "101%", "-1%", -0.5, 1.5, math.inf, math.nan):
        with pytest.raises(ValueError, match="persistence"):
            prstar.morse_complexes(mesh, "x", persistence=bad)
    with pytest.raises(TypeError, match="persistence"):
        prstar.morse_complexes(mesh, "x", persistence=[1])
    for bad in (-1.0, math.inf, math.nan):
        with pytest.raises(ValueError, match="threshold"):
            prstar.morse_complexes(mesh, "x", threshold=bad)
    with pytest.raises(ValueError, match="not both"):
        prstar.morse_complexes(mesh, "x", persistence="5%", threshold=0.1)
    # a fraction and the same percentage: the same threshold, as the CLI's 0.05 and 5%
    assert prstar.morse_complexes(mesh, "x", persistence=0.05, arcs=False).threshold == \
        prstar.morse_complexes(mesh, "x", persistence="5%", arcs=False).threshold

    def stop(done, total):
        raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        prstar.critical_points(mesh, "x", bucket_size=1, progress=stop)
    bad = mesh.tetrahedra.copy()
    bad[0, 0] = n + 5
    with pytest.raises(prstar.InvalidMeshError):
        prstar.critical_points((mesh.points, bad), "x")
