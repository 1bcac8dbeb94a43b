#!/usr/bin/python3
# Copyright (c) 2026 The PR-star octree project.
# SPDX-License-Identifier: LGPL-3.0-or-later
"""Reads a ParaView file, computes the boundary and the curvature with prstar, and saves a picture.

    boundary_and_curvature.py MESH.vtu [FIELD] [-o picture.png]

MESH is any file prstar reads (a ParaView .vtu/.vtk, gmsh .msh, Medit .mesh, TetGen .node/.ele,
XDMF); FIELD a point-data array of it (default: its first one, else the z coordinate).  The picture
shows the boundary surface coloured by the discrete distortion of the field, rendered off screen
with VTK (python3-vtk9; run under xvfb-run where there is no display).  Prints the counts.
"""

import argparse
import sys

import numpy as np

import prstar


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("mesh")
    parser.add_argument("field", nargs="?")
    parser.add_argument("-o", "--output", default="boundary_and_curvature.png")
    args = parser.parse_args()

    mesh = prstar.read(args.mesh)  # numpy arrays: points, tetrahedra, labels, point_data...
    field = args.field or (next(iter(mesh.point_data)) if mesh.point_data else "z")
    tree = prstar.Octree(mesh.points, mesh.tetrahedra, labels=mesh.labels)  # built once, used twice
    b = prstar.boundary(tree)
    c = prstar.curvature(tree, mesh.point_data[field] if field in mesh.point_data else field)
    print(f"{args.mesh}: {b.counts['boundary_vertices']} boundary vertices of {b.counts['vertices']}, "
          f"{b.counts['boundary_triangles']} boundary triangles")
    on = b.vertex_types == prstar.BOUNDARY
    print(f"distortion of {field!r} on the boundary: min {np.nanmin(c.distortion[on]):.4g}, "
          f"max {np.nanmax(c.distortion[on]):.4g}")

    # The boundary surface coloured by the distortion, with VTK (no file in between).
    import vtkmodules.all as vtk
    from vtkmodules.util.numpy_support import numpy_to_vtk, numpy_to_vtkIdTypeArray

    tri = b.boundary_triangles.astype(np.int64)
    cells = np.hstack([np.full((len(tri), 1), 3), tri]).ravel()
    surface = vtk.vtkPolyData()
    points = vtk.vtkPoints()
    points.SetData(numpy_to_vtk(np.ascontiguousarray(mesh.points), deep=True))
    surface.SetPoints(points)
    polys = vtk.vtkCellArray()
    polys.SetCells(len(tri), numpy_to_vtkIdTypeArray(cells, deep=True))
    surface.SetPolys(polys)
    values = np.nan_to_num(c.distortion)
    surface.GetPointData().SetScalars(numpy_to_vtk(values, deep=True))

    mapper = vtk.vtkPolyDataMapper()
    mapper.SetInputData(surface)
    limit = float(np.percentile(np.abs(values[on]), 98)) or 1.0
    mapper.SetScalarRange(-limit, limit)
    lut = vtk.vtkLookupTable()  # diverging: blue (negative), white (0), red (positive)
    lut.SetNumberOfTableValues(256)
    for k in range(256):
        t = k / 255
        lut.SetTableValue(k, min(1.0, 2 * t), 1 - abs(2 * t - 1) * 0.75, min(1.0, 2 - 2 * t), 1.0)
    lut.Build()
    mapper.SetLookupTable(lut)
    actor = vtk.vtkActor()
    actor.SetMapper(mapper)
    bar = vtk.vtkScalarBarActor()
    bar.SetLookupTable(lut)
    bar.SetTitle(f"distortion of {field}")
    bar.SetNumberOfLabels(3)
    renderer = vtk.vtkRenderer()
    renderer.AddActor(actor)
    renderer.AddActor2D(bar)
    renderer.SetBackground(1, 1, 1)
    bar.GetTitleTextProperty().SetColor(0, 0, 0)
    bar.GetLabelTextProperty().SetColor(0, 0, 0)
    renderer.GetActiveCamera().Azimuth(30)
    renderer.GetActiveCamera().Elevation(20)
    renderer.ResetCamera()
    window = vtk.vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetSize(800, 600)
    window.AddRenderer(renderer)
    window.Render()
    grab = vtk.vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.Update()
    writer = vtk.vtkPNGWriter()
    writer.SetFileName(args.output)
    writer.SetInputConnection(grab.GetOutputPort())
    writer.Write()
    print(f"wrote {args.output}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
