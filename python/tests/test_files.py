# Copyright (c) 2026 The PR-star octree project.
# SPDX-License-Identifier: LGPL-3.0-or-later
"""prstar.read / prstar.write and the conversions from and to meshio and VTK.

Truth: the prstar tool on the same files (``info --json`` counts, labels, arrays and bounding box;
``convert`` output byte for byte), meshio's and VTK's own readers of the same files, and the
arrays written (every format reads back exactly what it keeps).
"""

from __future__ import annotations

import math
import os
import pathlib
import threading
import tracemalloc
import warnings
from typing import Dict

import numpy as np
import pytest

import prstar

meshio = pytest.importorskip("meshio")

# What each format keeps (the package's format table, IO/formats.h): labels, point data (named:
# every array by name; unnamed: every array, by position; first: the first array only; none), cell
# data, label names.
FORMATS: Dict[str, tuple] = {
    "vtu": (True, "named", True, False),
    "vtk": (True, "named", True, False),
    "node": (True, "unnamed", False, False),
    "mesh": (True, "none", False, False),
    "meshb": (True, "none", False, False),
    "msh": (True, "named", True, True),
    "off": (False, "first", False, False),
    "xdmf": (True, "named", True, False),
}


def written(folder: pathlib.Path, ext: str) -> list:
    """The files a write of mesh.EXT makes in folder."""
    base = folder / "mesh"
    if ext == "node":
        return [base.with_suffix(".node"), base.with_suffix(".ele")]
    if ext == "xdmf":
        return [base.with_suffix(".xdmf"), base.with_suffix(".h5")]
    return [base.with_suffix("." + ext)]


def no_temporaries(folder: pathlib.Path) -> None:
    stray = [p.name for p in folder.iterdir() if "prstar-tmp" in p.name]
    assert not stray, f"temporaries left behind: {stray}"


@pytest.fixture(scope="module")
def sample(data_dir) -> prstar.Mesh:
    """cube.mesh with two labels (by the side of x = 0), their names, two point-data arrays and a
    cell-data array of values that need all 17 digits."""
    m = prstar.read(data_dir / "cube.mesh")
    centroids = m.points[m.tetrahedra].mean(axis=1)
    m.labels = (centroids[:, 0] > 0).astype(np.int32) + 1
    m.label_names = {1: "left", 2: "right"}
    m.point_data = {"f": np.sin(3.1 * m.points[:, 0]) + m.points[:, 1] / 3, "g": m.points[:, 2] * 1e-7}
    m.cell_data = {"q": np.arange(m.number_of_tetrahedra) / 7.0}
    return m


def assert_same_mesh(a: prstar.Mesh, b: prstar.Mesh, data: bool = True) -> None:
    np.testing.assert_array_equal(a.points, b.points)
    np.testing.assert_array_equal(a.tetrahedra, b.tetrahedra)
    assert (a.labels is None) == (b.labels is None)
    if a.labels is not None:
        np.testing.assert_array_equal(a.labels, b.labels)
    if data:
        assert list(a.point_data) == list(b.point_data)
        assert list(a.cell_data) == list(b.cell_data)
        for k in a.point_data:
            np.testing.assert_array_equal(a.point_data[k], b.point_data[k])
        for k in a.cell_data:
            np.testing.assert_array_equal(a.cell_data[k], b.cell_data[k])
        assert a.label_names == b.label_names


# ---------------------------------------------------------------------------------------------
# Every format: write, read back, the prstar tool, meshio
# ---------------------------------------------------------------------------------------------


@pytest.mark.parametrize("ext", FORMATS)
def test_write_read_back(sample, tmp_path, ext):
    labels, point_data, cell_data, names = FORMATS[ext]
    path = tmp_path / f"mesh.{ext}"
    prstar.write(path, sample)
    for f in written(tmp_path, ext):
        assert f.exists(), f
    no_temporaries(tmp_path)
    r = prstar.read(path)
    assert r.points.dtype == np.float64 and r.tetrahedra.dtype == np.uint32
    np.testing.assert_array_equal(r.points, sample.points)  # exact: every format writes 17 digits or binary
    np.testing.assert_array_equal(r.tetrahedra, sample.tetrahedra)  # and keeps the order
    if labels:
        assert r.labels.dtype == np.int32
        np.testing.assert_array_equal(r.labels, sample.labels)
    else:
        assert r.labels is None
    expected = list(sample.point_data.values())
    if point_data == "named":
        assert list(r.point_data) == list(sample.point_data)
    elif point_data == "first":
        expected = expected[:1]
    elif point_data == "none":
        expected = []
    assert len(r.point_data) == len(expected)
    for got, want in zip(r.point_data.values(), expected):
        assert got.dtype == np.float64
        np.testing.assert_array_equal(got, want)
    if cell_data:
        assert list(r.cell_data) == ["q"]
        np.testing.assert_array_equal(r.cell_data["q"], sample.cell_data["q"])
    else:
        assert r.cell_data == {}
    assert r.label_names == (sample.label_names if names else {})
    assert r.skipped_cells == {}


