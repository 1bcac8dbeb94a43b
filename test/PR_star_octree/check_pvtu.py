#!/usr/bin/env python3
# Copyright (c) 2026 The PR-star octree project.
# SPDX-License-Identifier: LGPL-3.0-or-later
#
# Author(s): The PR-star octree project
#
# Reads the distributed mesh test_pvtu_writer wrote (DIR/lattice.pvtu and its pieces) with VTK's
# vtkXMLPUnstructuredGridReader and checks it against DIR/expected.json (the whole mesh):
#   - the arrays exist with VTK's types: GlobalPointIds (Int64, the point GlobalIds attribute),
#     GlobalCellIds (Int64, the cell GlobalIds attribute), vtkGhostType (UInt8) on points and cells,
#     label (Int32, the active cell scalars), height and centroid_x (Float64);
#   - without the ghost cells (vtkGhostType & DUPLICATECELL) there are as many cells as in the whole
#     mesh, with distinct GlobalCellIds, and their volumes add up to the lattice's;
#   - the GlobalPointIds of the points that are not ghosts (vtkGhostType & DUPLICATEPOINT) are
#     distinct and as many as the whole mesh's vertices;
#   - each piece as a .vtu (vtkXMLUnstructuredGridReader) is read too, with an empty piece, and a
#     mesh without any optional array; any error or warning VTK reports is a failure.
# Exit 77 (skipped) when VTK's Python bindings are missing.
#
#   check_pvtu.py DIR

import json
import os
import sys

try:
    import vtk
except ImportError:
    print("check_pvtu: VTK's Python bindings are not installed: skipped")
    sys.exit(77)

failures = 0


def check(cond, message):
    global failures
    if not cond:
        failures += 1
        print("FAIL:", message)


def read(reader_class, path):
    """The output of a VTK XML reader of `path`; any error VTK reports is a failure."""
    reader = reader_class()
    reader.AddObserver("ErrorEvent", lambda obj, event: check(False, "VTK error reading %s" % path))
    reader.AddObserver("WarningEvent", lambda obj, event: check(False, "VTK warning reading %s" % path))
    reader.SetFileName(path)
    reader.Update()
    return reader


def det3(a, b, c):
    return (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0])
            + a[2] * (b[0] * c[1] - b[1] * c[0]))


