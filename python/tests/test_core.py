# Copyright (c) 2026 The PR-star octree project.
# SPDX-License-Identifier: LGPL-3.0-or-later
"""prstar.Octree, boundary, curvature and distortion: against the prstar tool on the same files,
against brute force in numpy, on every array layout and dtype, for every bucket size and thread
count; the errors; and that the arrays given are copied once (into the octree) and no more."""

from __future__ import annotations

import csv
import math
import os
import subprocess
import sys
import textwrap
import tracemalloc

import numpy as np
import pytest

import prstar
from conftest import TEST_MESHES

vtk = pytest.importorskip("vtkmodules.all")
from vtkmodules.util.numpy_support import vtk_to_numpy  # noqa: E402


# ---------------------------------------------------------------------------------------------
# Reading the meshes and the tool's outputs with VTK (independent of the package's readers)
# ---------------------------------------------------------------------------------------------

def read_medit(path):
    """A Medit .mesh (ASCII) read here: Vertices and Tetrahedra (1-based), the references as labels."""
    tokens = open(path).read().split()
    i, points, tets, labels = 0, None, None, None
    while i < len(tokens):
        t = tokens[i]
        if t == "Vertices":
            n = int(tokens[i + 1])
            a = np.array(tokens[i + 2:i + 2 + 4 * n], dtype=float).reshape(n, 4)
            points, i = a[:, :3], i + 2 + 4 * n
        elif t == "Tetrahedra":
            n = int(tokens[i + 1])
            a = np.array(tokens[i + 2:i + 2 + 5 * n], dtype=np.int64).reshape(n, 5)
            tets, labels, i = a[:, :4] - 1, a[:, 4].astype(np.int32), i + 2 + 5 * n
        elif t in ("Triangles", "Edges", "Corners", "Ridges", "RequiredVertices"):
            n = int(tokens[i + 1])
            width = {"Triangles": 4, "Edges": 3}.get(t, 1)
            i += 2 + width * n
        else:
            i += 1
    return points, tets, labels


def read_vtu(path):
    r = vtk.vtkXMLUnstructuredGridReader()
    r.SetFileName(str(path))
    r.Update()
    g = r.GetOutput()
    points = vtk_to_numpy(g.GetPoints().GetData()).astype(float)
    conn = vtk_to_numpy(g.GetCells().GetConnectivityArray()).reshape(-1, 4)
    pd = {g.GetPointData().GetArrayName(k): vtk_to_numpy(g.GetPointData().GetArray(k))
          for k in range(g.GetPointData().GetNumberOfArrays())}
    return points, conn, pd


def read_vtp(path):
    r = vtk.vtkXMLPolyDataReader()
    r.SetFileName(str(path))
    r.Update()
    g = r.GetOutput()
    polys = vtk_to_numpy(g.GetPolys().GetConnectivityArray()).reshape(-1, 3)
    pd = {g.GetPointData().GetArrayName(k): vtk_to_numpy(g.GetPointData().GetArray(k))
          for k in range(g.GetPointData().GetNumberOfArrays())}
    cd = {g.GetCellData().GetArrayName(k): vtk_to_numpy(g.GetCellData().GetArray(k))
          for k in range(g.GetCellData().GetNumberOfArrays())}
    return polys, pd, cd


def load(data_dir, name):
    path = data_dir / name
    if name.endswith(".mesh"):
        return read_medit(path)
    points, tets, _ = read_vtu(path)
    return points, tets, None


@pytest.fixture(scope="module", params=TEST_MESHES)
def mesh_file(request, data_dir):
    return data_dir / request.param


# ---------------------------------------------------------------------------------------------
# Brute force in numpy
# ---------------------------------------------------------------------------------------------

FACES = np.array([[1, 2, 3], [0, 3, 2], [0, 1, 3], [0, 2, 1]])  # outward for a positive tetrahedron


def signed_volumes(points, tets):
    a, b, c, d = (points[tets[:, k]] for k in range(4))
    return np.einsum("ij,ij->i", np.cross(b - a, c - a), d - a) / 6


