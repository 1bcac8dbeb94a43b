#!/usr/bin/python3
# Renders the pictures of the manual and the README from prstar's own output files, with VTK's
# Python bindings, off screen (run it through scripts/make_pictures.sh, which makes the files and
# calls this under xvfb-run when there is no display).
#
# usage: render_pictures.py WORK_DIR OUT_DIR
#   WORK_DIR holds mesh_boundary.vtu and field_boundary.vtu (prstar boundary -o), octree_kv20.vtu
#   and octree_kv200.vtu (prstar stats --octree, on the first mesh), curvature.vtu (prstar
#   curvature -o, on the second), morse.vtu, morse_arcs.vtp, morse_pairs.csv and morse.json
#   (prstar morse -o --arcs --csv --json, on the third), critical.csv (prstar critical --csv, on
#   the third) and names.txt (the three mesh names)
# usage: render_pictures.py --noisy-field IN.vtu OUT.vtu
#   writes OUT.vtu: the mesh of IN.vtu with the point array `f`, a sum of bumps with noise (the
#   field of the topology pictures when the real meshes are absent)
import csv
import json
import math
import os
import random
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


def window(renderer, width=WIDTH, height=HEIGHT):
    w = vtk.vtkRenderWindow()
    w.SetOffScreenRendering(1)
    w.SetSize(width, height)
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
    png.SetCompressionLevel(9)
    png.SetInputConnection(f.GetOutputPort())
    png.Write()
    check_not_blank(path)
    print("wrote", path)


def check_not_blank(path, least=0.02):
    # a picture with almost nothing but the white background (nothing rendered but the title, or a
    # failed off-screen context): fewer than `least` of the pixels darker than near-white
    r = vtk.vtkPNGReader()
    r.SetFileName(path)
    luminance = vtk.vtkImageLuminance()
    luminance.SetInputConnection(r.GetOutputPort())
    drawn = vtk.vtkImageThreshold()
    drawn.SetInputConnection(luminance.GetOutputPort())
    drawn.ThresholdByLower(250)
    drawn.SetInValue(1)
    drawn.SetOutValue(0)
    drawn.SetOutputScalarTypeToFloat()
    stats = vtk.vtkImageAccumulate()
    stats.SetInputConnection(drawn.GetOutputPort())
    stats.Update()
    if stats.GetMean()[0] < least:
        sys.exit(f"render_pictures.py: {path}: the picture is blank ({100 * stats.GetMean()[0]:.2f}% drawn)")
    return stats.GetMean()[0]


def title(renderer, text, height=HEIGHT, size=20):
    t = vtk.vtkTextActor()
    t.SetInput(text)
    t.GetTextProperty().SetColor(0, 0, 0)
    t.GetTextProperty().SetFontSize(size)
    t.SetPosition(12, height - 14 - size)
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


def centre_plane(grid, normal=(1, 0, 0)):
    b = grid.GetBounds()
    plane = vtk.vtkPlane()
    plane.SetOrigin((b[0] + b[1]) / 2, (b[2] + b[3]) / 2, (b[4] + b[5]) / 2)
    plane.SetNormal(*normal)
    return plane


def cut(grid, plane=None):
    # a "crinkle" cut: the whole tetrahedra on one side of a plane through the centre, so that the
    # vertex values are shown as computed, not interpolated on the plane
    if plane is None:
        plane = centre_plane(grid)
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


# The colours of the critical types, by TTK's codes (0 minimum ... 4 degenerate).
CRITICAL_TYPES = [("minimum", (0.10, 0.30, 0.95)), ("1-saddle", (0.10, 0.70, 0.20)),
                  ("2-saddle", (0.95, 0.85, 0.10)), ("maximum", (0.90, 0.10, 0.10)),
                  ("degenerate", (0.70, 0.20, 0.80))]
OUTFLOW = (0.86, 0.86, 0.86)  # the tetrahedra whose gradient path leaves through the boundary


def read_polydata(path):
    r = vtk.vtkXMLPolyDataReader()
    r.SetFileName(path)
    r.Update()
    if r.GetOutput().GetNumberOfCells() == 0:
        sys.exit(f"render_pictures.py: {path}: no cells")
    return r.GetOutput()