@pytest.mark.parametrize("ext", FORMATS)
def test_cli_info_of_module_write(cli, sample, tmp_path, ext):
    """What `prstar info` finds in the file the module wrote is what the module reads back."""
    path = tmp_path / f"mesh.{ext}"
    prstar.write(path, sample)
    r = prstar.read(path)
    info = cli.json("info", path)
    assert info["vertices"] == r.number_of_vertices == sample.number_of_vertices
    assert info["tetrahedra"] == r.number_of_tetrahedra == sample.number_of_tetrahedra
    assert info["other_cells"] == r.skipped_cells
    assert info["bounding_box"]["min"] == r.points.min(axis=0).tolist()
    assert info["bounding_box"]["max"] == r.points.max(axis=0).tolist()
    assert [a["name"] for a in info["point_data"]] == list(r.point_data)
    assert [a["name"] for a in info["cell_data"]] == list(r.cell_data)
    for a, values in zip(info["point_data"] + info["cell_data"],
                         list(r.point_data.values()) + list(r.cell_data.values())):
        assert (a["min"], a["max"]) == (values.min(), values.max())
    if r.labels is None:
        assert info["labels"] == []
    else:
        values, counts = np.unique(r.labels, return_counts=True)
        assert [(d["label"], d["tetrahedra"]) for d in info["labels"]] == list(zip(values.tolist(), counts.tolist()))
        assert {d["label"]: d["name"] for d in info["labels"] if "name" in d} == r.label_names


@pytest.mark.parametrize("ext", FORMATS)
def test_cli_convert_equals_module_write(cli, sample, tmp_path, ext):
    """`prstar convert` of a .msh (which keeps everything) to EXT makes the file the module writes
    for the same mesh (byte for byte; for XDMF the same XML but for the name of the .h5, and the
    same arrays)."""
    source = tmp_path / "source.msh"
    prstar.write(source, sample)
    mine, theirs = tmp_path / "mine", tmp_path / "theirs"
    mine.mkdir()
    theirs.mkdir()
    prstar.write(mine / f"mesh.{ext}", sample)
    cli.run("convert", source, theirs / f"mesh.{ext}", "--quiet", check=True)
    for a, b in zip(written(mine, ext), written(theirs, ext)):
        if b.suffix == ".h5":
            continue  # HDF5 files differ in their internal bookkeeping; the arrays are compared below
        assert a.read_bytes() == b.read_bytes(), a.name
    assert_same_mesh(prstar.read(mine / f"mesh.{ext}"), prstar.read(theirs / f"mesh.{ext}"))


# meshio's reader of each format, and the name of the labels in its cell data
MESHIO_READS = {
    "vtu": ("vtu", "label"),
    "vtk": ("vtk", "label"),
    "node": ("tetgen", "tetgen:ref"),
    "mesh": ("medit", "medit:ref"),
    "meshb": ("medit", "medit:ref"),
    "msh": ("gmsh", "gmsh:physical"),
    "xdmf": ("xdmf", "label"),
}


@pytest.mark.parametrize("ext", MESHIO_READS)
def test_meshio_reads_module_write(sample, tmp_path, ext):
    """meshio reads in the file the module wrote the same points, tetrahedra and labels."""
    path = tmp_path / f"mesh.{ext}"
    prstar.write(path, sample)
    file_format, label_key = MESHIO_READS[ext]
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        m = meshio.read(path, file_format=file_format)
    np.testing.assert_array_equal(m.points, sample.points)
    assert {b.type for b in m.cells} == {"tetra"}
    tets = np.concatenate([b.data for b in m.cells])
    labels = np.concatenate(m.cell_data[label_key]).reshape(-1)  # legacy VTK: (m, 1)
    if ext == "msh":
        # gmsh 4.1 groups the elements by entity (label): meshio keeps the blocks, in the order of
        # the file; the element tags of the file (tetrahedron index + 1) give the mesh's order back
        # in the package's reader.  Compare as sets of (label, tetrahedron).
        order = np.lexsort(np.c_[tets, labels].T[::-1])
        ref = np.lexsort(np.c_[sample.tetrahedra, sample.labels].T[::-1])
        tets, labels = tets[order], labels[order]
        want_tets, want_labels = sample.tetrahedra[ref], sample.labels[ref]
    else:
        want_tets, want_labels = sample.tetrahedra, sample.labels
    np.testing.assert_array_equal(tets, want_tets)
    np.testing.assert_array_equal(labels, want_labels)
    if ext in ("vtu", "vtk", "xdmf", "msh"):
        for k, v in sample.point_data.items():
            np.testing.assert_array_equal(m.point_data[k].reshape(-1), v)


def test_msh22_same_order_for_meshio(sample, tmp_path):
    """gmsh 2.2 lists the elements in the mesh's order: meshio reads them so (one block per label
    change)."""
    path = tmp_path / "mesh.msh"
    prstar.write(path, sample, version=2.2)
    assert path.read_text().startswith("$MeshFormat\n2.2 0 8\n")
    m = meshio.read(path)
    np.testing.assert_array_equal(np.concatenate([b.data for b in m.cells]), sample.tetrahedra)
    np.testing.assert_array_equal(np.concatenate(m.cell_data["gmsh:physical"]), sample.labels)
    assert_same_mesh(prstar.read(path), sample)