def brute_force_boundary_faces(tets):
    """The faces in exactly one tetrahedron, as sorted triples, with the tetrahedron they bound."""
    faces = np.sort(tets[:, FACES].reshape(-1, 3), axis=1)
    owner = np.repeat(np.arange(len(tets)), 4)
    uniq, inverse, counts = np.unique(faces, axis=0, return_inverse=True, return_counts=True)
    once = counts[inverse.ravel()] == 1
    return faces[once], owner[once]


# ---------------------------------------------------------------------------------------------
# Against the tool and brute force
# ---------------------------------------------------------------------------------------------

def test_boundary_matches_cli_and_brute_force(mesh_file, cli, tmp_path):
    points, tets, labels = load(mesh_file.parent, mesh_file.name)
    b = prstar.boundary(prstar.Mesh(points, tets, labels=labels))
    # the tool's counts
    j = cli.json("boundary", mesh_file, "--surface", tmp_path / "s.vtp", "-o", tmp_path / "b.vtu")
    for key, value in b.counts.items():
        assert j[key] == value, key
    # the tool's per-vertex array, in the user's order
    _, _, pd = read_vtu(tmp_path / "b.vtu")
    assert np.array_equal(pd["boundary"].astype(np.uint8), b.vertex_types)
    # the tool's surface: the same triangles, with the same orientation
    polys, spd, _ = read_vtp(tmp_path / "s.vtp")
    tool = spd["vertex"][polys]
    assert sorted(map(tuple, tool)) == sorted(map(tuple, b.triangles.astype(np.int64)))
    # brute force: the faces in one tetrahedron, outward
    faces, owner = brute_force_boundary_faces(tets.astype(np.int64))
    assert b.counts["boundary_triangles"] == len(faces)
    assert set(map(tuple, np.sort(b.boundary_triangles.astype(np.int64), axis=1))) == set(map(tuple, faces))
    tri = b.boundary_triangles.astype(np.int64)
    key = {tuple(f): o for f, o in zip(map(tuple, faces), owner)}
    opposite = np.array([np.setdiff1d(tets[key[tuple(sorted(t))]], t)[0] for t in tri])
    p = points
    normal_side = np.einsum("ij,ij->i", np.cross(p[tri[:, 1]] - p[tri[:, 0]], p[tri[:, 2]] - p[tri[:, 0]]),
                            p[opposite] - p[tri[:, 0]])
    assert np.all(normal_side < 0), "boundary triangles face out of their tetrahedron"
    # brute force vertex types on a manifold mesh: boundary iff on a boundary face
    on_face = np.zeros(len(points), bool)
    on_face[faces.ravel()] = True
    referenced = np.zeros(len(points), bool)
    referenced[tets.ravel()] = True
    if b.counts["nonmanifold_vertices"] == 0:
        assert np.array_equal(b.vertex_types == prstar.BOUNDARY, on_face)
        assert np.array_equal(b.vertex_types == prstar.INTERIOR, referenced & ~on_face)
    assert np.array_equal(b.vertex_types == prstar.UNREFERENCED, ~referenced)


def read_curvature_csv(path):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    return {k: np.array([float(r[k]) for r in rows]) for k in ("boundary", "distortion", "domain_curvature")}


@pytest.mark.parametrize("axis", ["x", "z"])
def test_curvature_matches_cli(mesh_file, cli, tmp_path, axis):
    points, tets, labels = load(mesh_file.parent, mesh_file.name)
    c = prstar.curvature((points, tets), axis)
    cli.run("curvature", mesh_file, "--field", axis, "--csv", tmp_path / "c.csv", "--quiet", check=True)
    ref = read_curvature_csv(tmp_path / "c.csv")
    assert np.array_equal(ref["boundary"].astype(np.uint8), c.vertex_types)
    # the tool prints 17 significant digits: the same doubles
    assert np.array_equal(ref["distortion"], c.distortion, equal_nan=True)
    assert np.array_equal(ref["domain_curvature"], c.domain_curvature, equal_nan=True)
    # distortion(): the same array; an array field equal to the coordinate: the same values
    k = "xyz".index(axis)
    assert np.array_equal(prstar.distortion((points, tets), points[:, k]), c.distortion, equal_nan=True)
    # closed form: a linear field lifts the mesh to a flat hyperplane, so the interior distortion is
    # the domain's curvature, 0 up to rounding
    interior = c.vertex_types == prstar.INTERIOR
    assert np.all(np.abs(c.distortion[interior]) < 1e-9)
    assert np.all(np.abs(c.domain_curvature[interior]) < 1e-9)