def read_rows(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def noisy_field(src, dst):
    # f = four Gaussian bumps and three wells at fixed places of the bounding box, plus uniform noise
    # of 3% of their height, the same on every run (fixed seed): a few persistent extrema and many
    # noisy ones
    grid = read(src)
    b = grid.GetBounds()
    centre = [(b[0] + b[1]) / 2, (b[2] + b[3]) / 2, (b[4] + b[5]) / 2]
    half = [(b[1] - b[0]) / 2, (b[3] - b[2]) / 2, (b[5] - b[4]) / 2]
    places = [((0.5, 0.0, 0.1), 1.0), ((-0.35, 0.45, 0.0), 0.9), ((-0.3, -0.3, 0.4), 0.8),
              ((0.1, -0.1, -0.5), 0.7), ((0.0, 0.5, 0.35), -1.0), ((0.3, -0.45, -0.15), -0.8),
              ((-0.5, 0.0, -0.3), -0.6)]
    bumps = [([centre[k] + half[k] * q[k] for k in range(3)], h, 0.3 * max(half)) for q, h in places]
    rng = random.Random(2026)
    points = grid.GetPoints()
    n = grid.GetNumberOfPoints()
    f = vtk.vtkDoubleArray()
    f.SetName("f")
    f.SetNumberOfValues(n)
    for i in range(n):
        p = points.GetPoint(i)
        v = 0.0
        for c, h, s in bumps:
            d2 = (p[0] - c[0]) ** 2 + (p[1] - c[1]) ** 2 + (p[2] - c[2]) ** 2
            v += h * math.exp(-d2 / (2 * s * s))
        f.SetValue(i, v + 0.03 * rng.uniform(-1, 1))
    grid.GetPointData().AddArray(f)
    w = vtk.vtkXMLUnstructuredGridWriter()
    w.SetFileName(dst)
    w.SetInputData(grid)
    w.SetDataModeToAscii()
    if not w.Write():
        sys.exit(f"render_pictures.py: cannot write {dst}")
    print("wrote", dst)


def palette():
    # categorical pastel colours (ColorBrewer Set3 and Pastel2 as VTK ships them), without the
    # greys, which stand for the tetrahedra flowing out
    colours = []
    for scheme in (vtk.vtkColorSeries.BREWER_QUALITATIVE_SET3, vtk.vtkColorSeries.BREWER_QUALITATIVE_PASTEL2):
        series = vtk.vtkColorSeries()
        series.SetColorScheme(scheme)
        for i in range(series.GetNumberOfColors()):
            c = series.GetColor(i)
            rgb = (c[0] / 255, c[1] / 255, c[2] / 255)
            if max(rgb) - min(rgb) > 0.08:
                colours.append(rgb)
    return colours


def descending_cells_lut(grid):
    # one colour per descending 3-cell (the largest cells first), light grey for -1 (out)
    d = grid.GetCellData().GetArray("descending_cell")
    sizes = {}
    for i in range(d.GetNumberOfTuples()):
        v = d.GetTuple1(i)
        sizes[v] = sizes.get(v, 0) + 1
    labels = sorted((v for v in sizes if v >= 0), key=lambda v: (-sizes[v], v))
    colours = palette()
    lut = vtk.vtkLookupTable()
    lut.IndexedLookupOn()
    lut.SetNumberOfTableValues(len(labels) + 1)
    lut.SetTableValue(0, *OUTFLOW, 1.0)
    lut.SetAnnotation(vtk.vtkVariant(-1.0), "out")
    for k, v in enumerate(labels):
        lut.SetTableValue(k + 1, *colours[k % len(colours)], 1.0)
        lut.SetAnnotation(vtk.vtkVariant(float(v)), str(int(v)))
    return lut, labels


def kept_arcs(arcs, grid, plane):
    # the arcs that end at an extremum kept after the cancellations (a minimum naming an ascending
    # cell, a maximum naming a descending cell), clipped to the kept side of the plane
    a = grid.GetPointData().GetArray("ascending_cell")
    d = grid.GetCellData().GetArray("descending_cell")
    minima = {int(a.GetTuple1(i)) for i in range(a.GetNumberOfTuples())}
    maxima = {int(d.GetTuple1(i)) for i in range(d.GetNumberOfTuples())} - {-1}
    dim = arcs.GetCellData().GetArray("saddle_dimension")
    ext = arcs.GetCellData().GetArray("extremum")
    ids = vtk.vtkIdTypeArray()
    for i in range(arcs.GetNumberOfCells()):
        e = int(ext.GetTuple1(i))
        if e in (minima if int(dim.GetTuple1(i)) == 1 else maxima):
            ids.InsertNextValue(i)
    node = vtk.vtkSelectionNode()
    node.SetFieldType(vtk.vtkSelectionNode.CELL)
    node.SetContentType(vtk.vtkSelectionNode.INDICES)
    node.SetSelectionList(ids)
    selection = vtk.vtkSelection()
    selection.AddNode(node)
    extract = vtk.vtkExtractSelection()
    extract.SetInputData(0, arcs)
    extract.SetInputData(1, selection)
    lines = vtk.vtkGeometryFilter()
    lines.SetInputConnection(extract.GetOutputPort())
    clip = vtk.vtkClipPolyData()
    clip.SetInputConnection(lines.GetOutputPort())
    clip.SetClipFunction(plane)
    clip.InsideOutOn()
    clip.Update()
    return clip.GetOutput(), ids.GetNumberOfTuples()


def critical_point_actor(rows, plane, on_boundary, radius):
    points = vtk.vtkPoints()
    types = vtk.vtkIntArray()
    types.SetName("type")
    for row in rows:
        t = int(row["type"])
        p = (float(row["x"]), float(row["y"]), float(row["z"]))
        if t > 4 or (row["boundary"] == "1") != on_boundary or plane.EvaluateFunction(p) > 0:
            continue
        points.InsertNextPoint(p)
        types.InsertNextValue(t)
    cloud = vtk.vtkPolyData()
    cloud.SetPoints(points)
    cloud.GetPointData().SetScalars(types)
    sphere = vtk.vtkSphereSource()
    sphere.SetRadius(radius)
    sphere.SetThetaResolution(14)
    sphere.SetPhiResolution(10)
    glyphs = vtk.vtkGlyph3D()
    glyphs.SetInputData(cloud)
    glyphs.SetSourceConnection(sphere.GetOutputPort())
    glyphs.SetScaleModeToDataScalingOff()
    glyphs.SetColorModeToColorByScalar()
    lut = vtk.vtkLookupTable()
    lut.SetNumberOfTableValues(len(CRITICAL_TYPES))
    for i, (_, rgb) in enumerate(CRITICAL_TYPES):
        lut.SetTableValue(i, *rgb, 1.0)
    lut.SetTableRange(0, len(CRITICAL_TYPES) - 1)
    m = vtk.vtkPolyDataMapper()
    m.SetInputConnection(glyphs.GetOutputPort())
    m.SetLookupTable(lut)
    m.SetScalarRange(0, len(CRITICAL_TYPES) - 1)
    a = vtk.vtkActor()
    a.SetMapper(m)
    return a, points.GetNumberOfPoints()


def critical_legend(renderer, x, y):
    # a disc of each colour and its name, in black, from (x, y) in pixels upwards
    for i, (text, rgb) in enumerate(reversed(CRITICAL_TYPES)):
        disc = vtk.vtkRegularPolygonSource()
        disc.SetNumberOfSides(24)
        disc.SetRadius(6)
        disc.SetCenter(x + 6, y + 22 * i + 7, 0)
        m = vtk.vtkPolyDataMapper2D()
        m.SetInputConnection(disc.GetOutputPort())
        a = vtk.vtkActor2D()
        a.SetMapper(m)
        a.GetProperty().SetColor(*rgb)
        renderer.AddActor2D(a)
        t = vtk.vtkTextActor()
        t.SetInput(text)
        t.GetTextProperty().SetColor(0, 0, 0)
        t.GetTextProperty().SetFontSize(15)
        t.SetPosition(x + 18, y + 22 * i)
        renderer.AddActor2D(t)


def topology_picture(seg, arcs, critical, info, name, path):
    width, height = 1200, 620
    plane = centre_plane(seg)
    half = cut(seg, plane)
    b = seg.GetBounds()
    diagonal = math.sqrt((b[1] - b[0]) ** 2 + (b[3] - b[2]) ** 2 + (b[5] - b[4]) ** 2)

    # left: the cut coloured by the descending 3-cells
    left = vtk.vtkRenderer()
    left.SetViewport(0, 0, 0.5, 1)
    lut, labels = descending_cells_lut(seg)
    m = vtk.vtkPolyDataMapper()
    m.SetInputData(half)
    m.SetScalarModeToUseCellFieldData()
    m.SelectColorArray("descending_cell")
    m.SetLookupTable(lut)
    m.UseLookupTableScalarRangeOn()
    a = vtk.vtkActor()
    a.SetMapper(m)
    a.GetProperty().SetAmbient(0.3)
    a.GetProperty().SetDiffuse(0.75)
    left.AddActor(a)
    title(left, f"cut: descending 3-cells of the {len(labels)} maxima kept (grey: out of the boundary)",
          height - 30, 15)

    # right: the same half as a ghost, the arcs to the kept extrema and the critical points in it
    right = vtk.vtkRenderer()
    right.SetViewport(0.5, 0, 1, 1)
    right.SetBackground(1, 1, 1)
    right.UseDepthPeelingOn()
    right.SetMaximumNumberOfPeels(16)
    right.SetOcclusionRatio(0.0)
    right.AddActor(surface_actor(half, 0.16))
    lines, count = kept_arcs(arcs, seg, plane)
    tubes = vtk.vtkTubeFilter()
    tubes.SetInputData(lines)
    tubes.SetRadius(0.0012 * diagonal)
    tubes.SetNumberOfSides(8)
    tm = vtk.vtkPolyDataMapper()
    tm.SetInputConnection(tubes.GetOutputPort())
    tm.ScalarVisibilityOff()
    ta = vtk.vtkActor()
    ta.SetMapper(tm)
    ta.GetProperty().SetColor(0.12, 0.12, 0.12)
    right.AddActor(ta)
    inside, n_inside = critical_point_actor(critical, plane, False, 0.006 * diagonal)
    boundary, n_boundary = critical_point_actor(critical, plane, True, 0.0025 * diagonal)
    right.AddActor(inside)
    right.AddActor(boundary)
    critical_legend(right, 470, 20)
    title(right, f"{count} arcs to the kept extrema; critical points: {n_inside} inside,", height - 30, 15)
    title(right, f"{n_boundary} on the boundary (small)", height - 50, 15)

    w = window(left, width, height)
    w.AddRenderer(right)
    w.SetAlphaBitPlanes(1)
    w.SetMultiSamples(0)
    heading = vtk.vtkTextActor()
    heading.SetInput(f"{name}, {info['persistence'] * 100:g}% persistence")
    heading.GetTextProperty().SetColor(0, 0, 0)
    heading.GetTextProperty().SetFontSize(20)
    heading.SetPosition(12, height - 30)
    left.AddActor2D(heading)
    left.ResetCamera(b)
    c = left.GetActiveCamera()
    c.Azimuth(70)
    c.Elevation(15)
    c.Zoom(1.3)
    right.SetActiveCamera(c)
    left.ResetCameraClippingRange()
    right.ResetCameraClippingRange()
    save(w, path)


def persistence_picture(pairs, info, name, path):
    width, height = 640, 520
    view = vtk.vtkContextView()
    view.GetRenderer().SetBackground(1, 1, 1)
    w = view.GetRenderWindow()
    w.SetOffScreenRendering(1)
    w.SetSize(width, height)
    chart = vtk.vtkChartXY()
    view.GetScene().AddItem(chart)

    def table(points, names=("birth", "death")):
        t = vtk.vtkTable()
        for n in names:
            col = vtk.vtkDoubleArray()
            col.SetName(n)
            t.AddColumn(col)
        t.SetNumberOfRows(len(points))
        for i, (x, y) in enumerate(points):
            t.SetValue(i, 0, vtk.vtkVariant(x))
            t.SetValue(i, 1, vtk.vtkVariant(y))
        return t

    lo, hi = info["field_min"], info["field_max"]
    tables = []  # the chart does not keep its tables alive
    for kind, label, rgb in (("minimum-saddle", "minimum-saddle", CRITICAL_TYPES[0][1]),
                             ("saddle-maximum", "saddle-maximum", CRITICAL_TYPES[3][1])):
        points = [(float(r["birth"]), float(r["death"])) for r in pairs
                  if r["type"] == kind and r["saddle"] != ""]
        kept = sum(1 for x, y in points if y - x >= info["threshold"])
        tables.append(table(points))
        p = chart.AddPlot(vtk.vtkChart.POINTS)
        p.SetInputData(tables[-1], 0, 1)
        p.SetColor(int(255 * rgb[0]), int(255 * rgb[1]), int(255 * rgb[2]), 200)
        p.SetMarkerStyle(vtk.vtkPlotPoints.CIRCLE)
        p.SetMarkerSize(7)
        p.SetLabel(f"{label} ({len(points)}, {kept} kept)")
    for offset, label, dashed in ((0.0, "diagonal", False),
                                  (info["threshold"], f"persistence {info['persistence'] * 100:g}%", True)):
        tables.append(table([(lo, lo + offset), (hi - offset, hi)], ("x", "y")))
        p = chart.AddPlot(vtk.vtkChart.LINE)
        p.SetInputData(tables[-1], 0, 1)
        p.SetColor(90, 90, 90, 255)
        p.SetWidth(1.5)
        if dashed:
            p.GetPen().SetLineType(vtk.vtkPen.DASH_LINE)
        p.SetLabel(label)
    for axis, text in ((vtk.vtkAxis.BOTTOM, "birth"), (vtk.vtkAxis.LEFT, "death")):
        ax = chart.GetAxis(axis)
        ax.SetTitle(text)
        ax.SetBehavior(vtk.vtkAxis.FIXED)
        ax.SetRange(lo - 0.02 * (hi - lo), hi + 0.02 * (hi - lo))
        ax.GetTitleProperties().SetFontSize(15)
        ax.GetLabelProperties().SetFontSize(13)
    chart.SetShowLegend(True)
    chart.GetLegend().SetHorizontalAlignment(vtk.vtkChartLegend.RIGHT)
    chart.GetLegend().SetVerticalAlignment(vtk.vtkChartLegend.BOTTOM)
    chart.GetLegend().GetLabelProperties().SetFontSize(13)
    chart.SetTitle(f"{name}: persistence diagram (essential pairs not shown)")
    chart.GetTitleProperties().SetFontSize(16)
    w.Render()
    save(w, path)


def main():
    if len(sys.argv) == 4 and sys.argv[1] == "--noisy-field":
        noisy_field(sys.argv[2], sys.argv[3])
        return
    if len(sys.argv) != 3:
        sys.exit("usage: render_pictures.py WORK_DIR OUT_DIR | --noisy-field IN.vtu OUT.vtu")
    work, out = sys.argv[1], sys.argv[2]
    os.makedirs(out, exist_ok=True)
    with open(os.path.join(work, "names.txt")) as f:
        octree_name, field_name, topology_name = [line.strip() for line in f][:3]

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

    with open(os.path.join(work, "morse.json")) as f:
        info = json.load(f)
    topology_picture(read(os.path.join(work, "morse.vtu")), read_polydata(os.path.join(work, "morse_arcs.vtp")),
                     read_rows(os.path.join(work, "critical.csv")), info, topology_name,
                     os.path.join(out, "morse_cells_cut.png"))
    persistence_picture(read_rows(os.path.join(work, "morse_pairs.csv")), info, topology_name,
                        os.path.join(out, "persistence_diagram.png"))


if __name__ == "__main__":
    main()
