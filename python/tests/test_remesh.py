# Copyright (c) 2026 The PR-star octree project.
# SPDX-License-Identifier: LGPL-3.0-or-later
"""prstar.remesh and the quality options of prstar.simplify (both floors, the ceiling, optimize) against
the prstar tool on the same files (every number of their --json, the mesh the tool writes, read back by
meshio and VTK) and against brute force in numpy: orientation by signed volumes, conformity and a
closed boundary by counting faces and edges, Euler characteristic, volume and area of the unit cube
(closed forms), the labels' volumes, the distance of the boundary to the cube's faces, dihedral angles
and radius ratios, and the edge lengths against the target (the share in [0.8 h, 1.33 h] recomputed)."""

from __future__ import annotations

import itertools
import json
import math
from pathlib import Path
from typing import Dict, Optional, Tuple

import numpy as np
import pytest

import prstar

# ---------------------------------------------------------------------------------------------
# Brute force
# ---------------------------------------------------------------------------------------------

EDGE_PAIRS = [[0, 1], [0, 2], [0, 3], [1, 2], [1, 3], [2, 3]]
FACES = [[1, 2, 3], [0, 3, 2], [0, 1, 3], [0, 2, 1]]  # outward for a positive tetrahedron


def signed_volumes(points: np.ndarray, tets: np.ndarray) -> np.ndarray:
    p = np.asarray(points, float)[np.asarray(tets, np.int64)]
    return np.einsum("ij,ij->i", np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]), p[:, 3] - p[:, 0]) / 6


def edges_of(tets: np.ndarray) -> np.ndarray:
    t = np.asarray(tets, np.int64)
    return np.unique(np.sort(t[:, EDGE_PAIRS].reshape(-1, 2), axis=1), axis=0)


def boundary_faces(tets: np.ndarray) -> Tuple[np.ndarray, np.ndarray]:
    """(the faces in exactly one tetrahedron, oriented outward, as listed; the number of tetrahedra of
    every distinct face)."""
    t = np.asarray(tets, np.int64)
    faces = t[:, FACES].reshape(-1, 3)
    key = np.sort(faces, axis=1)
    _, first, inverse, count = np.unique(key, axis=0, return_index=True, return_inverse=True, return_counts=True)
    once = count[inverse.ravel()] == 1
    return faces[once], count


def surface_area_and_volume(points: np.ndarray, tets: np.ndarray) -> Tuple[float, float]:
    """The area of the boundary triangles, and the volume they enclose (divergence theorem, from the
    triangles alone, not from the tetrahedra)."""
    b, _ = boundary_faces(tets)
    p = np.asarray(points, float)[b]
    n = np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0])
    return float(np.linalg.norm(n, axis=1).sum() / 2), float(np.einsum("ij,ij->i", n, p[:, 0]).sum() / 6)


def dihedral_angles(points: np.ndarray, tets: np.ndarray) -> np.ndarray:
    """(m, 6) the dihedral angles in degrees, from the outward normals of the faces."""
    p = np.asarray(points, float)[np.asarray(tets, np.int64)]
    normals = []
    for k in range(4):
        a, b, c = (p[:, i] for i in range(4) if i != k)
        n = np.cross(b - a, c - a)
        n *= np.where(np.einsum("ij,ij->i", n, p[:, k] - a) > 0, -1.0, 1.0)[:, None]
        normals.append(n / np.linalg.norm(n, axis=1)[:, None])
    return np.stack([np.degrees(np.pi - np.arccos(np.clip(np.einsum("ij,ij->i", normals[k], normals[l]), -1, 1)))
                     for k, l in itertools.combinations(range(4), 2)], axis=1)


def radius_ratios(points: np.ndarray, tets: np.ndarray) -> np.ndarray:
    """3 r / R: r = 3 V / (area of the faces), R from the circumcentre in closed form."""
    p = np.asarray(points, float)[np.asarray(tets, np.int64)]
    u, v, w = p[:, 1] - p[:, 0], p[:, 2] - p[:, 0], p[:, 3] - p[:, 0]
    six_v = np.einsum("ij,ij->i", u, np.cross(v, w))
    centre = ((u * u).sum(1)[:, None] * np.cross(v, w) + (v * v).sum(1)[:, None] * np.cross(w, u)
              + (w * w).sum(1)[:, None] * np.cross(u, v)) / (2 * six_v[:, None])
    big_r = np.linalg.norm(centre, axis=1)
    area = sum(np.linalg.norm(np.cross(p[:, f[1]] - p[:, f[0]], p[:, f[2]] - p[:, f[0]]), axis=1) / 2 for f in FACES)
    return 3 * (3 * np.abs(six_v) / 6 / area) / big_r