def test_statistics_match_cli(mesh_file, cli):
    points, tets, labels = load(mesh_file.parent, mesh_file.name)
    for kv in (8, 50):
        tree = prstar.Octree(points, tets, labels=labels, bucket_size=kv)
        s = tree.statistics()
        j = cli.json("stats", mesh_file, "--kv", kv)
        for key in ("vertices", "tetrahedra", "kv", "nodes", "leaves", "empty_leaves", "depth", "chi",
                    "max_leaf_vertices", "max_leaf_tetrahedra", "duplicate_vertices", "unreferenced_vertices",
                    "reoriented_tetrahedra", "degenerate_tetrahedra"):
            assert s[key] == j[key], key
        for key in ("points", "tetrahedra", "nodes", "leaf_tetrahedra"):
            assert s["bytes_detail"][key] == j["storage"]["bytes_detail"][key], key
        assert tree.number_of_leaves == j["leaves"] and tree.depth == j["depth"]
        assert repr(tree) == (f"prstar.Octree({j['vertices']} vertices, {j['tetrahedra']} tetrahedra, "
                              f"bucket_size={kv}, {j['leaves']} leaves, depth {j['depth']})")


def test_leaves_partition_the_vertices(data_dir):
    points, tets, _ = load(data_dir, "sphere.mesh")
    tree = prstar.Octree(points, tets, bucket_size=20)
    leaves = tree.leaves()
    order = tree.vertex_order()  # octree vertex -> user vertex
    assert np.array_equal(np.sort(order), np.arange(len(points)))
    begin, end = leaves["vertex_begin"].astype(np.int64), leaves["vertex_end"].astype(np.int64)
    assert begin[0] == 0 and end[-1] == len(points) and np.array_equal(begin[1:], end[:-1])
    assert np.all(end - begin <= 20) and tree.statistics()["depth_limited_leaves"] == 0
    for lo, hi, b, e in zip(leaves["box_min"], leaves["box_max"], begin, end):
        p = points[order[b:e]]
        assert np.all(p >= lo - 1e-12) and np.all(p <= hi + 1e-12)
    # each tetrahedron is listed by the leaves of its distinct vertices: sum = chi |T|
    s = tree.statistics()
    assert leaves["tetrahedra"].sum() == round(s["chi"] * s["tetrahedra"])
    leaf_of = np.empty(len(points), np.int64)
    for k, (b, e) in enumerate(zip(begin, end)):
        leaf_of[order[b:e]] = k
    per_leaf = np.zeros(len(begin), np.int64)
    for t in tets:
        np.add.at(per_leaf, np.unique(leaf_of[t]), 1)
    assert np.array_equal(per_leaf, leaves["tetrahedra"].astype(np.int64))