# ---------------------------------------------------------------------------------------------
# The test meshes: the module's read against meshio's and VTK's
# ---------------------------------------------------------------------------------------------


@pytest.mark.parametrize("name", ["cube.mesh", "sphere.mesh", "torus.mesh", "sphere_tetgen.mesh", "cube_tetgen.vtu"])
def test_read_equals_meshio(data_dir, name):
    r = prstar.read(data_dir / name)
    m = meshio.read(data_dir / name)
    np.testing.assert_array_equal(r.points, m.points)
    np.testing.assert_array_equal(r.tetrahedra, np.concatenate([b.data for b in m.cells if b.type == "tetra"]))
    # the same mesh through meshio's reader and from_meshio
    assert_same_mesh(prstar.from_meshio(m), r, data=False)


def vtk_read(path: pathlib.Path):
    from vtkmodules.vtkIOLegacy import vtkUnstructuredGridReader
    from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader

    reader = vtkXMLUnstructuredGridReader() if path.suffix == ".vtu" else vtkUnstructuredGridReader()
    reader.SetFileName(str(path))
    reader.Update()
    return reader.GetOutput()


def test_read_equals_vtk(data_dir, sample, tmp_path):
    pytest.importorskip("vtkmodules")
    r = prstar.read(data_dir / "cube_tetgen.vtu")
    assert_same_mesh(prstar.from_vtk(vtk_read(data_dir / "cube_tetgen.vtu")), r)
    # every array of the module's .vtu and .vtk (zlib, appended raw; big-endian legacy binary) as VTK
    # reads them
    for ext, options in (("vtu", {}), ("vtu", {"binary": False}), ("vtk", {"binary": True}),
                         ("vtk", {"version": 5.1})):
        path = tmp_path / f"mesh.{ext}"
        prstar.write(path, sample, **options)
        g = vtk_read(path)
        assert_same_mesh(prstar.from_vtk(g), prstar.read(path))


def test_shared_meshes(shared_data):
    """The real meshes of ../shared/data: VTU files as VTK and meshio read them, TetGen as meshio.
    (Their VTU points are ASCII Float32: VTK and meshio round the decimals to float32, the package
    reads them as doubles; rounded to float32 they agree exactly.)"""
    pytest.importorskip("vtkmodules")
    for path in sorted(shared_data.glob("*.vtu")):
        r = prstar.read(path)
        v = prstar.from_vtk(vtk_read(path))
        m = meshio.read(path)
        for other in (v.points, m.points):
            np.testing.assert_array_equal(r.points.astype(m.points.dtype), other)
        np.testing.assert_array_equal(r.tetrahedra, v.tetrahedra)
        np.testing.assert_array_equal(r.tetrahedra, np.concatenate([b.data for b in m.cells if b.type == "tetra"]))
        assert r.skipped_cells == v.skipped_cells and r.labels is None and v.labels is None
    for path in sorted(shared_data.glob("*.node")):
        r = prstar.read(path)
        m = meshio.read(path)
        np.testing.assert_array_equal(r.points, m.points)
        np.testing.assert_array_equal(r.tetrahedra, m.cells[0].data)


# ---------------------------------------------------------------------------------------------
# meshio and VTK in memory
# ---------------------------------------------------------------------------------------------


def test_meshio_round_trip(sample):
    m = prstar.to_meshio(sample)
    assert [b.type for b in m.cells] == ["tetra"]
    np.testing.assert_array_equal(m.cell_data["gmsh:physical"][0], sample.labels)
    assert {k: v.tolist() for k, v in m.field_data.items()} == {"left": [1, 3], "right": [2, 3]}
    back = prstar.from_meshio(m)
    assert_same_mesh(back, sample)
    assert back.tetrahedra.dtype == np.uint32 and back.labels.dtype == np.int32
    # another name for the labels, taken back as labels when it is one of LABEL_ARRAY_NAMES
    m = prstar.to_meshio(sample, labels_name="medit:ref")
    assert_same_mesh(prstar.from_meshio(m), sample)
    m = prstar.to_meshio(sample, labels_name="region")
    back = prstar.from_meshio(m)
    assert back.labels is None and list(back.cell_data) == ["region", "q"]