def edge_ratios(points: np.ndarray, tets: np.ndarray, target) -> np.ndarray:
    """length / target of every edge; `target` a number or one value per vertex (the mean of the ends')."""
    e = edges_of(tets)
    d = np.asarray(points, float)[e[:, 0]] - np.asarray(points, float)[e[:, 1]]
    length = np.sqrt(d[:, 0] * d[:, 0] + d[:, 1] * d[:, 1] + d[:, 2] * d[:, 2])
    h = target if np.isscalar(target) else (np.asarray(target)[e[:, 0]] + np.asarray(target)[e[:, 1]]) / 2
    return length / h


def check_valid_mesh(points: np.ndarray, tets: np.ndarray, euler: int) -> None:
    """Positive tetrahedra, a conforming mesh (every face in one or two tetrahedra), a closed
    manifold boundary (every boundary edge in two boundary triangles), every vertex used, the Euler
    characteristic."""
    t = np.asarray(tets, np.int64)
    assert t.min() >= 0 and t.max() < len(points)
    assert len(np.unique(t)) == len(points)
    assert np.all(signed_volumes(points, t) > 0)
    b, count = boundary_faces(t)
    assert count.max() <= 2
    _, edge_count = np.unique(np.sort(b[:, [[0, 1], [1, 2], [2, 0]]].reshape(-1, 2), axis=1), axis=0,
                              return_counts=True)
    assert np.all(edge_count == 2)
    chi = len(points) - len(edges_of(t)) + len(count) - len(t)
    assert chi == euler


# ---------------------------------------------------------------------------------------------
# The tool
# ---------------------------------------------------------------------------------------------


def as_module_statistics(expected: dict) -> dict:
    """The tool's JSON in the module's terms: "inf" and null bounds as math.inf, no seconds/output."""
    d = {k: v for k, v in expected.items() if k not in ("seconds", "output")}
    if d["kv"] == "inf":
        d["kv"] = math.inf
    if d["boundary_error"]["bound"] is None:
        d["boundary_error"] = dict(d["boundary_error"], bound=math.inf)
    return d


def without_seconds(d: dict) -> dict:
    return {k: v for k, v in d.items() if k != "seconds"}


def read_vtu(path: Path):
    """The tool's .vtu read by meshio: points, tetrahedra, cell data, point data."""
    meshio = pytest.importorskip("meshio")
    m = meshio.read(path)
    return m.points, m.get_cells_type("tetra"), {k: v[0] for k, v in m.cell_data.items()}, m.point_data


def assert_same_mesh(result_mesh: prstar.Mesh, path: Path) -> None:
    points, tets, cell_data, point_data = read_vtu(path)
    np.testing.assert_array_equal(result_mesh.points, points)
    np.testing.assert_array_equal(result_mesh.tetrahedra, tets)
    if result_mesh.labels is not None:
        np.testing.assert_array_equal(result_mesh.labels, cell_data["label"])
    for name, values in result_mesh.point_data.items():
        np.testing.assert_array_equal(values, point_data[name])


@pytest.fixture(scope="module")
def cube(data_dir) -> prstar.Mesh:
    """TetGen's unit cube [-0.5, 0.5]^3 (its boundary is the cube's: volume 1, area 6), two labels
    (x of the centroid below or above 0.1: a jagged interface) and a size field growing with x."""
    m = prstar.read(data_dir / "cube_tetgen.vtu")
    centroid_x = m.points[m.tetrahedra.astype(np.int64)].mean(axis=1)[:, 0]
    labels = np.where(centroid_x < 0.1, 1, 2).astype(np.int32)
    h = 0.05 + 0.15 * (m.points[:, 0] + 0.5)  # 0.05 at x = -0.5 to 0.2 at x = 0.5
    return prstar.Mesh(m.points, m.tetrahedra, labels, point_data={"h": h, "x2": m.points[:, 0] ** 2},
                       cell_data={"id": np.arange(m.number_of_tetrahedra, dtype=float)}, label_names={1: "left"})