def test_same_results_for_every_bucket_size_thread_count_and_layout(data_dir):
    points, tets, labels = load(data_dir, "torus.mesh")
    ref_b = prstar.boundary((points, tets), bucket_size=50)
    ref_c = prstar.curvature((points, tets), points[:, 1])
    variants = [
        dict(points=points, tets=tets, kv=1, threads=1),
        dict(points=points, tets=tets, kv=8, threads=2),
        dict(points=points, tets=tets, kv=math.inf, threads=None),
        dict(points=np.asfortranarray(points), tets=np.asfortranarray(tets), kv=50, threads=2),
        dict(points=np.hstack([points, points])[:, :3], tets=tets.astype(np.int32), kv=50, threads=1),
        dict(points=points, tets=tets.astype(np.uint32), kv=50, threads=1),
        dict(points=points, tets=tets.astype(np.uint64), kv=50, threads=1),
    ]
    # a strided view (every other row of a bigger array): read in place
    big = np.zeros((2 * len(points), 3))
    big[::2] = points
    variants.append(dict(points=big[::2], tets=tets, kv=50, threads=1))
    for v in variants:
        tree = prstar.Octree(v["points"], v["tets"], bucket_size=v["kv"], threads=v["threads"])
        b = prstar.boundary(tree)
        assert np.array_equal(b.vertex_types, ref_b.vertex_types)
        assert np.array_equal(b.triangles, ref_b.triangles) or v["kv"] != 50
        assert b.counts == ref_b.counts
        c = prstar.curvature(tree, points[:, 1])
        assert np.array_equal(c.distortion, ref_c.distortion, equal_nan=True)
    # float32 points: the same results as their float64 values
    p32 = points.astype(np.float32)
    b32 = prstar.boundary((p32, tets))
    b64 = prstar.boundary((p32.astype(np.float64), tets))
    assert np.array_equal(b32.vertex_types, b64.vertex_types) and np.array_equal(b32.triangles, b64.triangles)
    # and they stay 32-bit floats in the octree (12 bytes per vertex), unlike their float64 values
    s32 = prstar.Octree(p32, tets, bucket_size=50).statistics()
    s64 = prstar.Octree(p32.astype(np.float64), tets, bucket_size=50).statistics()
    assert s32["float32_coordinates"] and not s64["float32_coordinates"]
    assert s32["bytes_detail"]["points"] == 12 * len(p32) and s64["bytes_detail"]["points"] == 24 * len(p32)
    assert s32["chi"] == s64["chi"] and s32["nodes"] == s64["nodes"]


def test_labels_give_interfaces(data_dir):
    points, tets, _ = load(data_dir, "cube.mesh")
    # two labels split by the plane x = centroid median: the interface is the set of faces shared by
    # tetrahedra of both labels (brute force)
    centroid_x = points[tets].mean(axis=1)[:, 0]
    labels = np.where(centroid_x < np.median(centroid_x), 1, 2).astype(np.int32)
    b = prstar.boundary(prstar.Mesh(points, tets, labels=labels))
    faces = np.sort(tets[:, FACES].reshape(-1, 3), axis=1)
    face_label = np.repeat(labels, 4)
    uniq, inverse = np.unique(faces, axis=0, return_inverse=True)
    inverse = inverse.ravel()
    lo = np.full(len(uniq), 99)
    hi = np.full(len(uniq), -99)
    np.minimum.at(lo, inverse, face_label)
    np.maximum.at(hi, inverse, face_label)
    expected = set(map(tuple, uniq[lo != hi]))
    got = b.triangles[b.interface].astype(np.int64)
    assert set(map(tuple, np.sort(got, axis=1))) == expected
    assert b.counts["interface_triangles"] == len(expected)
    assert np.all(b.label_inside[b.interface] == 1) and np.all(b.label_outside[b.interface] == 2)
    assert np.all(b.label_outside[~b.interface] == -1)


def test_progress_is_called_and_can_stop(data_dir):
    points, tets, _ = load(data_dir, "sphere.mesh")
    tree = prstar.Octree(points, tets, bucket_size=4)
    calls = []
    prstar.boundary(tree, progress=lambda done, total: calls.append((done, total)))
    assert calls and calls[-1][0] == calls[-1][1] == tree.number_of_leaves
    assert all(a[0] <= b[0] for a, b in zip(calls, calls[1:]))

    class Stop(Exception):
        pass

    def stop(done, total):
        raise Stop("stopped by the callback")

    with pytest.raises(Stop):
        prstar.curvature(tree, "x", progress=stop)
    # the octree is still usable afterwards
    assert prstar.boundary(tree).counts["vertices"] == len(points)


# ---------------------------------------------------------------------------------------------
# Errors: exceptions with the package's message, never a crash
# ---------------------------------------------------------------------------------------------

P = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1], [1, 1, 1]], float)
T = np.array([[0, 1, 2, 3], [1, 2, 3, 4]])


