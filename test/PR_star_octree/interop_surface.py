#!/usr/bin/env python3
# Copyright (c) 2026 The PR-star octree project.
# SPDX-License-Identifier: LGPL-3.0-or-later
#
# Author(s): The PR-star octree project
#
# Reads the triangle surfaces test_io_surface wrote into DIR (every format of IO/surface.h, in both
# modes) with readers that are not ours, and compares them with DIR/expected.json:
#   - VTK: vtkXMLPolyDataReader (.vtp: ascii, appended raw, appended zlib), vtkPLYReader,
#     vtkSTLReader, vtkOBJReader; any error or warning VTK reports is a failure;
#   - meshio: .off, .stl, .ply (ascii: meshio's binary PLY reader cannot read face properties),
#     .obj, .mesh (Medit);
#   - the binary PLY by a small reader of this script (numpy structured arrays, from its header).
# Compared: the points bit for bit (within float32 where the reader or the format keeps floats:
# STL, VTK's PLY and OBJ readers), the triangles in order with their orientation (for STL, whose
# readers merge points, through their coordinates), the STL normals, the data arrays by name and
# type, the label names; and the volume bounded by the outer triangles (label_outside 0), which
# must be the box's and positive (outward orientation).
# Exit 77 (skipped) when neither VTK's nor meshio's Python bindings are installed.
#
#   interop_surface.py DIR

import json
import os
import sys

try:
    import numpy as np
except ImportError:
    print("interop_surface: numpy is not installed: skipped")
    sys.exit(77)
try:
    import vtk
    from vtk.util.numpy_support import vtk_to_numpy
except ImportError:
    vtk = None
try:
    import meshio
except ImportError:
    meshio = None
if vtk is None and meshio is None:
    print("interop_surface: neither VTK's nor meshio's Python bindings are installed: skipped")
    sys.exit(77)

failures = 0
checks = 0


def check(cond, message):
    global failures, checks
    checks += 1
    if not cond:
        failures += 1
        print("FAIL:", message)


class Expected:
    def __init__(self, folder):
        with open(os.path.join(folder, "expected.json")) as f:
            e = json.load(f)
        self.points = np.array(e["points"], dtype=np.float64)
        self.triangles = np.array(e["triangles"], dtype=np.int64)
        self.point_data = {k: np.array(v, dtype=np.float64) for k, v in e["point_data"].items()}
        self.point_int_data = {k: np.array(v, dtype=np.int64) for k, v in e["point_int_data"].items()}
        self.cell_int_data = {k: np.array(v, dtype=np.int64) for k, v in e["cell_int_data"].items()}
        self.label_names = {int(k): v for k, v in e["label_names"].items()}
        n = np.cross(self.corner(1) - self.corner(0), self.corner(2) - self.corner(0))
        self.normals = n / np.linalg.norm(n, axis=1)[:, None]
        lo, hi = self.points.min(axis=0), self.points.max(axis=0)
        self.volume = float(np.prod(hi - lo))

    def corner(self, k):
        return self.points[self.triangles[:, k]]


def same_bits(a, b):
    a, b = np.ascontiguousarray(a, dtype=np.float64), np.ascontiguousarray(b, dtype=np.float64)
    return a.shape == b.shape and np.array_equal(a.view(np.uint64), b.view(np.uint64))


def outer_volume(points, triangles, outside):
    """The volume bounded by the triangles whose label_outside is 0 (divergence theorem)."""
    t = triangles[outside == 0]
    a, b, c = points[t[:, 0]], points[t[:, 1]], points[t[:, 2]]
    return float(np.sum(np.einsum("ij,ij->i", a, np.cross(b, c)))) / 6


def check_geometry(what, ex, points, triangles, exact):
    """Points and triangles in the file's order; `exact`: bit for bit, else within float32."""
    points = np.asarray(points, dtype=np.float64)
    triangles = np.asarray(triangles, dtype=np.int64)
    check(points.shape == ex.points.shape, "%s: %s points, expected %s" % (what, points.shape, ex.points.shape))
    check(triangles.shape == ex.triangles.shape,
          "%s: %s triangles, expected %s" % (what, triangles.shape, ex.triangles.shape))
    if points.shape != ex.points.shape or triangles.shape != ex.triangles.shape:
        return
    if exact:
        check(same_bits(points, ex.points), "%s: the points are not the same bit for bit" % what)
    else:
        check(np.array_equal(points.astype(np.float32), ex.points.astype(np.float32)),
              "%s: the points differ beyond float32 rounding" % what)
    check(np.array_equal(triangles, ex.triangles), "%s: the triangles differ (order or orientation)" % what)
    volume = outer_volume(points, triangles, ex.cell_int_data["label_outside"])
    check(abs(volume - ex.volume) <= 1e-6 * ex.volume,
          "%s: the outer triangles bound a volume %r, expected %r (outward)" % (what, volume, ex.volume))