@pytest.fixture(scope="module")
def cube_file(cube, tmp_path_factory) -> Path:
    path = tmp_path_factory.mktemp("remesh") / "cube.vtu"
    prstar.write(path, cube)
    back = prstar.read(path)  # what the tool reads is the module's mesh, bit for bit
    np.testing.assert_array_equal(back.points, cube.points)
    np.testing.assert_array_equal(back.point_data["h"], cube.point_data["h"])
    return path


def test_the_cube_is_the_unit_cube(cube):
    area, volume = surface_area_and_volume(cube.points, cube.tetrahedra)
    assert abs(volume - 1) < 1e-12 and abs(area - 6) < 1e-12
    assert np.all(np.abs(cube.points) <= 0.5)
    check_valid_mesh(cube.points, cube.tetrahedra, 1)


# ---------------------------------------------------------------------------------------------
# remesh against the tool and brute force
# ---------------------------------------------------------------------------------------------

# (name, Python options, the tool's options)
REMESH_CASES = [
    ("coarser", {"edge_length": 0.2}, ["--edge-length", "0.2"]),
    ("finer", {"edge_length": "6%", "iterations": 3}, ["--edge-length", "6%", "--iterations", "3"]),
    ("floors", {"edge_length": 0.15, "iterations": 3, "min_dihedral": 10, "max_dihedral": 160,
                "min_radius_ratio": 0.2, "max_error": "0.5%", "bucket_size": 20, "feature_angle": 60},
     ["--edge-length", "0.15", "--iterations", "3", "--min-dihedral", "10", "--max-dihedral", "160",
      "--min-radius-ratio", "0.2", "--max-error", "0.5%", "--kv", "20", "--feature-angle", "60"]),
    ("size_field", {"size_field": "h"}, ["--size-field", "h"]),
]


@pytest.fixture(scope="module")
def remeshed(cli, cube, cube_file, tmp_path_factory) -> Dict[str, Tuple[prstar.RemeshResult, dict, Path]]:
    """Each case run once by the module and once by the tool."""
    out = {}
    folder = tmp_path_factory.mktemp("remeshed")
    for name, options, args in REMESH_CASES:
        path = folder / f"{name}.vtu"
        expected = cli.json("remesh", cube_file, *args, "-o", path)
        out[name] = (prstar.remesh(cube, **options), expected, path)
    return out


@pytest.mark.parametrize("case", [c[0] for c in REMESH_CASES])
def test_remesh_equals_cli(remeshed, case):
    r, expected, path = remeshed[case]
    assert without_seconds(r.statistics) == as_module_statistics(expected)
    assert set(r.statistics) == set(expected) - {"output"}
    assert_same_mesh(r.mesh, path)
    assert r.mesh.points.dtype == np.float64 and r.mesh.tetrahedra.dtype == np.uint32
    assert len(r.input_vertex) == len(r.mesh.points) and len(r.input_tetrahedron) == len(r.mesh.tetrahedra)
    assert str(r).startswith("remeshed to ")