@pytest.mark.parametrize(
    "points, tets, kwargs, error, message",
    [
        (P[:, :2], T, {}, ValueError, "points: shape (5, 2), expected (n, 3)"),
        (P.ravel(), T, {}, ValueError, "points: shape (15,), expected (n, 3)"),
        (P, T[:, :3], {}, ValueError, "tetrahedra: shape (2, 3), expected (n, 4)"),
        (P.astype(complex), T, {}, ValueError, "points: dtype complex128"),
        (P, T.astype(float), {}, ValueError, "tetrahedra: dtype float64, expected an integer dtype"),
        (P, T.astype(bool), {}, ValueError, "tetrahedra: boolean array"),
        (np.array([["a", "b", "c"]]), T, {}, ValueError, "points: dtype <U1"),
        (P, np.array([[0, 1, 2, 5]]), {}, prstar.InvalidMeshError, "has vertex index 5 out of range [0, 5)"),
        (P, np.array([[0, 1, 2, -1]]), {}, prstar.InvalidMeshError, "has vertex index -1 out of range"),
        (P, np.array([[0, 1, 2, 2**63]], dtype=np.uint64), {}, prstar.InvalidMeshError,
         "has vertex index 9223372036854775808 out of range"),
        (P, np.array([[0, 1, 2, 1]]), {}, prstar.InvalidMeshError, "lists vertex 1 twice"),
        (np.where(np.arange(15).reshape(5, 3) == 4, np.nan, P), T, {}, prstar.InvalidMeshError,
         "vertex 1 has a non-finite coordinate"),
        (np.where(np.arange(15).reshape(5, 3) == 7, np.inf, P), T, {}, ValueError, "non-finite coordinate"),
        (P, T, {"labels": [1, 2, 3]}, ValueError, "labels: 3 values for 2 tetrahedra"),
        (P, T, {"labels": np.array([1, 2**40])}, ValueError, "does not fit a 32-bit integer"),
        (P, T, {"labels": np.array([1.5, 2])}, ValueError, "labels: dtype float64"),
        (P, T, {"field": [1.0, 2.0]}, ValueError, "field: 2 values for 5 vertices"),
        (P, T, {"field": [1.0, 2.0, np.nan, 0, 0]}, ValueError, "field: the value at vertex 2 is not finite"),
        (P, T, {"bucket_size": 0}, ValueError, "bucket_size: must be a positive integer"),
        (P, T, {"bucket_size": -3}, ValueError, "bucket_size: must be a positive integer"),
        (P, T, {"bucket_size": 2.5}, ValueError, "bucket_size: must be a positive integer or math.inf"),
        (P, T, {"bucket_size": "50"}, TypeError, "bucket_size: expected a positive int"),
        (P, T, {"threads": 0}, ValueError, "threads: must be a positive integer"),
        (P, T, {"threads": 1.5}, TypeError, "threads: expected None or a positive int"),
        (P, T, {"max_depth": 0}, ValueError, "max_depth: must be in [1, 64]"),
    ],
)
def test_bad_arrays_raise(points, tets, kwargs, error, message):
    with pytest.raises(error) as e:
        prstar.Octree(points, tets, **kwargs)
    assert message in str(e.value)


def test_empty_arrays():
    # no tetrahedra: an octree of isolated vertices (every vertex unreferenced), no crash
    b = prstar.boundary((P, np.zeros((0, 4), np.int64)))
    assert b.counts["unreferenced_vertices"] == 5 and len(b.triangles) == 0
    assert np.all(b.vertex_types == prstar.UNREFERENCED)
    # nothing at all
    b = prstar.boundary((np.zeros((0, 3)), np.zeros((0, 4), np.int64)))
    assert b.counts["vertices"] == 0 and b.vertex_types.shape == (0,)
    with pytest.raises(ValueError, match="tetrahedra: shape"):
        prstar.Octree(np.zeros((0, 3)), np.zeros((0,), np.int64))