def main():
    folder = sys.argv[1]
    with open(os.path.join(folder, "expected.json")) as f:
        expected = json.load(f)

    reader = read(vtk.vtkXMLPUnstructuredGridReader, os.path.join(folder, "lattice.pvtu"))
    check(reader.GetNumberOfPieces() == expected["pieces"],
          "%d pieces, %d expected" % (reader.GetNumberOfPieces(), expected["pieces"]))
    grid = reader.GetOutput()
    pd, cd = grid.GetPointData(), grid.GetCellData()
    ghost = vtk.vtkDataSetAttributes.GhostArrayName()

    def array_of(data, name, vtk_type, kind):
        a = data.GetAbstractArray(name)
        check(a is not None, "no %s array %s" % (kind, name))
        if a is not None:
            check(a.GetDataType() == vtk_type, "%s array %s: type %s (VTK type %d expected)" %
                  (kind, name, a.GetDataTypeAsString(), vtk_type))
            check(a.GetNumberOfComponents() == 1, "%s array %s: %d components" %
                  (kind, name, a.GetNumberOfComponents()))
        return a

    point_ids = pd.GetGlobalIds()
    cell_ids = cd.GetGlobalIds()
    check(point_ids is not None and point_ids.GetName() == "GlobalPointIds",
          "GetPointData().GetGlobalIds() is not GlobalPointIds")
    check(cell_ids is not None and cell_ids.GetName() == "GlobalCellIds",
          "GetCellData().GetGlobalIds() is not GlobalCellIds")
    for ids in (point_ids, cell_ids):
        if ids is not None:
            check(ids.IsA("vtkIdTypeArray") and ids.GetDataTypeSize() == 8,
                  "%s is a %s, not a 64-bit vtkIdTypeArray" % (ids.GetName(), ids.GetClassName()))
    point_ghosts = array_of(pd, ghost, vtk.VTK_UNSIGNED_CHAR, "point")
    cell_ghosts = array_of(cd, ghost, vtk.VTK_UNSIGNED_CHAR, "cell")
    array_of(pd, "height", vtk.VTK_DOUBLE, "point")
    array_of(cd, "centroid_x", vtk.VTK_DOUBLE, "cell")
    label = array_of(cd, "label", vtk.VTK_INT, "cell")
    check(cd.GetScalars() is not None and cd.GetScalars().GetName() == "label", "label is not the cell scalars")
    if failures or point_ids is None or cell_ids is None or label is None:
        return

    # All pieces together: owned and ghost cells.
    check(grid.GetNumberOfCells() == expected["cells"] + expected["ghost_cells"],
          "%d cells in the pieces, %d + %d ghosts expected" %
          (grid.GetNumberOfCells(), expected["cells"], expected["ghost_cells"]))
    dup_cell = vtk.vtkDataSetAttributes.DUPLICATECELL
    dup_point = vtk.vtkDataSetAttributes.DUPLICATEPOINT
    owned_cells, cell_gids, volume = 0, set(), 0.0
    for c in range(grid.GetNumberOfCells()):
        if cell_ghosts.GetValue(c) & dup_cell:
            continue
        owned_cells += 1
        cell_gids.add(cell_ids.GetValue(c))
        check(grid.GetCellType(c) == vtk.VTK_TETRA, "cell %d is not a tetrahedron" % c)
        ids = grid.GetCell(c).GetPointIds()
        p = [grid.GetPoint(ids.GetId(k)) for k in range(4)]
        volume += abs(det3(*[[p[k][i] - p[0][i] for i in range(3)] for k in (1, 2, 3)])) / 6
    check(owned_cells == expected["cells"], "%d cells without the ghosts, %d expected" %
          (owned_cells, expected["cells"]))
    check(len(cell_gids) == expected["cells"], "%d distinct GlobalCellIds among them" % len(cell_gids))
    check(abs(volume - expected["volume"]) < 1e-9, "volume %g, %g expected" % (volume, expected["volume"]))

    owned_points, point_gids = 0, set()
    for v in range(grid.GetNumberOfPoints()):
        if point_ghosts.GetValue(v) & dup_point:
            continue
        owned_points += 1
        point_gids.add(point_ids.GetValue(v))
    check(len(point_gids) == expected["points"], "%d distinct GlobalPointIds of points that are not "
          "ghosts, %d expected" % (len(point_gids), expected["points"]))
    check(owned_points == expected["points"], "%d points that are not ghosts, %d expected" %
          (owned_points, expected["points"]))
    check(min(point_gids) == 0 and max(point_gids) == expected["points"] - 1, "GlobalPointIds out of range")

    # vtkRemoveGhosts (when this VTK has it) removes the same cells.
    if hasattr(vtk, "vtkRemoveGhosts"):
        rg = vtk.vtkRemoveGhosts()
        rg.SetInputConnection(reader.GetOutputPort())
        rg.Update()
        check(rg.GetOutput().GetNumberOfCells() == expected["cells"],
              "vtkRemoveGhosts leaves %d cells, %d expected" % (rg.GetOutput().GetNumberOfCells(), expected["cells"]))

    # Each piece alone.
    for r in range(expected["pieces"]):
        g = read(vtk.vtkXMLUnstructuredGridReader, os.path.join(folder, "lattice_%d.vtu" % r)).GetOutput()
        check(g.GetNumberOfCells() > 0 and g.GetPointData().GetGlobalIds() is not None,
              "piece %d: no cells or no point global ids" % r)

    # The 3 pieces and an empty one (every array, without values): the same mesh.
    e = read(vtk.vtkXMLPUnstructuredGridReader, os.path.join(folder, "with_empty.pvtu")).GetOutput()
    check(e.GetNumberOfCells() == expected["cells"] + expected["ghost_cells"],
          "with_empty.pvtu: %d cells" % e.GetNumberOfCells())
    check(e.GetPointData().GetGlobalIds() is not None and e.GetCellData().GetArray(ghost) is not None,
          "with_empty.pvtu: the arrays are missing")

    # The minimal files: no optional array, GhostLevel 0.
    w = read(vtk.vtkXMLPUnstructuredGridReader, os.path.join(folder, "whole.pvtu")).GetOutput()
    check(w.GetNumberOfCells() == expected["cells"] and w.GetNumberOfPoints() == expected["points"],
          "whole.pvtu: %d cells, %d points" % (w.GetNumberOfCells(), w.GetNumberOfPoints()))
    check(w.GetPointData().GetNumberOfArrays() == 0 and w.GetCellData().GetNumberOfArrays() == 0,
          "whole.pvtu: unexpected arrays")


if __name__ == "__main__":
    if len(sys.argv) != 2:
        print("usage: check_pvtu.py DIR")
        sys.exit(2)
    main()
    print("check_pvtu: %d failure(s)" % failures)
    sys.exit(1 if failures else 0)