@pytest.mark.parametrize("case", [c[0] for c in REMESH_CASES])
def test_remesh_brute_force(remeshed, cube, case):
    r, _, _ = remeshed[case]
    m, s = r.mesh, r.statistics
    check_valid_mesh(m.points, m.tetrahedra, 1)
    assert (s["output_vertices"], s["output_tetrahedra"]) == (len(m.points), len(m.tetrahedra))
    # the boundary: on the cube's faces within the bound (the distance of a point on or near the
    # surface to it is at least | max(|x|, |y|, |z|) - 0.5 |), volume and area of the cube
    bound = s["boundary_error"]["bound"]
    b, _ = boundary_faces(m.tetrahedra)
    on_surface = np.abs(np.abs(m.points[np.unique(b)]).max(axis=1) - 0.5)
    assert on_surface.max() <= bound
    area, volume = surface_area_and_volume(m.points, m.tetrahedra)
    assert abs(volume - 1) <= 6 * bound  # the surface moved by at most the bound
    assert abs(signed_volumes(m.points, m.tetrahedra).sum() - volume) < 1e-12  # the tetrahedra fill it
    assert abs(area - 6) <= 0.05 * 6
    # each label's volume: its surface (boundary and interface) moved by at most the bound
    vol_in = signed_volumes(cube.points, cube.tetrahedra)
    vol_out = signed_volumes(m.points, m.tetrahedra)
    for label in (1, 2):
        a, c = vol_in[cube.labels == label].sum(), vol_out[m.labels == label].sum()
        assert abs(a - c) <= 10 * bound, (label, a, c)
    # the labels and data carried, as the input vertex and tetrahedron of each output one say
    np.testing.assert_array_equal(m.labels, cube.labels[r.input_tetrahedron])
    np.testing.assert_array_equal(m.point_data["h"], cube.point_data["h"][r.input_vertex])
    np.testing.assert_array_equal(m.cell_data["id"], r.input_tetrahedron.astype(float))
    assert m.label_names == {1: "left"}
    # the quality the statistics report, recomputed
    angles = dihedral_angles(m.points, m.tetrahedra)
    q = s["output_quality"]
    assert math.isclose(q["min_dihedral"], angles.min(), rel_tol=1e-9)
    assert math.isclose(q["max_dihedral"], angles.max(), rel_tol=1e-9)
    assert q["share_under_10"] == np.mean(angles.min(axis=1) < 10)
    assert math.isclose(q["min_radius_ratio"], radius_ratios(m.points, m.tetrahedra).min(), rel_tol=1e-9)


@pytest.mark.parametrize("case", [c[0] for c in REMESH_CASES])
def test_remesh_edge_lengths(remeshed, cube, case):
    r, expected, _ = remeshed[case]
    m, s = r.mesh, r.statistics
    if s["edge_length"] is not None:
        h_in = h_out = s["edge_length"]
        if case == "finer":  # 6% of the diagonal of the unit cube
            assert h_in == 0.06 * math.sqrt(3)
    else:
        h_in, h_out = cube.point_data["h"], m.point_data["h"]  # the field, as the output carries it
    for key, points, tets, h in (("input_edges", cube.points, cube.tetrahedra, h_in),
                                 ("output_edges", m.points, m.tetrahedra, h_out)):
        ratio = edge_ratios(points, tets, h)
        e = expected[key]
        assert e["edges"] == len(ratio)
        assert e["share_in_range"] == np.count_nonzero((ratio >= 0.8) & (ratio <= 1.33)) / len(ratio)
        assert e["share_short"] == np.count_nonzero(ratio < 0.8) / len(ratio)
        assert e["share_long"] == np.count_nonzero(ratio > 1.33) / len(ratio)
        assert e["median_ratio"] == np.median(ratio)
    # the target differs from the input's edges (mean 0.13): remeshing brings more of them in range
    assert expected["output_edges"]["share_in_range"] > expected["input_edges"]["share_in_range"] + 0.1
    assert 0.8 < expected["output_edges"]["median_ratio"] < 1.33


def test_remesh_size_field_grades_the_edges(remeshed):
    r, _, _ = remeshed["size_field"]
    m = r.mesh
    e = edges_of(m.tetrahedra)
    middle_x = (m.points[e[:, 0], 0] + m.points[e[:, 1], 0]) / 2
    length = np.linalg.norm(m.points[e[:, 0]] - m.points[e[:, 1]], axis=1)
    small, large = length[middle_x < -0.25].mean(), length[middle_x > 0.25].mean()
    # the target is 0.05 to 0.125 on the left, 0.125 to 0.2 on the right
    assert small < 0.75 * large, (small, large)
    # a uniform target at the field's mean brings fewer edges into the field's range
    uniform, _, _ = remeshed["coarser"]
    ratio = edge_ratios(uniform.mesh.points, uniform.mesh.tetrahedra, uniform.mesh.point_data["h"])
    share_uniform = np.count_nonzero((ratio >= 0.8) & (ratio <= 1.33)) / len(ratio)
    assert r.statistics["output_edges"]["share_in_range"] > share_uniform


def test_remesh_refines_and_coarsens(remeshed, cube):
    n = cube.number_of_tetrahedra
    coarser, finer = remeshed["coarser"][0].statistics, remeshed["finer"][0].statistics
    assert coarser["output_tetrahedra"] < n < finer["output_tetrahedra"]
    assert finer["operations"]["splits"] > 0 and coarser["operations"]["collapses"] > 0


