#!/usr/bin/python3
# Renders the pictures of the manual and the README from prstar's own output files, with VTK's
# Python bindings, off screen (run it through scripts/make_pictures.sh, which makes the files and
# calls this under xvfb-run when there is no display).
#
# usage: render_pictures.py WORK_DIR OUT_DIR
#   WORK_DIR holds mesh_boundary.vtu and field_boundary.vtu (prstar boundary -o), octree_kv20.vtu
#   and octree_kv200.vtu (prstar stats --octree, on the first mesh), curvature.vtu (prstar
#   curvature -o, on the second) and names.txt (the two mesh names)
import os
import sys

import vtk

WIDTH, HEIGHT = 900, 700


def read(path):
    r = vtk.vtkXMLUnstructuredGridReader()
    r.SetFileName(path)
    r.Update()
    if r.GetOutput().GetNumberOfCells() == 0:
        sys.exit(f"render_pictures.py: {path}: no cells")
    return r.GetOutput()


def window(renderer):
    w = vtk.vtkRenderWindow()
    w.SetOffScreenRendering(1)
    w.SetSize(WIDTH, HEIGHT)
    w.AddRenderer(renderer)
    renderer.SetBackground(1, 1, 1)
    return w


def save(w, path):
    w.Render()
    f = vtk.vtkWindowToImageFilter()
    f.SetInput(w)
    f.ReadFrontBufferOff()
    f.Update()
    png = vtk.vtkPNGWriter()
    png.SetFileName(path)
    png.SetInputConnection(f.GetOutputPort())
    png.Write()
    print("wrote", path)


def title(renderer, text):
    t = vtk.vtkTextActor()
    t.SetInput(text)
    t.GetTextProperty().SetColor(0, 0, 0)
    t.GetTextProperty().SetFontSize(20)
    t.SetPosition(12, HEIGHT - 34)
    renderer.AddActor2D(t)


def camera(renderer, bounds):
    renderer.ResetCamera(bounds)
    c = renderer.GetActiveCamera()
    c.Azimuth(35)
    c.Elevation(25)
    c.Zoom(1.25)
    renderer.ResetCameraClippingRange()


def surface_actor(grid, opacity):
    s = vtk.vtkDataSetSurfaceFilter()
    s.SetInputData(grid)
    m = vtk.vtkPolyDataMapper()
    m.SetInputConnection(s.GetOutputPort())
    m.ScalarVisibilityOff()
    a = vtk.vtkActor()
    a.SetMapper(m)
    a.GetProperty().SetColor(0.80, 0.80, 0.78)
    a.GetProperty().SetOpacity(opacity)
    return a


def octree_picture(mesh, leaves, kv, name, path):
    r = vtk.vtkRenderer()
    r.AddActor(surface_actor(mesh, 0.35))
    edges = vtk.vtkExtractEdges()
    edges.SetInputData(leaves)
    m = vtk.vtkPolyDataMapper()
    m.SetInputConnection(edges.GetOutputPort())
    m.SetScalarModeToUseCellFieldData()
    m.SelectColorArray("depth")
    rng = leaves.GetCellData().GetArray("depth").GetRange()
    m.SetScalarRange(rng)
    lut = vtk.vtkLookupTable()
    lut.SetHueRange(0.66, 0.0)
    lut.Build()
    m.SetLookupTable(lut)
    a = vtk.vtkActor()
    a.SetMapper(m)
    a.GetProperty().SetLineWidth(1.2)
    r.AddActor(a)
    bar = vtk.vtkScalarBarActor()
    bar.SetLookupTable(lut)
    bar.SetTitle("depth")
    bar.SetNumberOfLabels(int(rng[1] - rng[0]) + 1)
    bar.GetTitleTextProperty().SetColor(0, 0, 0)
    bar.GetLabelTextProperty().SetColor(0, 0, 0)
    bar.SetWidth(0.08)
    r.AddActor2D(bar)
    title(r, f"{name}: PR-star octree leaves, k_v = {kv} ({leaves.GetNumberOfCells()} leaves)")
    w = window(r)
    camera(r, mesh.GetBounds())
    save(w, path)