def check_stl(what, ex, points, triangles, normals=None, exact=False):
    """STL readers merge the points: the triangles compared through their coordinates (float32,
    or bit for bit when `exact`)."""
    points = np.asarray(points, dtype=np.float64)
    triangles = np.asarray(triangles, dtype=np.int64)
    check(triangles.shape == ex.triangles.shape,
          "%s: %s triangles, expected %s" % (what, triangles.shape, ex.triangles.shape))
    if triangles.shape != ex.triangles.shape:
        return
    check(len(points) == len(ex.points), "%s: %d points after merging, expected %d" % (what, len(points), len(ex.points)))
    for k in range(3):
        got, expected = points[triangles[:, k]], ex.corner(k)
        same = same_bits(got, expected) if exact else np.array_equal(got.astype(np.float32),
                                                                      expected.astype(np.float32))
        check(same,
              "%s: corner %d of the triangles differs (order, orientation or coordinates)" % (what, k))
    if normals is not None:
        normals = np.asarray(normals, dtype=np.float64)
        check(normals.shape == ex.normals.shape and np.allclose(normals, ex.normals, rtol=0, atol=1e-6),
              "%s: the facet normals are not the unit normals of the triangles" % what)


def check_array(what, name, got, expected, integer):
    if got is None:
        check(False, "%s: no array %r" % (what, name))
        return
    got = np.asarray(got).reshape(-1)
    if integer:
        check(np.issubdtype(got.dtype, np.integer), "%s: %r has type %s, not an integer" % (what, name, got.dtype))
        check(got.shape == expected.shape and np.array_equal(got.astype(np.int64), expected),
              "%s: %r differs: %s, expected %s" % (what, name, got, expected))
    else:
        check(got.dtype == np.float64, "%s: %r has type %s, not float64" % (what, name, got.dtype))
        check(same_bits(got, expected), "%s: %r differs: %r, expected %r" % (what, name, got, expected))


def check_data(what, ex, point_arrays, cell_arrays):
    """`point_arrays`, `cell_arrays`: name -> values (or missing)."""
    for name, values in ex.point_data.items():
        check_array(what, name, point_arrays.get(name), values, False)
    for name, values in ex.point_int_data.items():
        check_array(what, name, point_arrays.get(name), values, True)
    for name, values in ex.cell_int_data.items():
        check_array(what, name, cell_arrays.get(name), values, True)


# --- VTK ---------------------------------------------------------------------------------------


def vtk_read(reader_class, path):
    reader = reader_class()
    reader.AddObserver("ErrorEvent", lambda obj, event: check(False, "VTK error reading %s" % path))
    reader.AddObserver("WarningEvent", lambda obj, event: check(False, "VTK warning reading %s" % path))
    reader.SetFileName(path)
    reader.Update()
    return reader.GetOutput()


def vtk_triangles(poly, what):
    polys = poly.GetPolys()
    offsets = vtk_to_numpy(polys.GetOffsetsArray()).astype(np.int64)
    connectivity = vtk_to_numpy(polys.GetConnectivityArray()).astype(np.int64)
    check(np.all(np.diff(offsets) == 3), "%s: cells that are not triangles" % what)
    check(poly.GetNumberOfVerts() == 0 and poly.GetNumberOfLines() == 0 and poly.GetNumberOfStrips() == 0,
          "%s: vertices, lines or strips" % what)
    return connectivity.reshape(-1, 3)


def vtk_points(poly):
    return vtk_to_numpy(poly.GetPoints().GetData())


def vtk_arrays(data):
    return {data.GetArrayName(i): vtk_to_numpy(data.GetArray(i)) for i in range(data.GetNumberOfArrays())}