def test_remesh_cli_output_read_by_vtk(remeshed, cube):
    vtk = pytest.importorskip("vtkmodules.vtkIOXML")
    from vtkmodules.util.numpy_support import vtk_to_numpy
    r, _, path = remeshed["size_field"]
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(str(path))
    reader.Update()
    grid = reader.GetOutput()
    assert grid.GetNumberOfCells() == r.statistics["output_tetrahedra"]
    np.testing.assert_array_equal(vtk_to_numpy(grid.GetPoints().GetData()), r.mesh.points)
    np.testing.assert_array_equal(vtk_to_numpy(grid.GetCellData().GetArray("label")), cube.labels[r.input_tetrahedron])
    for name in ("h", "x2"):
        np.testing.assert_array_equal(vtk_to_numpy(grid.GetPointData().GetArray(name)),
                                      cube.point_data[name][r.input_vertex])


def test_remesh_inputs_agree(cube):
    by_mesh = prstar.remesh(cube, edge_length=0.2, iterations=1)
    pair = prstar.remesh((cube.points, cube.tetrahedra), edge_length=0.2, iterations=1)
    assert pair.mesh.labels is None and pair.mesh.point_data == {}
    tree = prstar.Octree(cube.points, cube.tetrahedra, labels=cube.labels, field=cube.points[:, 2])
    by_tree = prstar.remesh(tree, edge_length=0.2, iterations=1)
    np.testing.assert_array_equal(by_tree.mesh.points, by_mesh.mesh.points)
    np.testing.assert_array_equal(by_tree.mesh.tetrahedra, by_mesh.mesh.tetrahedra)
    np.testing.assert_array_equal(by_tree.mesh.labels, by_mesh.mesh.labels)
    np.testing.assert_array_equal(by_tree.mesh.point_data["scalar"], cube.points[by_tree.input_vertex, 2])
    assert without_seconds(by_tree.statistics) == without_seconds(by_mesh.statistics)
    # a size field as an array is the same as by name
    by_name = prstar.remesh(cube, size_field="h", iterations=1)
    by_array = prstar.remesh(cube, size_field=cube.point_data["h"].tolist(), iterations=1)
    np.testing.assert_array_equal(by_name.mesh.tetrahedra, by_array.mesh.tetrahedra)
    assert by_array.statistics["size_field"] == "<array>" and by_name.statistics["size_field"] == "h"
    assert by_name.statistics["edge_length"] is None


@pytest.mark.parametrize("options,message", [
    ({}, "give edge_length or size_field"),
    ({"edge_length": 0.1, "size_field": "h"}, "not both"),
    ({"edge_length": 0}, "edge_length must be a positive length"),
    ({"edge_length": -0.1}, "edge_length must be a positive length"),
    ({"edge_length": "abc"}, "edge_length must be a positive length"),
    ({"edge_length": "0%"}, "edge_length must be a positive length"),
    ({"edge_length": math.inf}, "edge_length must be a positive length"),
    ({"size_field": "pressure"}, "no point-data array named 'pressure' for size_field"),
    ({"size_field": "neg"}, r"size field 'neg': the target edge length at vertex 3 is -1 \(it must be positive"),
    ({"size_field": "nan"}, r"size field 'nan': the target edge length at vertex 0 is nan"),
    ({"size_field": np.ones(5)}, r"size_field: shape \(5,\)"),
    ({"edge_length": 0.1, "iterations": 0}, r"iterations must be an integer in \[1, 1000\]"),
    ({"edge_length": 0.1, "iterations": 2.5}, r"iterations must be an integer in \[1, 1000\]"),
    ({"edge_length": 0.1, "min_dihedral": 80}, r"min_dihedral must be in \[0, 70.5\]"),
    ({"edge_length": 0.1, "max_dihedral": 60}, r"max_dihedral must be in \[70.6, 180\]"),
    ({"edge_length": 0.1, "min_radius_ratio": 1.5}, r"min_radius_ratio must be in \[0, 1\]"),
    ({"edge_length": 0.1, "feature_angle": -1}, r"feature_angle must be in \[0, 180\]"),
    ({"edge_length": 0.1, "max_error": "2cm"}, "max_error must be a distance"),
    ({"edge_length": 0.1, "bucket_size": 0}, "bucket_size"),
])
def test_remesh_bad_options(options, message):
    points, tets = np.array(list(itertools.product((0.0, 1.0), repeat=3))), np.array([[0, 1, 3, 7], [0, 1, 5, 7]])
    tets[signed_volumes(points, tets) < 0] = tets[signed_volumes(points, tets) < 0][:, [1, 0, 2, 3]]
    h = np.full(len(points), 0.5)
    neg = h.copy()
    neg[3] = -1
    mesh = prstar.Mesh(points, tets, point_data={"h": h, "neg": neg, "nan": np.full(len(points), np.nan)})
    with pytest.raises(ValueError, match=message) as e:
        prstar.remesh(mesh, **options)
    if "bucket_size" not in options:  # (that one has the message every function gives)
        assert str(e.value).startswith("remesh: ")