def test_meshio_files_through_conversions(sample, tmp_path):
    """meshio writes (to_meshio) what the module reads; the module writes what meshio reads
    (from_meshio of meshio.read equals prstar.read)."""
    m = prstar.to_meshio(sample)
    for ext in ("vtu", "vtk", "xdmf", "mesh"):
        path = tmp_path / f"mio.{ext}"
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            meshio.write(path, m)
        r = prstar.read(path)
        assert_same_mesh(r, sample, data=False)
        if ext != "mesh":
            for k in sample.point_data:
                np.testing.assert_array_equal(r.point_data[k], sample.point_data[k])
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            assert_same_mesh(prstar.from_meshio(meshio.read(path)), r, data=False)
    path = tmp_path / "mio.msh"
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        meshio.write(path, m, file_format="gmsh22")
    r = prstar.read(path)
    assert_same_mesh(r, sample, data=False)
    # meshio's gmsh entity tags are not data: from_meshio leaves them out, as the package's reader
    with warnings.catch_warnings():
        warnings.simplefilter("error", UserWarning)
        assert_same_mesh(prstar.from_meshio(meshio.read(path)), r)
    path = tmp_path / "module.msh"  # the module's gmsh 4.1 (label names, data) through meshio
    prstar.write(path, sample)
    with warnings.catch_warnings():
        warnings.simplefilter("error", UserWarning)
        back = prstar.from_meshio(meshio.read(path))
    order = np.lexsort(back.tetrahedra.T[::-1])  # meshio: grouped by label (see above)
    ref = np.lexsort(sample.tetrahedra.T[::-1])
    np.testing.assert_array_equal(back.tetrahedra[order], sample.tetrahedra[ref])
    np.testing.assert_array_equal(back.labels[order], sample.labels[ref])
    assert back.label_names == sample.label_names
    assert list(back.point_data) == list(sample.point_data) and list(back.cell_data) == ["q"]


def mixed_grid(sample):
    """A vtkUnstructuredGrid of the sample's tetrahedra with 3 triangles and a hexahedron among them,
    labels in 'CellEntityIds' (int64), a 3-component point array and a string array."""
    from vtkmodules.util import numpy_support as ns
    from vtkmodules.vtkCommonCore import vtkPoints, vtkStringArray
    from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkUnstructuredGrid

    t = sample.tetrahedra.astype(np.int64)
    cells = [(10, list(x)) for x in t[:5]] + [(5, [0, 1, 2]), (5, [1, 2, 3])] + [(10, list(x)) for x in t[5:]]
    cells.insert(3, (12, list(range(8))))
    cells.append((5, [4, 5, 6]))
    types = np.array([c[0] for c in cells], dtype=np.uint8)
    offsets = np.cumsum([0] + [len(c[1]) for c in cells]).astype(np.int64)
    conn = np.concatenate([c[1] for c in cells]).astype(np.int64)
    g = vtkUnstructuredGrid()
    p = vtkPoints()
    p.SetData(ns.numpy_to_vtk(np.ascontiguousarray(sample.points), deep=1))
    g.SetPoints(p)
    ca = vtkCellArray()
    ca.SetData(ns.numpy_to_vtkIdTypeArray(offsets, deep=1), ns.numpy_to_vtkIdTypeArray(conn, deep=1))
    g.SetCells(ns.numpy_to_vtk(types, deep=1, array_type=3), ca)
    tet = types == 10
    lab = np.full(len(cells), 99, dtype=np.int64)
    lab[tet] = sample.labels
    a = ns.numpy_to_vtk(lab, deep=1)
    a.SetName("CellEntityIds")
    g.GetCellData().AddArray(a)
    q = np.zeros(len(cells))
    q[tet] = sample.cell_data["q"]
    a = ns.numpy_to_vtk(q, deep=1)
    a.SetName("q")
    g.GetCellData().AddArray(a)
    a = ns.numpy_to_vtk(np.ascontiguousarray(sample.points), deep=1)
    a.SetName("position")
    g.GetPointData().AddArray(a)
    a = ns.numpy_to_vtk(np.ascontiguousarray(sample.point_data["f"]), deep=1)
    a.SetName("f")
    g.GetPointData().AddArray(a)
    s = vtkStringArray()
    s.SetName("names")
    s.SetNumberOfValues(len(cells))
    g.GetCellData().AddArray(s)
    return g


def test_vtk_round_trip_and_mixed_cells(sample, tmp_path):
    pytest.importorskip("vtkmodules")
    from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridWriter

    g = prstar.to_vtk(sample)
    assert g.GetNumberOfCells() == sample.number_of_tetrahedra
    assert g.GetCellData().GetArray("label").GetDataTypeAsString() == "int"
    assert g.GetPointData().GetArray("f").GetDataTypeAsString() == "double"
    assert_same_mesh(prstar.from_vtk(g), dict_free(sample))
    # cells of other types: counted, as the package's reader counts them in the same grid's .vtu
    mixed = mixed_grid(sample)
    with pytest.warns(UserWarning, match="position"):
        m = prstar.from_vtk(mixed)
    assert m.skipped_cells == {"triangle": 3, "hexahedron": 1}
    np.testing.assert_array_equal(m.tetrahedra, sample.tetrahedra)
    np.testing.assert_array_equal(m.labels, sample.labels)
    assert list(m.point_data) == ["f"] and list(m.cell_data) == ["q"]
    w = vtkXMLUnstructuredGridWriter()
    w.SetFileName(str(tmp_path / "mixed.vtu"))
    w.SetInputData(mixed)
    assert w.Write() == 1
    assert_same_mesh(prstar.read(tmp_path / "mixed.vtu"), m)
    assert prstar.read(tmp_path / "mixed.vtu").skipped_cells == m.skipped_cells
    # meshio (which does not read VTK's string arrays): the same counts, by the same names
    mixed.GetCellData().RemoveArray("names")
    w.SetFileName(str(tmp_path / "mixed2.vtu"))
    assert w.Write() == 1
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        mm = prstar.from_meshio(meshio.read(tmp_path / "mixed2.vtu"))
    assert mm.skipped_cells == m.skipped_cells
    np.testing.assert_array_equal(mm.tetrahedra, m.tetrahedra)
    np.testing.assert_array_equal(mm.labels, m.labels)


