#!/usr/bin/python3
# Copyright (c) 2026 The PR-star octree project.
# SPDX-License-Identifier: LGPL-3.0-or-later
#
# Renders a tetrahedral mesh and its simplification side by side: the boundary surface of each
# (vtkDataSetSurfaceFilter), flat shaded with its edges, under the same camera, into one PNG.  VTK's
# Python bindings (python3-vtk9), off screen; on a machine without a display run it under xvfb-run.
#
# usage: render_simplification.py INPUT SIMPLIFIED OUT.png [--size WxH] [--view AZIMUTH,ELEVATION]
#                                 [--zoom Z] [--focus FX,FY,FZ] [--labels "left title" "right title"]
#   --focus: the point looked at, as fractions of the input's bounding box (default 0.5,0.5,0.5, the
#   centre); with --zoom, a close-up of a detail (fine input meshes make a picture of edges only).
#   INPUT, SIMPLIFIED: any file VTK reads (.vtu, .vtk, .vtp, .stl, .ply, .obj); cells other than
#   tetrahedra are rendered too.
# example (doc/PR_star_octree/fig/simplification_fandisk.png):
#   prstar simplify fandisk_tetgen_1m.vtu --target 0.75 -o fandisk_75.vtu
#   xvfb-run -a /usr/bin/python3 scripts/render_simplification.py fandisk_tetgen_1m.vtu fandisk_75.vtu \
#       doc/PR_star_octree/fig/simplification_fandisk.png
import argparse
import os
import sys

try:
    import vtk
except ImportError as e:
    sys.exit(f"render_simplification.py: VTK's Python bindings cannot be imported ({e}); install python3-vtk9")


def read(path):
    ext = os.path.splitext(path)[1].lower()
    readers = {".vtu": vtk.vtkXMLUnstructuredGridReader, ".vtp": vtk.vtkXMLPolyDataReader,
               ".vtk": vtk.vtkDataSetReader, ".stl": vtk.vtkSTLReader, ".ply": vtk.vtkPLYReader,
               ".obj": vtk.vtkOBJReader}
    if ext not in readers:
        sys.exit(f"render_simplification.py: {path}: unknown extension (known: {', '.join(readers)})")
    if not os.path.exists(path):
        sys.exit(f"render_simplification.py: {path}: no such file")
    r = readers[ext]()
    r.SetFileName(path)
    r.Update()
    data = r.GetOutput()
    if data is None or data.GetNumberOfCells() == 0:
        sys.exit(f"render_simplification.py: {path}: no cells")
    return data


def surface(data):
    s = vtk.vtkDataSetSurfaceFilter()
    s.SetInputData(data)
    s.Update()
    return s.GetOutput()


def count(data):
    n = data.GetNumberOfCells()
    tets = sum(1 for i in range(n) if data.GetCellType(i) == vtk.VTK_TETRA) if n < 5_000_000 else n
    return f"{tets:,} tetrahedra" if tets else f"{n:,} cells"


def main():
    p = argparse.ArgumentParser(description="Input and simplified meshes side by side (boundary with edges).")
    p.add_argument("input")
    p.add_argument("simplified")
    p.add_argument("output", help="PNG file")
    p.add_argument("--size", default="1400x620", help="WxH in pixels (default 1400x620)")
    p.add_argument("--view", default="-35,25", help="camera azimuth,elevation in degrees (default -35,25)")
    p.add_argument("--zoom", type=float, default=1.25)
    p.add_argument("--focus", default="0.5,0.5,0.5", help="point looked at, in fractions of the bounding box")
    p.add_argument("--colors", type=int, default=48,
                   help="quantize the picture to this many colours, for a small PNG (0: no quantization)")
    p.add_argument("--labels", nargs=2, metavar=("LEFT", "RIGHT"), help="titles (default: file names and counts)")
    a = p.parse_args()
    width, height = (int(x) for x in a.size.lower().split("x"))
    azimuth, elevation = (float(x) for x in a.view.split(","))
    focus = [float(x) for x in a.focus.split(",")]

    meshes = [read(a.input), read(a.simplified)]
    labels = a.labels or [f"{os.path.basename(path)}: {count(m)}" for path, m in zip((a.input, a.simplified), meshes)]
    window = vtk.vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetMultiSamples(0)  # crisp edges: fewer colours, a smaller PNG
    window.SetSize(width, height)
    camera = vtk.vtkCamera()
    bounds = [0.0] * 6
    for i, (mesh, label) in enumerate(zip(meshes, labels)):
        poly = surface(mesh)
        mapper = vtk.vtkPolyDataMapper()
        mapper.SetInputData(poly)
        mapper.ScalarVisibilityOff()
        actor = vtk.vtkActor()
        actor.SetMapper(mapper)
        prop = actor.GetProperty()
        prop.SetColor(0.78, 0.84, 0.93)
        prop.SetInterpolationToFlat()
        prop.EdgeVisibilityOn()
        prop.SetEdgeColor(0.15, 0.2, 0.3)
        prop.SetLineWidth(0.5)
        renderer = vtk.vtkRenderer()
        renderer.SetViewport(i / 2, 0, (i + 1) / 2, 1)
        renderer.SetBackground(1, 1, 1)
        renderer.AddActor(actor)
        renderer.SetActiveCamera(camera)  # the same camera for both
        text = vtk.vtkTextActor()
        text.SetInput(label)
        text.GetTextProperty().SetColor(0, 0, 0)
        text.GetTextProperty().SetFontSize(18)
        text.GetTextProperty().SetBackgroundColor(1, 1, 1)
        text.GetTextProperty().SetBackgroundOpacity(0.85)
        text.SetPosition(10, height - 30)
        renderer.AddActor2D(text)
        window.AddRenderer(renderer)
        if i == 0:
            bounds = poly.GetBounds()
            renderer.ResetCamera(bounds)
            camera.Azimuth(azimuth)
            camera.Elevation(elevation)
            camera.OrthogonalizeViewUp()
            renderer.ResetCamera(bounds)
            target = [bounds[2 * k] + focus[k] * (bounds[2 * k + 1] - bounds[2 * k]) for k in range(3)]
            shift = [target[k] - camera.GetFocalPoint()[k] for k in range(3)]
            camera.SetFocalPoint(*target)
            camera.SetPosition(*[camera.GetPosition()[k] + shift[k] for k in range(3)])
            camera.Zoom(a.zoom)
    window.Render()
    grab = vtk.vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.ReadFrontBufferOff()
    grab.Update()
    image = grab.GetOutputPort()
    if a.colors > 0:
        # A few colours compress far better (a palette of a.colors, each pixel mapped back to RGB).
        rgb = vtk.vtkImageExtractComponents()
        rgb.SetInputConnection(image)
        rgb.SetComponents(0, 1, 2)
        quantize = vtk.vtkImageQuantizeRGBToIndex()
        quantize.SetInputConnection(rgb.GetOutputPort())
        quantize.SetNumberOfColors(a.colors)
        quantize.Update()
        colors = vtk.vtkImageMapToColors()
        colors.SetInputConnection(quantize.GetOutputPort())
        colors.SetLookupTable(quantize.GetLookupTable())
        colors.SetOutputFormatToRGB()
        image = colors.GetOutputPort()
    png = vtk.vtkPNGWriter()
    png.SetFileName(a.output)
    png.SetCompressionLevel(9)
    png.SetInputConnection(image)
    png.Write()
    print(f"wrote {a.output} ({os.path.getsize(a.output) // 1024} KB)")


if __name__ == "__main__":
    main()