def cut(grid):
    # a "crinkle" cut: the whole tetrahedra on one side of a plane through the centre, so that the
    # vertex values are shown as computed, not interpolated on the plane
    b = grid.GetBounds()
    plane = vtk.vtkPlane()
    plane.SetOrigin((b[0] + b[1]) / 2, (b[2] + b[3]) / 2, (b[4] + b[5]) / 2)
    plane.SetNormal(1, 0, 0)
    clip = vtk.vtkExtractGeometry()
    clip.SetInputData(grid)
    clip.SetImplicitFunction(plane)
    clip.ExtractInsideOn()
    clip.ExtractBoundaryCellsOn()
    clip.Update()
    s = vtk.vtkDataSetSurfaceFilter()
    s.SetInputConnection(clip.GetOutputPort())
    s.Update()
    return s.GetOutput()


def field_picture(grid, array, lut, scalar_range, text, path, bar_title):
    r = vtk.vtkRenderer()
    m = vtk.vtkPolyDataMapper()
    m.SetInputData(cut(grid))
    m.SetScalarModeToUsePointFieldData()
    m.SelectColorArray(array)
    m.SetScalarRange(scalar_range)
    m.SetLookupTable(lut)
    m.InterpolateScalarsBeforeMappingOn()
    a = vtk.vtkActor()
    a.SetMapper(m)
    a.GetProperty().EdgeVisibilityOn()
    a.GetProperty().SetEdgeColor(0.25, 0.25, 0.25)
    a.GetProperty().SetLineWidth(0.4)
    r.AddActor(a)
    bar = vtk.vtkScalarBarActor()
    bar.SetLookupTable(lut)
    bar.SetTitle(bar_title)
    bar.GetTitleTextProperty().SetColor(0, 0, 0)
    bar.GetLabelTextProperty().SetColor(0, 0, 0)
    bar.SetWidth(0.08)
    r.AddActor2D(bar)
    title(r, text)
    w = window(r)
    camera(r, grid.GetBounds())
    save(w, path)


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: render_pictures.py WORK_DIR OUT_DIR")
    work, out = sys.argv[1], sys.argv[2]
    os.makedirs(out, exist_ok=True)
    with open(os.path.join(work, "names.txt")) as f:
        octree_name, field_name = [line.strip() for line in f][:2]

    mesh = read(os.path.join(work, "mesh_boundary.vtu"))
    for kv in (20, 200):
        octree_picture(mesh, read(os.path.join(work, f"octree_kv{kv}.vtu")), kv, octree_name,
                       os.path.join(out, f"octree_kv{kv}.png"))

    classes = vtk.vtkLookupTable()
    classes.SetNumberOfTableValues(4)
    for i, rgb in enumerate([(0.23, 0.45, 0.80), (0.85, 0.20, 0.15), (0.95, 0.80, 0.10), (0.6, 0.6, 0.6)]):
        classes.SetTableValue(i, *rgb, 1.0)
    classes.Build()
    field_picture(read(os.path.join(work, "field_boundary.vtu")), "boundary", classes, (-0.5, 3.5),
                  f"{field_name}, cut: interior (blue), boundary (red), non-manifold (yellow)",
                  os.path.join(out, "boundary_cut.png"), "class")

    curvature = read(os.path.join(work, "curvature.vtu"))
    d = curvature.GetPointData().GetArray("distortion")
    values = sorted(abs(d.GetValue(i)) for i in range(d.GetNumberOfTuples()))
    bound = values[int(0.95 * (len(values) - 1))] or 1.0  # the 95th percentile of |distortion|
    diverging = vtk.vtkLookupTable()
    diverging.SetHueRange(0.66, 0.0)
    diverging.SetSaturationRange(0.8, 0.8)
    diverging.Build()
    field_picture(curvature, "distortion", diverging, (-bound, bound),
                  f"{field_name}, cut: discrete distortion of its scalar field",
                  os.path.join(out, "distortion_cut.png"), "distortion")


if __name__ == "__main__":
    main()