def dict_free(m: prstar.Mesh) -> prstar.Mesh:
    """``m`` without its label names (VTK grids have no place for them)."""
    return prstar.Mesh(m.points, m.tetrahedra, m.labels, m.point_data, m.cell_data)


def test_conversion_errors(sample):
    pytest.importorskip("vtkmodules")
    from vtkmodules.vtkCommonDataModel import vtkPolyData

    with pytest.raises(TypeError, match="vtkUnstructuredGrid"):
        prstar.from_vtk(vtkPolyData())
    bad = meshio.Mesh(sample.points, [("tetra", np.array([[0, 1, 2, len(sample.points)]]))])
    with pytest.raises(prstar.InvalidMeshError, match="out of range"):
        prstar.from_meshio(bad)
    with pytest.raises(prstar.InvalidMeshError, match="twice"):
        prstar.from_meshio(meshio.Mesh(sample.points, [("tetra", np.array([[0, 1, 1, 2]]))]))
    with pytest.raises(ValueError, match="no tetrahedron"):
        prstar.from_meshio(meshio.Mesh(sample.points, [("triangle", np.array([[0, 1, 2]]))]))
    with pytest.raises(ValueError, match=r"\(n, 3\)"):
        prstar.from_meshio(meshio.Mesh(sample.points[:, :2], [("tetra", np.array([[0, 1, 2, 3]]))]))
    bad = prstar.Mesh(sample.points, np.array([[0, 1, 2, -1]]))
    with pytest.raises(prstar.InvalidMeshError):
        prstar.to_vtk(bad)


def test_missing_library_message(monkeypatch, sample):
    import builtins

    real = builtins.__import__

    def no_meshio(name, *args, **kwargs):
        if name == "meshio" or name.startswith("vtkmodules"):
            raise ImportError("no " + name)
        return real(name, *args, **kwargs)

    monkeypatch.setattr(builtins, "__import__", no_meshio)
    with pytest.raises(ImportError, match="python3-meshio"):
        prstar.to_meshio(sample)
    with pytest.raises(ImportError, match="python3-vtk9"):
        prstar.to_vtk(sample)


# ---------------------------------------------------------------------------------------------
# Reading: memory, zero copy, errors
# ---------------------------------------------------------------------------------------------


def test_memory_limit(data_dir, cli):
    path = data_dir / "cube.mesh"
    with pytest.raises(OSError, match=f"^{path}:.*more than the limit of 1.00 kB"):
        prstar.read(path, max_memory=1000)
    # the same refusal as the tool's
    p = cli.run("info", path, "--max-memory", "1000", "--quiet")
    assert p.returncode == 1 and "more than the limit of 1.00 kB" in p.stderr
    assert prstar.read(path, max_memory=math.inf).number_of_tetrahedra == prstar.read(path).number_of_tetrahedra
    assert prstar.read(path, max_memory=10**9).number_of_vertices == cli.json("info", path)["vertices"]
    for bad in (0, -5, "1G", 1.5, True):
        with pytest.raises((ValueError, TypeError)):
            prstar.read(path, max_memory=bad)


def test_read_hands_over_without_copy(data_dir):
    """The arrays the reader made become numpy's: the Python heap grows by less than a tenth of them
    while reading."""
    path = data_dir / "torus.mesh"
    tracemalloc.start()
    try:
        m = prstar.read(path)
        _, peak = tracemalloc.get_traced_memory()
    finally:
        tracemalloc.stop()
    nbytes = m.points.nbytes + m.tetrahedra.nbytes + m.labels.nbytes
    assert peak < nbytes / 10, (peak, nbytes)
    assert not m.points.flags.owndata and m.points.base is not None


def test_path_types(sample, tmp_path):
    prstar.write(str(tmp_path / "a.vtu"), sample)
    assert_same_mesh(prstar.read(pathlib.Path(tmp_path / "a.vtu")), prstar.read(str(tmp_path / "a.vtu")))
    with pytest.raises(TypeError):
        prstar.read(42)
    # a TetGen mesh by either of its names (both files written and read)
    prstar.write(tmp_path / "t.ele", sample)
    assert (tmp_path / "t.node").exists()
    assert_same_mesh(prstar.read(tmp_path / "t.ele"), prstar.read(tmp_path / "t.node"))
    np.testing.assert_array_equal(prstar.read(tmp_path / "t.ele").labels, sample.labels)