def check_with_vtk(folder, ex):
    for name in ["box_binary.vtp", "box_raw.vtp", "box_ascii.vtp"]:
        what = "VTK " + name
        poly = vtk_read(vtk.vtkXMLPolyDataReader, os.path.join(folder, name))
        check(poly.GetPoints().GetDataType() == vtk.VTK_DOUBLE, "%s: the points are not Float64" % what)
        check_geometry(what, ex, vtk_points(poly), vtk_triangles(poly, what), True)
        point_arrays, cell_arrays = vtk_arrays(poly.GetPointData()), vtk_arrays(poly.GetCellData())
        check_data(what, ex, point_arrays, cell_arrays)
        check(sorted(point_arrays) == sorted(list(ex.point_data) + list(ex.point_int_data)),
              "%s: point arrays %s" % (what, sorted(point_arrays)))
        check(sorted(cell_arrays) == sorted(ex.cell_int_data), "%s: cell arrays %s" % (what, sorted(cell_arrays)))
        field = poly.GetFieldData()
        ids, names = field.GetAbstractArray("label_ids"), field.GetAbstractArray("label_names")
        check(ids is not None and names is not None, "%s: no field data label_ids and label_names" % what)
        if ids is not None and names is not None:
            got = {int(ids.GetTuple1(i)): names.GetValue(i) for i in range(ids.GetNumberOfTuples())}
            check(names.GetNumberOfValues() == ids.GetNumberOfTuples(), "%s: label arrays of different sizes" % what)
            check(got == ex.label_names, "%s: label names %r, expected %r" % (what, got, ex.label_names))

    for name in ["box_binary.ply", "box_ascii.ply"]:
        what = "VTK " + name
        poly = vtk_read(vtk.vtkPLYReader, os.path.join(folder, name))
        check_geometry(what, ex, vtk_points(poly), vtk_triangles(poly, what), False)

    for name in ["box_binary.stl", "box_ascii.stl"]:
        what = "VTK " + name
        poly = vtk_read(vtk.vtkSTLReader, os.path.join(folder, name))
        check_stl(what, ex, vtk_points(poly), vtk_triangles(poly, what))

    for name in ["empty.vtp", "empty_binary.vtp", "empty.ply", "empty_binary.ply", "empty.stl", "empty_binary.stl"]:
        path = os.path.join(folder, name)
        if not os.path.exists(path):
            check(False, "%s: missing" % path)
            continue
        reader = {"vtp": vtk.vtkXMLPolyDataReader, "ply": vtk.vtkPLYReader, "stl": vtk.vtkSTLReader}[name[-3:]]
        if name == "empty_binary.stl":  # VTK tells binary from ASCII by the size: it fails on an empty binary one
            check(os.path.getsize(path) == 84, "%s: %d bytes" % (path, os.path.getsize(path)))
            continue
        poly = vtk_read(reader, path)
        check(poly.GetNumberOfPoints() == 0 and poly.GetNumberOfCells() == 0, "VTK %s: not empty" % name)

    what = "VTK box.obj"
    poly = vtk_read(vtk.vtkOBJReader, os.path.join(folder, "box.obj"))
    check_geometry(what, ex, vtk_points(poly), vtk_triangles(poly, what), False)


# --- meshio ------------------------------------------------------------------------------------


def meshio_triangles(mesh, what):
    check(all(c.type == "triangle" for c in mesh.cells), "%s: cells other than triangles" % what)
    return np.concatenate([c.data for c in mesh.cells]) if mesh.cells else np.zeros((0, 3))


def meshio_cell_arrays(mesh):
    return {k: np.concatenate([np.asarray(b).reshape(-1) for b in v]) for k, v in mesh.cell_data.items()}