def test_remesh_size_field_errors_match_cli(cli, tmp_path):
    # the tool says the same for a missing array and a bad value, with exit status 1
    points = np.array(list(itertools.product((0.0, 1.0), repeat=3)))
    tets = np.array([[0, 1, 3, 7], [0, 1, 5, 7], [0, 2, 3, 7], [0, 2, 6, 7], [0, 4, 5, 7], [0, 4, 6, 7]])
    tets[signed_volumes(points, tets) < 0] = tets[signed_volumes(points, tets) < 0][:, [1, 0, 2, 3]]
    h = np.full(8, 0.5)
    h[6] = 0
    mesh = prstar.Mesh(points, tets, point_data={"h": h})
    prstar.write(tmp_path / "k.vtu", mesh)
    p = cli.run("remesh", tmp_path / "k.vtu", "--size-field", "h", "-o", tmp_path / "o.vtu")
    assert p.returncode == 1 and "size field 'h': the target edge length at vertex 6 is 0 (it must be positive" in p.stderr
    with pytest.raises(ValueError, match="at vertex 6 is 0 "):
        prstar.remesh(mesh, size_field="h")
    p = cli.run("remesh", tmp_path / "k.vtu", "--size-field", "p", "-o", tmp_path / "o.vtu")
    assert p.returncode == 1 and "no point-data array named 'p' for --size-field (it has: h)" in p.stderr
    assert not (tmp_path / "o.vtu").exists()


# ---------------------------------------------------------------------------------------------
# simplify: both floors, the ceiling, optimize
# ---------------------------------------------------------------------------------------------

SIMPLIFY_CASES = [
    ("floors", {"target": 0.5, "min_dihedral": 8, "min_radius_ratio": 0.15, "max_dihedral": 160},
     ["--target", "0.5", "--min-dihedral", "8", "--min-radius-ratio", "0.15", "--max-dihedral", "160"]),
    ("coarsen_only", {"target": 0.5, "optimize": 0}, ["--target", "0.5", "--optimize", "0"]),
    ("optimize_3", {"target": 0.6, "optimize": 3, "bucket_size": math.inf},
     ["--target", "0.6", "--optimize", "3", "--kv", "inf"]),
    ("no_floors", {"target": 0.5, "min_dihedral": 0, "min_radius_ratio": 0, "max_dihedral": 180},
     ["--target", "0.5", "--min-dihedral", "0", "--min-radius-ratio", "0", "--max-dihedral", "180"]),
]


@pytest.fixture(scope="module")
def simplified(cli, cube, cube_file, tmp_path_factory):
    out = {}
    folder = tmp_path_factory.mktemp("simplified")
    for name, options, args in SIMPLIFY_CASES:
        path = folder / f"{name}.vtu"
        p = cli.run("simplify", cube_file, *args, "-o", path, "--json")
        assert p.returncode in (0, 4), p.stderr
        out[name] = (prstar.simplify(cube, **options), json.loads(p.stdout), path)
    return out