def test_application_argument_errors():
    tree = prstar.Octree(P, T)
    with pytest.raises(ValueError, match="bucket_size given with an Octree"):
        prstar.boundary(tree, bucket_size=8)
    with pytest.raises(ValueError, match="curvature: field has 3 values for 5 vertices"):
        prstar.curvature(tree, [1, 2, 3])
    with pytest.raises(ValueError, match="curvature: the field's value at vertex 0 is not finite"):
        prstar.curvature(tree, [np.inf, 0, 0, 0, 0])
    with pytest.raises(ValueError, match="no point-data array 'temperature'"):
        prstar.curvature(prstar.Mesh(P, T, point_data={"pressure": np.zeros(5)}), "temperature")
    with pytest.raises(ValueError, match="no field"):
        prstar.curvature(tree)
    with pytest.raises(TypeError, match="expected a prstar.Mesh, an Octree or a"):
        prstar.boundary("mesh.vtu")
    # a Mesh's first point-data array is the default field, as the CLI's --field
    m = prstar.Mesh(P, T, point_data={"f": P[:, 0] * 2, "g": P[:, 1]})
    assert np.array_equal(prstar.distortion(m), prstar.distortion((P, T), P[:, 0] * 2), equal_nan=True)
    # an Octree built with field=: its own field is the default
    t2 = prstar.Octree(P, T, field=P[:, 2])
    assert t2.has_field
    assert np.array_equal(prstar.distortion(t2), prstar.distortion(t2, "z"), equal_nan=True)


# ---------------------------------------------------------------------------------------------
# The arrays given are read in place: copied once, into the octree
# ---------------------------------------------------------------------------------------------

def lattice(n):
    """A Kuhn lattice of n^3 cubes (6 n^3 tetrahedra), int64 indices as numpy makes them."""
    g = np.arange(n + 1, dtype=float)
    x, y, z = np.meshgrid(g, g, g, indexing="ij")
    points = np.stack([x.ravel(), y.ravel(), z.ravel()], axis=1)
    i, j, k = (a.ravel() for a in np.meshgrid(*(np.arange(n),) * 3, indexing="ij"))

    def vid(a, b, c):
        return (a * (n + 1) + b) * (n + 1) + c

    corners = [vid(i + (m & 1), j + ((m >> 1) & 1), k + ((m >> 2) & 1)) for m in range(8)]
    paths = [(1, 3), (1, 5), (2, 3), (2, 6), (4, 5), (4, 6)]
    tets = np.concatenate([np.stack([corners[0], corners[a], corners[b], corners[7]], axis=1) for a, b in paths])
    return points, tets


def test_no_numpy_copy_of_the_input():
    points, tets = lattice(12)
    # numpy allocations are traced: the module makes none of the size of the input, for C and
    # Fortran layouts and for dtypes other than the octree's (all converted on the fly)
    for p, t in ((points, tets), (np.asfortranarray(points), np.asfortranarray(tets)),
                 (points.astype(np.float32), tets.astype(np.int32))):
        tracemalloc.start()
        tree = prstar.Octree(p, t)
        _, peak = tracemalloc.get_traced_memory()
        tracemalloc.stop()
        assert peak < (p.nbytes + t.nbytes) / 20, peak
        assert tree.number_of_tetrahedra == len(tets)


def test_peak_memory_is_the_octree_alone(tmp_path):
    # In a fresh process: the peak RSS added by building the octree on big arrays stays below what
    # the octree itself holds plus its construction's transient part, and far below what one more
    # copy of the input would add.  The high-water mark is reset (/proc/self/clear_refs) once the
    # input is made, so that the temporaries of making it do not hide the construction's peak.
    if not os.path.exists("/proc/self/clear_refs"):
        pytest.skip("no /proc/self/clear_refs (Linux) to reset the peak RSS")
    script = textwrap.dedent("""
        import sys, numpy as np, prstar
        sys.path.insert(0, %r)
        from test_core import lattice

        def status(key):
            for line in open("/proc/self/status"):
                if line.startswith(key + ":"):
                    return int(line.split()[1]) * 1024

        points, tets = lattice(60)   # 1.3M tetrahedra: 42 MB of int64 indices
        tets = np.asfortranarray(tets)
        open("/proc/self/clear_refs", "w").write("5")
        before = status("VmRSS")
        tree = prstar.Octree(points, tets)
        print(status("VmHWM") - before, tree.statistics()["bytes"], points.nbytes + tets.nbytes)
    """) % os.path.dirname(os.path.abspath(__file__))
    out = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, check=True, env=os.environ)
    added, structure, given = map(int, out.stdout.split())
    # the construction's transient part (the sort keys and one copy of V) is under a third of the
    # structure; a copy of the input would add `given` (47 MB) on top of the structure (37 MB)
    assert 0.9 * structure < added < 1.35 * structure, (added, structure, given)