def write_text(path: pathlib.Path, text: str) -> pathlib.Path:
    path.write_text(text)
    return path


MEDIT_HEAD = "MeshVersionFormatted 2\nDimension 3\nVertices\n4\n0 0 0 1\n1 0 0 1\n0 1 0 1\n"


def test_malformed_files(sample, tmp_path):
    # a NaN coordinate (line 8), an index out of range (line 11), written by hand
    p = write_text(tmp_path / "nan.mesh", MEDIT_HEAD + "0 0 nan 1\nTetrahedra\n1\n1 2 3 4 1\nEnd\n")
    with pytest.raises(OSError, match=f"^{p}:8: "):
        prstar.read(p)
    p = write_text(tmp_path / "index.mesh", MEDIT_HEAD + "0 0 1 1\nTetrahedra\n1\n1 2 3 9 1\nEnd\n")
    with pytest.raises(OSError, match=f"^{p}:11: .*9"):
        prstar.read(p)
    p = write_text(tmp_path / "twice.mesh", MEDIT_HEAD + "0 0 1 1\nTetrahedra\n1\n1 2 3 3 1\nEnd\n")
    with pytest.raises(OSError, match=f"^{p}:11: "):
        prstar.read(p)
    p = write_text(tmp_path / "good.mesh", MEDIT_HEAD + "0 0 1 1\nTetrahedra\n1\n1 2 3 4 7\nEnd\n")
    good = prstar.read(p)
    np.testing.assert_array_equal(good.tetrahedra, [[0, 1, 2, 3]])
    np.testing.assert_array_equal(good.labels, [7])
    # truncated text and binary files: OSError naming the file
    for ext in ("mesh", "vtu", "meshb", "msh"):
        full = tmp_path / f"full.{ext}"
        prstar.write(full, sample)
        data = full.read_bytes()
        cut = tmp_path / f"cut.{ext}"
        cut.write_bytes(data[: len(data) // 2])
        with pytest.raises(OSError, match=f"^{cut}[:]"):
            prstar.read(cut)
    with pytest.raises(OSError, match=f"^{tmp_path / 'absent.vtu'}: "):
        prstar.read(tmp_path / "absent.vtu")
    (tmp_path / "lonely.node").write_text((tmp_path / "full.mesh").read_text()[:0] + "0 3 0 0\n")
    with pytest.raises(OSError, match="lonely.ele"):
        prstar.read(tmp_path / "lonely.node")


def test_unknown_extension(sample, tmp_path):
    for call in (lambda p: prstar.read(p), lambda p: prstar.write(p, sample)):
        with pytest.raises(ValueError, match=r"unknown file extension '\.stl': supported are \.vtu, \.vtk"):
            call(tmp_path / "mesh.stl")
        with pytest.raises(ValueError, match="no file extension"):
            call(tmp_path / "mesh")
    assert list(tmp_path.iterdir()) == []
    assert ".node/.ele" in prstar.EXTENSIONS and ".xdmf/.xmf" in prstar.EXTENSIONS


# ---------------------------------------------------------------------------------------------
# Writing: arguments, options, errors, temporaries
# ---------------------------------------------------------------------------------------------


def test_write_arrays_like_meshio(sample, tmp_path):
    """write(path, points, tetrahedra, ...), a (points, tetrahedra) pair, a meshio.Mesh, a VTK grid;
    any dtype and layout; the keyword arrays added to a Mesh's."""
    pts = np.asfortranarray(sample.points.astype(np.float32))
    tets = sample.tetrahedra.astype(np.int64)[:, ::-1][:, ::-1]  # a strided view
    prstar.write(tmp_path / "a.vtu", pts, tets, labels=sample.labels.astype(np.uint8),
                 point_data={"f": sample.point_data["f"].astype(np.float32)}, cell_data={"c": np.arange(len(tets))})
    r = prstar.read(tmp_path / "a.vtu")
    np.testing.assert_array_equal(r.points, pts.astype(np.float64))
    np.testing.assert_array_equal(r.tetrahedra, tets)
    np.testing.assert_array_equal(r.labels, sample.labels)
    np.testing.assert_array_equal(r.point_data["f"], sample.point_data["f"].astype(np.float32))
    np.testing.assert_array_equal(r.cell_data["c"], np.arange(len(tets)))
    prstar.write(tmp_path / "b.vtu", (sample.points, sample.tetrahedra))
    r = prstar.read(tmp_path / "b.vtu")
    assert r.labels is None and r.point_data == {}
    np.testing.assert_array_equal(r.tetrahedra, sample.tetrahedra)
    prstar.write(tmp_path / "c.msh", prstar.to_meshio(sample))
    assert_same_mesh(prstar.read(tmp_path / "c.msh"), sample)
    prstar.write(tmp_path / "d.vtu", prstar.to_vtk(sample))
    assert_same_mesh(prstar.read(tmp_path / "d.vtu"), dict_free(sample))
    extra = np.linspace(0, 1, sample.number_of_vertices)
    prstar.write(tmp_path / "e.msh", sample, point_data={"extra": extra, "f": extra}, label_names={3: "none"},
                 labels=np.full(sample.number_of_tetrahedra, 5))
    r = prstar.read(tmp_path / "e.msh")
    assert list(r.point_data) == ["f", "g", "extra"]
    np.testing.assert_array_equal(r.point_data["f"], extra)
    assert set(r.labels.tolist()) == {5}
    assert r.label_names == {}  # gmsh names only the physical groups that exist
    with pytest.raises(TypeError):
        prstar.write(tmp_path / "f.vtu", sample, sample.tetrahedra)
    with pytest.raises(TypeError):
        prstar.write(tmp_path / "f.vtu", sample.points)


def test_write_options(cli, sample, tmp_path):
    """The options reach the writer: the same files as `prstar convert` with the same options."""
    source = tmp_path / "source.msh"
    prstar.write(source, sample)
    cases = [
        ("vtu", {"binary": False}, ["--ascii"], b'format="ascii"'),
        ("vtu", {"compression": "none"}, ["--compression", "none"], b'format="binary"'),
        ("vtu", {}, [], b'compressor="vtkZLibDataCompressor"'),
        ("vtk", {"binary": True}, ["--binary"], b"\nBINARY\n"),
        ("vtk", {"version": 5.1}, ["--format-version", "5.1"], b"# vtk DataFile Version 5.1"),
        ("msh", {"version": "2.2", "binary": True}, ["--format-version", "2.2", "--binary"], b"2.2 1 8"),
        ("meshb", {"version": 3}, ["--format-version", "3"], b""),
        ("xdmf", {"binary": False}, ["--ascii"], b'Format="XML"'),
    ]
    for i, (ext, options, flags, marker) in enumerate(cases):
        mine, theirs = tmp_path / f"m{i}.{ext}", tmp_path / f"t{i}.{ext}"
        prstar.write(mine, sample, **options)
        cli.run("convert", source, theirs, "--quiet", *flags, check=True)
        assert marker in mine.read_bytes(), (ext, options)
        assert mine.read_bytes() == theirs.read_bytes(), (ext, options)
        assert_same_mesh(prstar.read(mine), prstar.read(theirs))
    assert not (tmp_path / "m7.h5").exists()  # inline XDMF: no heavy data file


def test_write_argument_errors(sample, tmp_path):
    pts, tets, n, m = sample.points, sample.tetrahedra, sample.number_of_vertices, sample.number_of_tetrahedra
    path = tmp_path / "mesh.vtu"
    cases = [
        (dict(mesh_or_points=pts[:, :2], tetrahedra=tets), ValueError, r"points: shape \(2332, 2\)"),
        (dict(mesh_or_points=pts, tetrahedra=tets[:, :3]), ValueError, "tetrahedra: shape"),
        (dict(mesh_or_points=pts, tetrahedra=tets.astype(float)), ValueError, "tetrahedra: dtype float64"),
        (dict(mesh_or_points=pts.astype(str), tetrahedra=tets), ValueError, "points: dtype"),
        (dict(mesh_or_points=pts, tetrahedra=tets, labels=np.ones(m - 1, int)), ValueError, "labels: 9963 values"),
        (dict(mesh_or_points=pts, tetrahedra=tets, labels=np.ones(m, bool)), ValueError, "labels: boolean"),
        (dict(mesh_or_points=pts, tetrahedra=tets, labels=np.full(m, 2**40)), ValueError, "32-bit"),
        (dict(mesh_or_points=pts, tetrahedra=tets, point_data={"f": np.ones(n + 1)}), ValueError,
         r"point_data\['f'\]: 2333 values for 2332 vertices"),
        (dict(mesh_or_points=pts, tetrahedra=tets, point_data={"f": np.ones((n, 3))}), ValueError,
         r"point_data\['f'\]: shape"),
        (dict(mesh_or_points=pts, tetrahedra=tets, point_data={"f": np.full(n, np.nan)}), ValueError,
         "not finite"),
        (dict(mesh_or_points=pts, tetrahedra=tets, cell_data={"c": np.ones(3)}), ValueError, "3 values for 9964"),
        (dict(mesh_or_points=pts, tetrahedra=tets, labels=sample.labels, cell_data={"label": np.ones(m)}),
         ValueError, "labels="),
        (dict(mesh_or_points=pts, tetrahedra=tets, point_data={1: np.ones(n)}), TypeError, "str"),
        (dict(mesh_or_points=pts, tetrahedra=np.where(tets == 5, n, tets)), prstar.InvalidMeshError,
         f"vertex index {n} out of range"),
        (dict(mesh_or_points=pts, tetrahedra=np.where(tets == 5, -1, tets).astype(np.int32)),
         prstar.InvalidMeshError, "vertex index -1 out of range"),
        (dict(mesh_or_points=pts, tetrahedra=np.where(tets == 5, 2**64 - 1, tets).astype(np.uint64)),
         prstar.InvalidMeshError, f"vertex index {2**64 - 1} out of range"),
        (dict(mesh_or_points=pts, tetrahedra=np.c_[tets[:, :3], tets[:, :1]]), prstar.InvalidMeshError, "twice"),
        (dict(mesh_or_points=np.where(pts == pts[7, 1], np.inf, pts), tetrahedra=tets), prstar.InvalidMeshError,
         "vertex 7 has a non-finite coordinate"),
        (dict(mesh_or_points=sample, binary="yes"), TypeError, "binary"),
        (dict(mesh_or_points=sample, compression="lz4"), ValueError, "compression"),
        (dict(mesh_or_points=sample, version="x"), ValueError, "not a number"),
        (dict(mesh_or_points=sample, overwrite=1), TypeError, "overwrite"),
    ]
    for kwargs, error, message in cases:
        with pytest.raises(error, match=message):
            prstar.write(path, **kwargs)
    # options a format cannot honour: ValueError, before anything is written
    for ext, options, message in [("mesh", {"binary": True}, "text only"), ("meshb", {"binary": False}, "binary only"),
                                  ("msh", {"version": 3}, r"version 3 cannot be written \(4.1, 2.2\)"),
                                  ("off", {"version": 1}, "no version"), ("vtk", {"compression": "zlib"},
                                                                          "not compressed"),
                                  ("vtu", {"binary": False, "compression": "zlib"}, "needs use_binary_mode")]:
        with pytest.raises(ValueError, match=message):
            prstar.write(tmp_path / f"mesh.{ext}", sample, **options)
    assert list(tmp_path.iterdir()) == []


def test_write_file_errors(sample, tmp_path):
    missing = tmp_path / "no" / "such" / "folder" / "mesh.vtu"
    with pytest.raises(OSError, match=f"^{missing}: cannot open the file for writing: No such file"):
        prstar.write(missing, sample)
    assert list(tmp_path.iterdir()) == []
    # the name is a folder: written to the temporary, refused at the rename, the temporary removed
    (tmp_path / "dir.vtu").mkdir()
    with pytest.raises(OSError, match="dir.vtu"):
        prstar.write(tmp_path / "dir.vtu", sample)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["dir.vtu"]
    assert list((tmp_path / "dir.vtu").iterdir()) == []


@pytest.mark.parametrize("ext", ["vtu", "node", "xdmf"])
def test_overwrite(sample, tmp_path, ext):
    files = written(tmp_path, ext)
    path = files[0].with_suffix("." + ext)
    prstar.write(path, (sample.points, sample.tetrahedra))
    before = {f: f.read_bytes() for f in files}
    with pytest.raises(FileExistsError) as e:
        prstar.write(path, sample, overwrite=False)
    assert e.value.filename == str(files[0])
    assert {f: f.read_bytes() for f in files} == before
    no_temporaries(tmp_path)
    if len(files) == 1:
        files[0].unlink()
        prstar.write(path, sample, overwrite=False)
        assert_same_mesh(prstar.read(path), sample, data=False)
        return
    # one file of the pair (the .ele, the .h5) is enough to refuse
    files[0].unlink()
    with pytest.raises(FileExistsError) as e:
        prstar.write(path, sample, overwrite=False)
    assert e.value.filename == str(files[1])
    assert not files[0].exists()
    files[1].unlink()
    prstar.write(path, sample, overwrite=False)
    assert_same_mesh(prstar.read(path), sample, data=False)
    prstar.write(path, sample)  # the default replaces
    no_temporaries(tmp_path)


def test_xdmf_names_its_h5_by_the_final_name(sample, tmp_path):
    path = tmp_path / "mesh.xdmf"
    prstar.write(path, sample)
    text = path.read_text()
    assert "mesh.h5:/Mesh/geometry" in text and "prstar-tmp" not in text
    # the pair moves together (the reference is relative)
    other = tmp_path / "moved"
    other.mkdir()
    path.rename(other / "mesh.xdmf")
    (tmp_path / "mesh.h5").rename(other / "mesh.h5")
    assert_same_mesh(prstar.read(other / "mesh.xdmf"), dict_free(sample))


def test_concurrent_writes_and_reads(sample, tmp_path):
    """Threads write and read at once (the GIL released, one temporary per write, HDF5 serialised)."""
    errors = []

    def work(i):
        try:
            for ext in ("vtu", "xdmf", "msh"):
                p = tmp_path / f"t{i}.{ext}"
                prstar.write(p, sample)
                r = prstar.read(p)
                np.testing.assert_array_equal(r.tetrahedra, sample.tetrahedra)
            prstar.write(tmp_path / "same.vtu", sample)  # every thread: the same name
        except Exception as e:  # noqa: BLE001 - reported below
            errors.append(e)

    threads = [threading.Thread(target=work, args=(i,)) for i in range(4)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert errors == []
    assert_same_mesh(prstar.read(tmp_path / "same.vtu"), dict_free(sample))
    no_temporaries(tmp_path)