@pytest.mark.parametrize("case", [c[0] for c in SIMPLIFY_CASES])
def test_simplify_options_equal_cli(simplified, cube, case):
    r, expected, path = simplified[case]
    assert without_seconds(r.statistics) == as_module_statistics(expected)
    assert_same_mesh(r.mesh, path)
    o = r.statistics["optimization"]
    assert set(o) == {"vertex_moves", "flips_2_3", "flips_3_2", "flips_4_4", "edge_removals", "splits", "rounds",
                      "tetrahedra_added", "tetrahedra_deleted", "refused_moves", "refused_flips", "refused_splits"}
    s = r.statistics
    assert s["removed_tetrahedra"] == s["input_tetrahedra"] - s["output_tetrahedra"]
    for k in ("refused_moves", "refused_flips", "refused_splits"):
        assert set(o[k]) == set(r.statistics["blocked"])
    assert o["splits"] == 0  # simplify never splits
    check_valid_mesh(r.mesh.points, r.mesh.tetrahedra, 1)
    area, volume = surface_area_and_volume(r.mesh.points, r.mesh.tetrahedra)
    assert abs(volume - 1) <= 6 * r.statistics["boundary_error"]["bound"]


def test_simplify_floors_hold(simplified, cube):
    # A tetrahedron is made under a floor (over the ceiling) only if it replaces worse ones: the
    # output's worst is no worse than the floor or the input's worst.
    angles_in, ratio_in = dihedral_angles(cube.points, cube.tetrahedra), radius_ratios(cube.points, cube.tetrahedra)
    for case, (lo, ratio_floor, hi) in (("floors", (8, 0.15, 160)), ("coarsen_only", (5, 0.1, 165)),
                                        ("optimize_3", (5, 0.1, 165))):
        r, _, _ = simplified[case]
        angles, ratio = dihedral_angles(r.mesh.points, r.mesh.tetrahedra), radius_ratios(r.mesh.points, r.mesh.tetrahedra)
        assert angles.min() >= min(lo, angles_in.min()) - 1e-9, case
        assert ratio.min() >= min(ratio_floor, ratio_in.min()) - 1e-9, case
        assert angles.max() <= max(hi, angles_in.max()) + 1e-9, case
    # the floors are above the input's worst: the output is better than the input's worst
    assert angles_in.min() < 8 and angles_in.max() > 160
    r, _, _ = simplified["floors"]
    assert dihedral_angles(r.mesh.points, r.mesh.tetrahedra).min() > angles_in.min()


def test_simplify_optimize(simplified, cube):
    # optimize 0: the old coarsening: no vertex moves, no flips, every vertex where its input vertex is
    r, _, _ = simplified["coarsen_only"]
    o = r.statistics["optimization"]
    assert o["vertex_moves"] == o["flips_2_3"] == o["flips_3_2"] == o["flips_4_4"] == o["rounds"] == 0
    np.testing.assert_array_equal(r.mesh.points, cube.points[r.input_vertex])
    # optimize 3: the rounds are done, vertices moved (and say so), the data still follows
    r, _, _ = simplified["optimize_3"]
    o = r.statistics["optimization"]
    assert o["rounds"] == 3 and o["vertex_moves"] > 0
    moved = np.any(r.mesh.points != cube.points[r.input_vertex], axis=1)
    assert moved.any()
    np.testing.assert_array_equal(r.mesh.point_data["h"], cube.point_data["h"][r.input_vertex])
    np.testing.assert_array_equal(r.mesh.labels, cube.labels[r.input_tetrahedron])


@pytest.mark.parametrize("options,message", [
    ({"min_dihedral": 80}, r"min_dihedral must be in \[0, 70.5\] degrees \(0: no floor\)"),
    ({"max_dihedral": 70}, r"max_dihedral must be in \[70.6, 180\] degrees \(180: no ceiling\)"),
    ({"max_dihedral": 181}, r"max_dihedral must be in \[70.6, 180\]"),
    ({"min_radius_ratio": -0.1}, r"min_radius_ratio must be in \[0, 1\] \(0: no floor\)"),
    ({"optimize": -1}, r"optimize must be an integer in \[0, 1000\] \(0: coarsen only\)"),
    ({"optimize": 1.5}, r"optimize must be an integer in \[0, 1000\]"),
])
def test_simplify_bad_quality_options(options, message):
    points = np.array(list(itertools.product((0.0, 1.0), repeat=3)))
    tets = np.array([[0, 1, 3, 7], [0, 1, 5, 7], [0, 2, 3, 7], [0, 2, 6, 7], [0, 4, 5, 7], [0, 4, 6, 7]])
    with pytest.raises(ValueError, match=message):
        prstar.simplify((points, tets), target=0.5, **options)
    with pytest.raises(TypeError):
        prstar.simplify((points, tets), target=0.5, optimize="2")