def check_with_meshio(folder, ex):
    for name in ["box.off", "box_ascii.ply", "box.obj", "box.mesh"]:
        what = "meshio " + name
        mesh = meshio.read(os.path.join(folder, name))
        triangles = meshio_triangles(mesh, what)
        check_geometry(what, ex, mesh.points, triangles, True)
        cells = meshio_cell_arrays(mesh)
        if name.endswith(".ply"):
            check_data(what, ex, mesh.point_data, cells)
        elif name.endswith(".mesh"):
            check_array(what, "medit:ref", cells.get("medit:ref"), ex.cell_int_data["label_inside"], True)
            check_array(what, "vertex medit:ref", mesh.point_data.get("medit:ref"),
                        np.zeros(len(ex.points), dtype=np.int64), True)
        elif name.endswith(".obj"):
            # one group each time label_inside changes along the triangles
            inside = ex.cell_int_data["label_inside"]
            runs = 1 + int(np.count_nonzero(inside[1:] != inside[:-1]))
            check(len(mesh.cells) == runs, "%s: %d groups, expected %d" % (what, len(mesh.cells), runs))
    for name in ["box_binary.stl", "box_ascii.stl"]:
        what = "meshio " + name
        mesh = meshio.read(os.path.join(folder, name))
        normals = meshio_cell_arrays(mesh).get("facet_normals")
        # meshio reads the ASCII coordinates as float64: those written exactly
        check(normals is not None or name == "box_binary.stl", "%s: no facet normals" % what)
        check_stl(what, ex, mesh.points, meshio_triangles(mesh, what),
                  None if normals is None else normals.reshape(-1, 3), exact=name == "box_ascii.stl")


# --- binary PLY, read here ---------------------------------------------------------------------

PLY_TYPES = {"char": "i1", "uchar": "u1", "short": "i2", "ushort": "u2", "int": "i4", "uint": "u4",
             "float": "f4", "double": "f8", "int8": "i1", "uint8": "u1", "int16": "i2", "uint16": "u2",
             "int32": "i4", "uint32": "u4", "float32": "f4", "float64": "f8"}


def read_binary_ply(path):
    """(points, triangles, vertex properties, face properties, comments) of a binary little-endian
    PLY whose faces are `list uchar int` of 3 indices followed by scalar properties."""
    with open(path, "rb") as f:
        data = f.read()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    lines = data[:end].decode("ascii").splitlines()
    assert lines[0] == "ply" and lines[1] == "format binary_little_endian 1.0", lines[:2]
    elements, comments = [], []
    for line in lines[2:-1]:
        words = line.split()
        if words[0] == "comment":
            comments.append(line[len("comment "):])
        elif words[0] == "element":
            elements.append((words[1], int(words[2]), []))
        elif words[0] == "property" and words[1] == "list":
            assert words[2:4] == ["uchar", "int"], words
            elements[-1][2].append((words[4], "list"))
        elif words[0] == "property":
            elements[-1][2].append((words[2], "<" + PLY_TYPES[words[1]]))
    position, result = end, {}
    for name, count, properties in elements:
        fields = []
        for pname, ptype in properties:
            if ptype == "list":
                fields += [(pname + "_count", "u1"), (pname, "<i4", (3,))]
            else:
                fields.append((pname, ptype))
        dtype = np.dtype(fields)
        result[name] = np.frombuffer(data, dtype=dtype, count=count, offset=position)
        position += dtype.itemsize * count
    check(position == len(data), "%s: %d bytes after the faces" % (path, len(data) - position))
    vertex, face = result["vertex"], result["face"]
    check(np.all(face["vertex_indices_count"] == 3), "%s: faces that are not triangles" % path)
    points = np.column_stack([vertex["x"], vertex["y"], vertex["z"]])
    vertex_arrays = {n: vertex[n] for n in vertex.dtype.names if n not in ("x", "y", "z")}
    face_arrays = {n: face[n] for n in face.dtype.names if not n.startswith("vertex_indices")}
    return points, face["vertex_indices"], vertex_arrays, face_arrays, comments


def check_ply_here(folder, ex):
    what = "box_binary.ply read here"
    points, triangles, vertex_arrays, face_arrays, comments = read_binary_ply(os.path.join(folder, "box_binary.ply"))
    check_geometry(what, ex, points, triangles, True)
    check_data(what, ex, vertex_arrays, face_arrays)
    labels = {}
    for c in comments:
        words = c.split(" ", 2)
        if words[0] == "label":
            labels[int(words[1])] = words[2]
    check(labels == ex.label_names, "%s: label comments %r, expected %r" % (what, labels, ex.label_names))


def main():
    folder = sys.argv[1]
    ex = Expected(folder)
    if vtk is not None:
        check_with_vtk(folder, ex)
    else:
        print("interop_surface: VTK's Python bindings are not installed: its readers skipped")
    if meshio is not None:
        check_with_meshio(folder, ex)
    else:
        print("interop_surface: meshio is not installed: its readers skipped")
    check_ply_here(folder, ex)
    print("interop_surface: %d checks, %d failures" % (checks, failures))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
