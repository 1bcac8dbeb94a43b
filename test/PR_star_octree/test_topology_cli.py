#!/usr/bin/python3
# Copyright (c) 2026 The PR-star octree project.
# SPDX-License-Identifier: LGPL-3.0-or-later
#
# prstar critical and prstar morse against references computed here, from the tetrahedra alone
# (numpy), never from the tool:
# - critical: the lower and upper links of every vertex (the triangles opposite it in its
#   tetrahedra), their connected components through the link edges with both ends on the same side
#   of the (value, index) order, the boundary flag (a link edge not in exactly two link triangles):
#   the counts, every listed point of --json, every --csv row and the -o point arrays read by VTK;
# - --gradient: alternating sum = Euler characteristic = V - E + F - T counted here, 4 bytes per
#   tetrahedron, and the critical simplices of each dimension those of a perfect gradient: the
#   minima, and the Betti numbers b0 - 1, b1, b2 of the lower links (from their Euler characteristic);
# - morse: the persistence pairs by a union-find over the edge graph in the (value, index) order
#   and its reverse (elder rule), in --json and --csv; the ascending cells by steepest descent and
#   the cancellations resolved here; the descending cells around every interior maximum; the arcs
#   (.vtp read by VTK) against steepest-descent paths, the critical triangles against the mesh;
# - the same JSON for --kv 1, 8, 50, inf and --threads 1, 2, 8;
# - errors: unknown field, NaN in the field, --persistence 2, a missing file (exit codes, messages).
# Meshes: jittered lattices of `prstar generate` with fields written here (a bowl, three bumps, a
# linear field, noise, plateaus, two components with a vertex in no tetrahedron), the generated
# test meshes (Medit, VTU: TEST_DATA_DIR) and, when present, the shared meshes t13_data.1.node
# (TetGen) and spx_zsweep.off (tet-OFF with its own scalar).
# Usage: test_topology_cli.py PRSTAR WORKDIR [SHARED_DATA_DIR [TEST_DATA_DIR]].
# Exit 77 (skipped) without numpy or VTK's Python bindings.
import csv
import json
import math
import os
import shutil
import subprocess
import sys
import time
import traceback

try:
    import numpy as np
    from vtkmodules.vtkCommonCore import vtkPoints
    from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkUnstructuredGrid, VTK_TETRA
    from vtkmodules.vtkIOXML import (vtkXMLPolyDataReader, vtkXMLUnstructuredGridReader,
                                     vtkXMLUnstructuredGridWriter)
    from vtkmodules.util.numpy_support import numpy_to_vtk, numpy_to_vtkIdTypeArray, vtk_to_numpy
except ImportError as e:
    print("skipped: %s" % e)
    sys.exit(77)
try:
    import meshio
except ImportError:
    meshio = None

if len(sys.argv) < 3:
    print("usage: test_topology_cli.py PRSTAR WORKDIR [SHARED_DATA_DIR [TEST_DATA_DIR]]")
    sys.exit(2)
PRSTAR, WORK = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
SHARED = sys.argv[3] if len(sys.argv) > 3 else ""
TEST_DATA = sys.argv[4] if len(sys.argv) > 4 else ""
shutil.rmtree(WORK, ignore_errors=True)
os.makedirs(WORK)
START = time.time()
failures = []
checks = [0]


def check(ok, what):
    checks[0] += 1
    if not ok:
        failures.append(what)
        print("FAILED: " + what)
    return ok


def path(name):
    return os.path.join(WORK, name)


def prstar(*args, expect=0):
    args = [str(a) for a in args]
    r = subprocess.run([PRSTAR] + args, cwd=WORK, capture_output=True, text=True, timeout=600)
    check(r.returncode >= 0 and r.returncode < 128,
          "prstar %s: crashed (exit %d)\n%s" % (" ".join(args), r.returncode, r.stderr[-2000:]))
    check("Traceback" not in r.stderr and "terminate called" not in r.stderr,
          "prstar %s: a crash message on stderr: %s" % (" ".join(args), r.stderr[-2000:]))
    if expect is not None:
        check(r.returncode == expect, "prstar %s: exit %d, expected %d\n%s%s" %
              (" ".join(args), r.returncode, expect, r.stdout[-2000:], r.stderr[-2000:]))
    return r


def prstar_json(*args):
    r = prstar(*args, "--json")
    try:
        return json.loads(r.stdout)
    except ValueError:
        check(False, "prstar %s --json: not JSON: %s" % (" ".join(map(str, args)), r.stdout[-500:]))
        return None


# ---------------------------------------------------------------------------------------------
# Reading and writing meshes (VTK, meshio, TetGen by hand)

def read_vtu(file):
    """points, tetrahedra, {point array name: values}, {cell array name: values}"""
    r = vtkXMLUnstructuredGridReader()
    r.SetFileName(file)
    r.Update()
    g = r.GetOutput()
    pts = vtk_to_numpy(g.GetPoints().GetData()).astype(float)
    conn = vtk_to_numpy(g.GetCells().GetConnectivityArray()).astype(np.int64)
    offs = vtk_to_numpy(g.GetCells().GetOffsetsArray()).astype(np.int64)
    types = vtk_to_numpy(g.GetCellTypesArray())
    sizes = np.diff(offs)
    keep = (types == VTK_TETRA) & (sizes == 4)
    tets = np.array([conn[offs[i]:offs[i] + 4] for i in np.nonzero(keep)[0]], dtype=np.int64).reshape(-1, 4)
    pd = {}
    for i in range(g.GetPointData().GetNumberOfArrays()):
        a = g.GetPointData().GetArray(i)
        if a is not None:
            pd[a.GetName()] = vtk_to_numpy(a).astype(float)
    cd = {}
    for i in range(g.GetCellData().GetNumberOfArrays()):
        a = g.GetCellData().GetArray(i)
        if a is not None:
            cd[a.GetName()] = vtk_to_numpy(a).astype(float)[keep]
    return pts, tets, pd, cd


def write_vtu(file, pts, tets, fields):
    """VTK XML with inline binary data (no compression), Float64 point arrays; inline because this
    test reads some back with VTK, whose 9.1/9.2 versions read no appended data with Debian 12's
    current libexpat (interop_vtk.py feeds the tool VTK's appended files)"""
    g = vtkUnstructuredGrid()
    p = vtkPoints()
    p.SetData(numpy_to_vtk(np.ascontiguousarray(pts, dtype=np.float64), deep=True))
    g.SetPoints(p)
    cells = vtkCellArray()
    offsets = numpy_to_vtkIdTypeArray(np.arange(0, 4 * len(tets) + 1, 4, dtype=np.int64), deep=True)
    conn = numpy_to_vtkIdTypeArray(np.ascontiguousarray(tets, dtype=np.int64).ravel(), deep=True)
    cells.SetData(offsets, conn)
    g.SetCells(VTK_TETRA, cells)
    for name, values in fields.items():
        a = numpy_to_vtk(np.ascontiguousarray(values, dtype=np.float64), deep=True)
        a.SetName(name)
        g.GetPointData().AddArray(a)
    w = vtkXMLUnstructuredGridWriter()
    w.SetFileName(file)
    w.SetInputData(g)
    w.SetCompressorTypeToNone()
    w.SetDataModeToBinary()
    if not w.Write():
        raise RuntimeError("VTK could not write " + file)


def read_medit(file):
    m = meshio.read(file)
    tets = np.concatenate([c.data for c in m.cells if c.type == "tetra"]).astype(np.int64)
    return np.asarray(m.points, dtype=float), tets


def read_tetgen(node_file):
    """TetGen .node/.ele by hand: points in file order, tetrahedra renumbered from the first index"""
    with open(node_file) as f:
        rows = [l.split("#")[0].split() for l in f]
    rows = [r for r in rows if r]
    n = int(rows[0][0])
    body = rows[1:1 + n]
    base = int(body[0][0])
    pts = np.array([[float(x) for x in r[1:4]] for r in body])
    with open(node_file[:-5] + ".ele") as f:
        rows = [l.split("#")[0].split() for l in f]
    rows = [r for r in rows if r]
    m = int(rows[0][0])
    tets = np.array([[int(x) - base for x in r[1:5]] for r in rows[1:1 + m]], dtype=np.int64)
    return pts, tets


def read_vtp(file):
    r = vtkXMLPolyDataReader()
    r.SetFileName(file)
    r.Update()
    g = r.GetOutput()
    n = g.GetNumberOfPoints()
    pts = vtk_to_numpy(g.GetPoints().GetData()).astype(float) if n else np.zeros((0, 3))
    lines = g.GetLines()
    conn = vtk_to_numpy(lines.GetConnectivityArray()).astype(np.int64) if g.GetNumberOfLines() else []
    offs = vtk_to_numpy(lines.GetOffsetsArray()).astype(np.int64) if g.GetNumberOfLines() else [0]
    polylines = [pts[conn[offs[i]:offs[i + 1]]] for i in range(len(offs) - 1)]
    cd = {}
    for i in range(g.GetCellData().GetNumberOfArrays()):
        a = g.GetCellData().GetArray(i)
        cd[a.GetName()] = vtk_to_numpy(a)
    return polylines, cd


# ---------------------------------------------------------------------------------------------
# The references, from the points, tetrahedra and field alone

TYPE_NAMES = ["minimum", "1-saddle", "2-saddle", "maximum", "degenerate", "regular"]


def classify(lo, up):
    if lo == 0 and up == 0:
        return 5
    if lo == 0:
        return 0
    if up == 0:
        return 3
    if lo == 1 and up == 1:
        return 5
    if lo == 2 and up == 1:
        return 1
    if lo == 1 and up == 2:
        return 2
    return 4


def components(n, a, b):
    """connected component labels (the smallest node of each) of n nodes joined by the edges a-b"""
    lab = np.arange(n)
    if len(a) == 0:
        return lab
    while True:
        old = lab.copy()
        m = np.minimum(lab[a], lab[b])
        np.minimum.at(lab, a, m)
        np.minimum.at(lab, b, m)
        lab = lab[lab]
        if np.array_equal(lab, old):
            return lab


class Truth:
    """Everything the checks compare with, computed from the tetrahedra by brute force."""

    def __init__(self, pts, tets, f):
        nv = len(pts)
        self.pts, self.tets, self.f, self.nv = pts, tets, np.asarray(f, dtype=float), nv
        f = self.f
        self.order = np.lexsort((np.arange(nv), f))  # (value, index)
        self.rank = np.empty(nv, dtype=np.int64)
        self.rank[self.order] = np.arange(nv)
        rank = self.rank
        self.referenced = np.zeros(nv, dtype=bool)
        self.referenced[tets.ravel()] = True
        # the link triangles: corner i of each tetrahedron, the other three
        centre = tets.T.ravel()
        others = np.concatenate([tets[:, [1, 2, 3]], tets[:, [0, 2, 3]], tets[:, [0, 1, 3]], tets[:, [0, 1, 2]]])
        ea = np.concatenate([others[:, 0], others[:, 0], others[:, 1]])
        eb = np.concatenate([others[:, 1], others[:, 2], others[:, 2]])
        ec = np.tile(centre, 3)
        lo, hi = np.minimum(ea, eb), np.maximum(ea, eb)
        # the boundary flag: a link edge not in exactly two link triangles
        key = (ec * nv + lo) * nv + hi
        u, cnt = np.unique(key, return_counts=True)
        self.open = np.zeros(nv, dtype=bool)
        self.open[u[cnt != 2] // (nv * nv)] = True
        # the link vertices (centre, neighbour) as nodes; the link edges with both ends on one side
        node_keys = np.unique(np.concatenate([ec * nv + lo, ec * nv + hi]))
        nc, nn = node_keys // nv, node_keys % nv
        lower = rank[nn] < rank[nc]
        ue = np.unique(key)
        uc, ul, uh = ue // (nv * nv), (ue // nv) % nv, ue % nv
        ia = np.searchsorted(node_keys, uc * nv + ul)
        ib = np.searchsorted(node_keys, uc * nv + uh)
        same = lower[ia] == lower[ib]
        lab = components(len(node_keys), ia[same], ib[same])
        roots = np.nonzero(lab == np.arange(len(node_keys)))[0]
        self.lower = np.bincount(nc[roots[lower[roots]]], minlength=nv)
        self.upper = np.bincount(nc[roots[~lower[roots]]], minlength=nv)
        self.types = np.array([classify(a, b) for a, b in zip(self.lower.tolist(), self.upper.tolist())])
        # the Betti numbers of the lower link from its Euler characteristic (b2 = 1 only for a
        # closed link entirely below): a perfect gradient has, in the lower star of each vertex,
        # b0 - 1 critical edges, b1 critical triangles, b2 critical tetrahedra
        chi = np.bincount(nc[lower], minlength=nv) - np.bincount(uc[lower[ia] & lower[ib]], minlength=nv) + \
            np.bincount(centre[rank[others].max(axis=1) < rank[centre]], minlength=nv)
        b2 = (~self.open & (self.upper == 0) & (self.lower > 0)).astype(np.int64)
        self.betti1 = self.lower + b2 - chi
        self.betti2 = b2
        # the edges of the tetrahedra: the vertex graph
        pairs = np.concatenate([tets[:, [a, b]] for a in range(4) for b in range(a + 1, 4)])
        pairs.sort(axis=1)
        edges = np.unique(pairs[:, 0] * nv + pairs[:, 1])
        self.edges = np.stack([edges // nv, edges % nv], axis=1)
        tris = np.concatenate([np.sort(tets[:, [a, b, c]], axis=1)
                               for a, b, c in ((0, 1, 2), (0, 1, 3), (0, 2, 3), (1, 2, 3))])
        tkeys = (tris[:, 0] * nv + tris[:, 1]) * nv + tris[:, 2]
        ut, tcount = np.unique(tkeys, return_counts=True)
        self.triangle_tets = dict(zip(ut.tolist(), tcount.tolist()))  # triangle key -> tetrahedra
        self.euler = int(self.referenced.sum()) - len(self.edges) + len(ut) - len(tets)
        adj = [[] for _ in range(nv)]
        for a, b in self.edges.tolist():
            adj[a].append(b)
            adj[b].append(a)
        self.adj = adj
        # steepest descent and ascent: the lowest (highest) neighbour, if lower (higher)
        a, b = self.edges[:, 0], self.edges[:, 1]
        low = np.full(nv, nv, dtype=np.int64)
        np.minimum.at(low, a, rank[b])
        np.minimum.at(low, b, rank[a])
        high = np.full(nv, -1, dtype=np.int64)
        np.maximum.at(high, a, rank[b])
        np.maximum.at(high, b, rank[a])
        self.descent = np.where(low < rank, self.order[np.minimum(low, nv - 1)], np.arange(nv))
        self.ascent = np.where(high > rank, self.order[np.maximum(high, 0)], np.arange(nv))
        self.min_root = self.resolve(self.descent)
        self.max_root = self.resolve(self.ascent)
        self.field_min = float(f[self.referenced].min())
        self.field_max = float(f[self.referenced].max())
        self.pairs, self.min_into, self.max_into = self.persistence()

    @staticmethod
    def resolve(p):
        r = p.copy()
        while True:
            n = r[r]
            if np.array_equal(n, r):
                return r
            r = n

    def elder(self, seq, kind):
        """0-dimensional persistence over the vertex graph, the vertices taken in `seq`"""
        pos = np.empty(self.nv, dtype=np.int64)
        pos[seq] = np.arange(len(seq))
        parent = {}
        oldest = {}
        pairs, into = [], {}

        def find(x):
            while parent[x] != x:
                parent[x] = parent[parent[x]]
                x = parent[x]
            return x
        f = self.f
        for v in seq.tolist():
            if not self.referenced[v]:
                continue
            roots = {find(u) for u in self.adj[v] if u in parent}
            parent[v] = v
            if not roots:
                oldest[v] = v
                continue
            elder = min(roots, key=lambda r: pos[oldest[r]])
            for r in sorted(roots, key=lambda r: pos[oldest[r]]):
                if r == elder:
                    continue
                e = oldest[r]
                pers = f[v] - f[e] if kind == "minimum-saddle" else f[e] - f[v]
                pairs.append((kind, e, v, pers))
                into[e] = (oldest[elder], pers)
                parent[r] = elder
            parent[v] = elder
        for v in parent:
            if find(v) == v:
                pairs.append((kind, oldest[v], None, math.inf))
        return pairs, into

    def persistence(self):
        p0, min_into = self.elder(self.order, "minimum-saddle")
        p1, max_into = self.elder(self.order[::-1], "saddle-maximum")
        return p0 + p1, min_into, max_into

    def finals(self, threshold, maxima):
        """each extremum's label after the cancellations below threshold: the older first"""
        into = self.max_into if maxima else self.min_into
        ext = [v for v in range(self.nv) if self.referenced[v] and
               (self.ascent[v] == v if maxima else self.descent[v] == v)]
        ext.sort(key=lambda v: -self.rank[v] if maxima else self.rank[v])
        final = {}
        for e in ext:
            if e in into and into[e][1] < threshold:
                final[e] = final[into[e][0]]
            else:
                final[e] = e
        return final

    def counts(self):
        ref = self.referenced
        c = {k: int(((self.types == i) & ref).sum()) for i, k in
             enumerate(["minima", "saddles_1", "saddles_2", "maxima", "degenerate", "regular"])}
        c["unreferenced"] = int((~ref).sum())
        c["join_multiplicity"] = int(np.maximum(self.lower - 1, 0).sum())
        c["split_multiplicity"] = int(np.maximum(self.upper - 1, 0).sum())
        inside = ref & ~self.open
        c["interior"] = {k: int(((self.types == i) & inside).sum()) for i, k in
                         enumerate(["minima", "saddles_1", "saddles_2", "maxima", "degenerate"])}
        return c


# ---------------------------------------------------------------------------------------------
# The checks of one (mesh, field)

def check_critical(name, mesh_file, field_args, t, outputs=True):
    """check 2 (and 5): critical --gradient --json, --csv, -o against the links"""
    tag = "%s [%s]" % (name, " ".join(field_args))
    extra = ["--csv", path(name + ".critical.csv"), "-o", path(name + ".critical.vtu"), "--force"] if outputs else []
    j = prstar_json("critical", mesh_file, *field_args, "--gradient", *extra)
    if j is None:
        return None
    c = t.counts()
    check(j["vertices"] == t.nv and j["tetrahedra"] == len(t.tets), tag + ": vertex/tetrahedron counts")
    check(j["field_min"] == t.field_min and j["field_max"] == t.field_max,
          tag + ": field range %s..%s, expected %s..%s" % (j["field_min"], j["field_max"], t.field_min, t.field_max))
    for k, v in c.items():
        check(j.get(k) == v, "%s: %s = %s, expected %s" % (tag, k, j.get(k), v))
    expected = [v for v in range(t.nv) if t.types[v] != 5]
    got = [p["vertex"] for p in j["critical_points"]]
    check(got == expected, "%s: critical_points lists vertices %s..., expected %s..." % (tag, got[:10], expected[:10]))
    bad = []
    for p in j["critical_points"]:
        v = p["vertex"]
        if not (0 <= v < t.nv):
            bad.append(p)
            continue
        want = (TYPE_NAMES[t.types[v]], int(t.lower[v]), int(t.upper[v]), bool(t.open[v]), float(t.f[v]),
                t.pts[v].tolist())
        have = (p["type"], p["lower_components"], p["upper_components"], p["boundary"], p["value"], p["point"])
        if want != have:
            bad.append((v, "expected", want, "got", have))
    check(not bad, "%s: %d critical points differ from the links, e.g. %s" % (tag, len(bad), bad[:3]))
    # --gradient: the Euler characteristic counted here
    g = j.get("gradient", {})
    check(g.get("alternating_sum") == t.euler and g.get("euler_characteristic") == t.euler and
          g.get("critical_vertices", 0) - g.get("critical_edges", 0) + g.get("critical_triangles", 0) -
          g.get("critical_tetrahedra", 0) == t.euler,
          "%s: gradient %s, Euler characteristic V-E+F-T = %d" % (tag, g, t.euler))
    # ProcessLowerStars is perfect in 3D: its critical simplices are the homology of the lower links
    perfect = [c["minima"], c["join_multiplicity"], int(t.betti1[t.referenced].sum()),
               int(t.betti2[t.referenced].sum())]
    have = [g.get("critical_vertices"), g.get("critical_edges"), g.get("critical_triangles"),
            g.get("critical_tetrahedra")]
    check(have == perfect, "%s: critical vertices, edges, triangles, tetrahedra %s; the lower links' homology "
          "(minima, sum of b0 - 1, b1, b2) gives %s" % (tag, have, perfect))
    check(g.get("bytes_per_tetrahedron") == 4, "%s: bytes_per_tetrahedron %s" % (tag, g.get("bytes_per_tetrahedron")))
    if not outputs:
        return j
    # --csv
    with open(path(name + ".critical.csv")) as fh:
        rows = list(csv.reader(fh))
    check(rows and rows[0] == ["vertex", "x", "y", "z", "value", "type", "type_name", "lower_components",
                               "upper_components", "boundary"], tag + ": CSV header " + str(rows[:1]))
    want_rows = [[v, *t.pts[v].tolist(), float(t.f[v]), int(t.types[v]), TYPE_NAMES[t.types[v]], int(t.lower[v]),
                  int(t.upper[v]), int(t.open[v])] for v in expected]
    try:
        have_rows = [[int(r[0]), float(r[1]), float(r[2]), float(r[3]), float(r[4]), int(r[5]), r[6], int(r[7]),
                      int(r[8]), int(r[9])] for r in rows[1:]]
    except (ValueError, IndexError):
        have_rows = rows[1:]
    diff = [(w, h) for w, h in zip(want_rows, have_rows) if w != h]
    check(len(have_rows) == len(want_rows) and not diff,
          "%s: CSV %d rows (expected %d), first differences %s" % (tag, len(have_rows), len(want_rows), diff[:3]))
    # -o: the point arrays, in the input's vertex order
    P, T, pd, _ = read_vtu(path(name + ".critical.vtu"))
    check(P.shape == t.pts.shape and np.array_equal(P, t.pts), tag + ": -o does not keep the vertices in order")
    ok = all(k in pd for k in ("critical_type", "lower_components", "upper_components"))
    check(ok, tag + ": -o arrays missing: " + str(sorted(pd)))
    if ok and len(pd["critical_type"]) == t.nv:
        for k, want in (("critical_type", t.types), ("lower_components", t.lower), ("upper_components", t.upper)):
            d = np.nonzero(pd[k] != want)[0]
            check(len(d) == 0, "%s: -o %s differs at %d vertices, e.g. vertex %s: %s, expected %s" %
                  (tag, k, len(d), d[:1].tolist(), pd[k][d[:1]].tolist(), want[d[:1]].tolist()))
    return j


def tet_key(rows):
    return [tuple(sorted(r)) for r in rows.tolist()]


def check_morse(name, mesh_file, field_args, t, persistence=None, arcs=True):
    """checks 3, 4, 6: the pairs, the cells, the arcs"""
    tag = "%s [%s%s]" % (name, " ".join(field_args), "" if persistence is None else " --persistence " + persistence)
    stem = path(name + ".morse" + ("" if persistence is None else ".p"))
    args = ["morse", mesh_file, *field_args, "-o", stem + ".vtu", "--csv", stem + ".csv", "--force"]
    if arcs:
        args += ["--arcs", stem + ".vtp"]
    if persistence is not None:
        args += ["--persistence", persistence]
    j = prstar_json(*args)
    if j is None:
        return None, None
    relative = 0.0
    if persistence is not None:
        relative = float(persistence[:-1]) / 100 if persistence.endswith("%") else float(persistence)
    threshold = relative * (t.field_max - t.field_min)
    check(abs(j["persistence"] - relative) <= 1e-15 and abs(j["threshold"] - threshold) <= 1e-12 * (1 + threshold),
          "%s: persistence %s threshold %s, expected %s %s" % (tag, j["persistence"], j["threshold"], relative,
                                                              threshold))
    near = [p for p in t.pairs if p[3] != math.inf and abs(p[3] - threshold) <= 1e-9 * (1 + abs(threshold))]
    check(not near or threshold == 0, "%s: test design: pairs at the threshold %s" % (tag, near[:3]))
    c = t.counts()
    cp = j["critical_points"]
    for k in ("minima", "saddles_1", "saddles_2", "maxima", "degenerate", "regular"):
        check(cp.get(k) == c[k], "%s: critical_points.%s = %s, expected %s" % (tag, k, cp.get(k), c[k]))
    check(j["gradient"]["alternating_sum"] == t.euler and j["gradient"]["euler_characteristic"] == t.euler,
          "%s: gradient %s, Euler characteristic %d" % (tag, j["gradient"], t.euler))
    # 3. the persistence pairs: the same list, in the documented order
    want = sorted(((k, e, s) for k, e, s, _ in t.pairs),
                  key=lambda p: (p[0] != "minimum-saddle", t.rank[p[1]]))
    have = [(p["type"], p["extremum"], p["saddle"]) for p in j["pairs"]]
    missing = sorted(set(want) - set(have), key=str)
    extra = sorted(set(have) - set(want), key=str)
    check(not missing and not extra,
          "%s: persistence pairs: %d missing, e.g. %s; %d unexpected, e.g. %s" %
          (tag, len(missing), missing[:4], len(extra), extra[:4]))
    check(have == want or missing or extra, "%s: pairs not in the order (type, extremum's field order)" % tag)
    bad = []
    for p in j["pairs"]:
        e, s = p["extremum"], p["saddle"]
        if not (0 <= e < t.nv) or (s is not None and not (0 <= s < t.nv)):
            bad.append(p)
            continue
        if p["extremum_value"] != t.f[e]:
            bad.append(p)
        elif s is None:
            if p["persistence"] is not None or p["saddle_value"] is not None:
                bad.append(p)
        elif p["saddle_value"] != t.f[s] or p["persistence"] != abs(t.f[s] - t.f[e]):
            bad.append(p)
    check(not bad, "%s: pair values differ from the field: %s" % (tag, bad[:3]))
    kinds = ("minimum-saddle", "saddle-maximum")
    total = [sum(1 for p in t.pairs if p[0] == k) for k in kinds]
    kept = [sum(1 for p in t.pairs if p[0] == k and not p[3] < threshold) for k in kinds]
    check([j["minimum_saddle_pairs"], j["saddle_maximum_pairs"]] == total and
          [j["minimum_saddle_pairs_kept"], j["saddle_maximum_pairs_kept"]] == kept,
          "%s: pair counts %s, kept %s; expected %s, %s" % (
              tag, [j["minimum_saddle_pairs"], j["saddle_maximum_pairs"]],
              [j["minimum_saddle_pairs_kept"], j["saddle_maximum_pairs_kept"]], total, kept))
    # the CSV: the same pairs
    with open(stem + ".csv") as fh:
        rows = list(csv.reader(fh))
    check(rows and rows[0] == ["type", "extremum", "saddle", "extremum_value", "saddle_value", "birth", "death",
                               "persistence"], tag + ": pairs CSV header " + str(rows[:1]))
    want_rows = []
    for k, e, s in want:
        fe = float(t.f[e])
        if s is None:
            want_rows.append([k, e, None, fe, None, fe if k == kinds[0] else -math.inf,
                              math.inf if k == kinds[0] else fe, math.inf])
        else:
            fs = float(t.f[s])
            want_rows.append([k, e, s, fe, fs, fe if k == kinds[0] else fs, fs if k == kinds[0] else fe,
                              abs(fs - fe)])
    try:
        have_rows = [[r[0], int(r[1]), int(r[2]) if r[2] else None, float(r[3]), float(r[4]) if r[4] else None,
                      float(r[5]), float(r[6]), float(r[7])] for r in rows[1:]]
    except (ValueError, IndexError):
        have_rows = rows[1:]
    diff = [(w, h) for w, h in zip(want_rows, have_rows) if w != h]
    check(len(have_rows) == len(want_rows) and not diff,
          "%s: pairs CSV %d rows (expected %d), differences %s" % (tag, len(have_rows), len(want_rows), diff[:3]))
    # 4. the cells
    P, T, pd, cd = read_vtu(stem + ".vtu")
    check(P.shape == t.pts.shape and np.array_equal(P, t.pts), tag + ": -o does not keep the vertices in order")
    min_final = t.finals(threshold, False)
    max_final = t.finals(threshold, True)
    if check("ascending_cell" in pd and len(pd["ascending_cell"]) == t.nv, tag + ": no ascending_cell array"):
        want_asc = np.array([min_final[int(t.min_root[v])] if t.referenced[v] else -1 for v in range(t.nv)])
        d = np.nonzero(pd["ascending_cell"] != want_asc)[0]
        check(len(d) == 0, "%s: ascending_cell differs at %d vertices, e.g. vertex %s: %s, expected %s "
              "(steepest descent to %s)" % (tag, len(d), d[:1].tolist(), pd["ascending_cell"][d[:1]].tolist(),
                                            want_asc[d[:1]].tolist(), t.min_root[d[:1]].tolist()))
        survivors = sum(1 for e, fe in min_final.items() if fe == e)
        check(j["ascending_cells"] == survivors and len(set(want_asc[t.referenced].tolist())) == survivors,
              "%s: ascending_cells %s, expected %d" % (tag, j["ascending_cells"], survivors))
    if check("critical_type" in pd and len(pd["critical_type"]) == t.nv, tag + ": no critical_type array"):
        check(np.array_equal(pd["critical_type"], t.types), tag + ": morse critical_type differs from the links")
    desc = None
    if check("descending_cell" in cd and len(T) == len(t.tets), tag + ": no descending_cell array"):
        index = {k: i for i, k in enumerate(tet_key(t.tets))}
        perm = np.array([index.get(k, -1) for k in tet_key(T)])
        if check(sorted(perm.tolist()) == list(range(len(t.tets))), tag + ": -o does not hold the input's tetrahedra"):
            desc = np.empty(len(t.tets))
            desc[perm] = cd["descending_cell"]
            labels = set(desc[desc >= 0].astype(np.int64).tolist())
            check(len(labels) == j["descending_cells"],
                  "%s: %d distinct descending_cell labels, JSON descending_cells %s" %
                  (tag, len(labels), j["descending_cells"]))
            check(int((desc < 0).sum()) == j["outflow_tetrahedra"],
                  "%s: %d tetrahedra labelled -1, outflow_tetrahedra %s" % (tag, int((desc < 0).sum()),
                                                                            j["outflow_tetrahedra"]))
            interior_max = [v for v in range(t.nv) if t.types[v] == 3 and not t.open[v]]
            check(labels <= set(max_final.values()),
                  "%s: descending labels %s are not maxima" % (tag, sorted(labels - set(max_final.values()))[:5]))
            # every tetrahedron around an interior maximum flows to the maximum's critical tetrahedron
            inc = {}
            for ti, row in enumerate(t.tets.tolist()):
                for v in row:
                    if t.types[v] == 3 and not t.open[v]:
                        inc.setdefault(v, []).append(ti)
            bad = [(m, ti, desc[ti], max_final[m]) for m in interior_max for ti in inc[m] if desc[ti] != max_final[m]]
            check(not bad, "%s: tetrahedra around interior maxima not in their cell (max, tet, got, expected): %s"
                  % (tag, bad[:4]))
    if arcs:
        check_arcs(tag, stem + ".vtp", j, t)
    return j, desc


def check_arcs(tag, file, j, t):
    """6. the arcs: dimension-1 arcs are steepest-descent paths from a critical edge's two ends"""
    lines, cd = read_vtp(file)
    g = j["gradient"]
    check(len(lines) == j.get("arcs"), "%s: %d polylines, JSON arcs %s" % (tag, len(lines), j.get("arcs")))
    if not check(all(k in cd for k in ("saddle_dimension", "saddle", "saddle_vertex", "extremum", "saddle_value")),
                 tag + ": arc arrays " + str(sorted(cd))):
        return
    dim, sad, sv, ext = cd["saddle_dimension"], cd["saddle"], cd["saddle_vertex"], cd["extremum"]
    vertex_at = {tuple(p): v for v, p in enumerate(t.pts.tolist())}
    one = np.nonzero(dim == 1)[0]
    check(len(one) == 2 * g["critical_edges"], "%s: %d arcs of dimension 1, %d critical edges" %
          (tag, len(one), g["critical_edges"]))
    by_saddle = {}
    bad = []
    for i in one.tolist():
        pl, s, e = lines[i], int(sv[i]), int(ext[i])
        by_saddle.setdefault(int(sad[i]), []).append(i)
        if not (0 <= e < t.nv) or t.types[e] != 0:
            bad.append((i, "extremum %d is not a minimum" % e))
            continue
        if len(pl) < 2 or tuple(pl[-1].tolist()) != tuple(t.pts[e].tolist()):
            bad.append((i, "does not end at its minimum %d" % e))
            continue
        if cd["saddle_value"][i] != t.f[s]:
            bad.append((i, "saddle_value"))
        start = vertex_at.get(tuple(pl[1].tolist()))
        if start is None:
            bad.append((i, "second point is not a vertex"))
            continue
        path_ = [start]
        while t.descent[path_[-1]] != path_[-1]:
            path_.append(int(t.descent[path_[-1]]))
        if [vertex_at.get(tuple(p)) for p in pl[1:].tolist()] != path_:
            bad.append((i, "not the steepest-descent path from vertex %d" % start))
    for s, arcs_ in by_saddle.items():
        starts = sorted(vertex_at.get(tuple(lines[i][1].tolist()), -1) for i in arcs_)
        v = int(sv[arcs_[0]])
        if len(arcs_) != 2 or v not in starts or any(int(sv[i]) != v for i in arcs_):
            bad.append((s, "critical edge %d: arcs from %s, saddle vertex %d" % (s, starts, v)))
            continue
        w = starts[0] if starts[1] == v else starts[1]
        mid = (t.pts[v] + t.pts[w]) / 2
        if w not in t.adj[v] or t.rank[w] > t.rank[v] or \
                np.abs(lines[arcs_[0]][0] - mid).max() > 1e-12 * (1 + np.abs(mid).max()):
            bad.append((s, "critical edge %d-%d: not an edge down from its saddle vertex, or not its midpoint" % (v, w)))
    check(len(by_saddle) == g["critical_edges"], "%s: %d critical edges in the arcs, %d in the gradient" %
          (tag, len(by_saddle), g["critical_edges"]))
    check(not bad, "%s: dimension-1 arcs wrong: %s" % (tag, bad[:4]))
    # dimension 2: one arc per tetrahedron of the critical triangle, ending at a maximum or out (-1)
    two = np.nonzero(dim == 2)[0]
    check(len(one) + len(two) == len(lines), tag + ": arcs of a dimension other than 1 and 2")
    tri_arcs = {}
    bad = []
    for i in two.tolist():
        tri_arcs.setdefault(int(sad[i]), []).append(i)
        e = int(ext[i])
        if e != -1:
            if not (0 <= e < t.nv) or t.types[e] != 3 or t.open[e]:
                bad.append((i, "extremum %d is not an interior maximum" % e))
                continue
            cent = [t.pts[row].mean(axis=0) for row in t.tets[np.any(t.tets == e, axis=1)]]
            if min(np.abs(c - lines[i][-1]).max() for c in cent) > 1e-9 * (1 + np.abs(lines[i][-1]).max()):
                bad.append((i, "does not end in a tetrahedron of its maximum %d" % e))
    expected_lines = 2 * g["critical_edges"]
    for s, arcs_ in tri_arcs.items():
        v = int(sv[arcs_[0]])
        # the critical triangle: a triangle of the link of v whose barycentre with v is the first point
        first = lines[arcs_[0]][0]
        cands = set()
        for row in t.tets[np.any(t.tets == v, axis=1)].tolist():
            o = [x for x in row if x != v]
            for a, b in ((o[0], o[1]), (o[0], o[2]), (o[1], o[2])):
                tri = tuple(sorted((v, a, b)))
                c = t.pts[list(tri)].mean(axis=0)
                if np.abs(c - first).max() <= 1e-9 * (1 + np.abs(first).max()) and max(t.rank[a], t.rank[b]) < t.rank[v]:
                    cands.add(tri)
        if len(cands) != 1:
            bad.append((s, "critical triangle of saddle vertex %d not found from its barycentre" % v))
            continue
        tri = cands.pop()
        nt = t.triangle_tets[(tri[0] * t.nv + tri[1]) * t.nv + tri[2]]
        expected_lines += min(nt, 2) if nt <= 2 else 0
        if len(arcs_) != (nt if nt <= 2 else 0):
            bad.append((s, "critical triangle %s in %d tetrahedra: %d arcs" % (tri, nt, len(arcs_))))
    manifold = max(t.triangle_tets.values()) <= 2
    check(len(tri_arcs) == g["critical_triangles"] or (not manifold and len(tri_arcs) <= g["critical_triangles"]),
          "%s: %d critical triangles with arcs, %d in the gradient" % (tag, len(tri_arcs), g["critical_triangles"]))
    check(not bad, "%s: dimension-2 arcs wrong: %s" % (tag, bad[:4]))
    check(len(lines) == expected_lines, "%s: %d arcs, expected 2 per critical edge + 1 or 2 per critical triangle"
          " = %d" % (tag, len(lines), expected_lines))


def strip(j):
    return {k: v for k, v in j.items() if k not in ("seconds", "kv", "kv_automatic")} if j else j


def check_invariance(name, mesh_file, field_args, persistence="2%"):
    """7. the same JSON (and cells, arcs) for every k_v and thread count"""
    runs = []
    for opts in (["--kv", "1"], ["--kv", "8"], ["--kv", "50"], ["--kv", "inf"], ["--threads", "1"],
                 ["--threads", "2", "--kv", "4"], ["--threads", "8", "--kv", "2"]):
        jc = prstar_json("critical", mesh_file, *field_args, "--gradient", *opts)
        jm = prstar_json("morse", mesh_file, *field_args, "--persistence", persistence, "-o",
                         path(name + ".inv.vtu"), "--arcs", path(name + ".inv.vtp"), "--force", *opts)
        P, T, pd, cd = read_vtu(path(name + ".inv.vtu"))
        key = tet_key(T)
        desc = dict(zip(key, cd["descending_cell"].tolist()))
        lines, acd = read_vtp(path(name + ".inv.vtp"))
        runs.append((" ".join(opts), strip(jc), strip(jm), pd["ascending_cell"].tolist(), desc, lines,
                     {k: v.tolist() for k, v in acd.items()}))
    ref = runs[0]
    for r in runs[1:]:
        check(r[1] == ref[1], "%s: critical --json differs between %s and %s" % (name, ref[0], r[0]))
        check(r[2] == ref[2], "%s: morse --json differs between %s and %s" % (name, ref[0], r[0]))
        check(r[3] == ref[3] and r[4] == ref[4], "%s: morse cells differ between %s and %s" % (name, ref[0], r[0]))
        same_lines = len(r[5]) == len(ref[5]) and all(
            a.shape == b.shape and np.abs(a - b).max(initial=0) <= 1e-12 * (1 + np.abs(b).max(initial=0))
            for a, b in zip(r[5], ref[5]))
        check(same_lines and r[6] == ref[6], "%s: arcs differ between %s and %s" % (name, ref[0], r[0]))


# ---------------------------------------------------------------------------------------------
# The cases

summary = []


def guarded(what, fn, *args, **kwargs):
    """fn(...), a failure (not a traceback) if it raises: a missing or unreadable output"""
    try:
        return fn(*args, **kwargs)
    except Exception:
        check(False, "%s: %s" % (what, traceback.format_exc(limit=3)))
        return None


def run_case(name, mesh_file, field_args, t, persistence=None, outputs=True, arcs=True):
    t0 = time.time()
    jc = guarded(name + " critical", check_critical, name, mesh_file, field_args, t, outputs)
    jm, desc = guarded(name + " morse", check_morse, name, mesh_file, field_args, t, None, arcs) or (None, None)
    if persistence is not None:
        jm, desc = guarded(name + " morse --persistence", check_morse, name, mesh_file, field_args, t, persistence,
                           arcs) or (None, None)
    c = t.counts()
    summary.append("%-22s %6d V %7d T  min %3d  1-s %3d  2-s %3d  max %3d  deg %2d  pairs %4d  %.1f s" % (
        name + " " + " ".join(field_args), t.nv, len(t.tets), c["minima"], c["saddles_1"], c["saddles_2"],
        c["maxima"], c["degenerate"], len(t.pairs), time.time() - t0))
    return jc, jm, desc


def lattice(n):
    # generate streams a .vtu lattice as raw appended data (for MPI byte ranges), which VTK 9.1/9.2
    # cannot read with Debian 12's current libexpat; any other output goes through the package's
    # writer (inline data)
    file = path("lattice%d.vtu" % n)
    prstar("generate", "--shape", "lattice", "--cells", n, "-o", path("lattice%d.vtk" % n), "--force", "--quiet")
    prstar("convert", path("lattice%d.vtk" % n), file, "--force", "--quiet")
    P, T, pd, _ = read_vtu(file)
    return P, T, pd


# --- lattices with fields written here ---------------------------------------------------------
P8, T8, pd8 = lattice(8)
centre = np.array([3.37, 4.61, 4.23])
bowl = ((P8 - centre) ** 2 * np.array([1.0, 1.3, 0.7])).sum(axis=1)
rng = np.random.default_rng(20261124)
fields8 = {"bowl": bowl, "linear": 0.5 * P8[:, 0] + 0.25 * P8[:, 1] - 0.125 * P8[:, 2]}
write_vtu(path("bowl8.vtu"), P8, T8, fields8)
t = Truth(P8, T8, bowl)
c = t.counts()
check(c["minima"] == 1 and c["interior"]["saddles_1"] == 0 and c["interior"]["saddles_2"] == 0 and
      c["interior"]["maxima"] == 0 and c["interior"]["degenerate"] == 0, "bowl: test design: %s" % c)
best = int(np.argmin(bowl))
jc, jm, _ = run_case("bowl8", path("bowl8.vtu"), ["--field", "bowl"], t)
if jc:
    mins = [p["vertex"] for p in jc["critical_points"] if p["type"] == "minimum"]
    check(mins == [best], "bowl: minima %s, expected the vertex nearest the centre %d" % (mins, best))
    check(not any(p["type"] != "minimum" and not p["boundary"] for p in jc["critical_points"]),
          "bowl: an interior critical point other than the minimum")
if jm:
    P, T, pd, _ = read_vtu(path("bowl8.morse.vtu"))
    check(set(pd["ascending_cell"].tolist()) == {best}, "bowl: more than one ascending cell")
t = Truth(P8, T8, fields8["linear"])
jc, _, _ = run_case("linear8", path("bowl8.vtu"), ["--field", "linear"], t)
check(jc is not None and jc["interior"] == {"minima": 0, "saddles_1": 0, "saddles_2": 0, "maxima": 0,
                                            "degenerate": 0}, "linear8: interior critical points %s" %
      (jc or {}).get("interior"))
# f = x (--field x): no interior critical point
tx = Truth(P8, T8, P8[:, 0])
guarded("invariance", check_invariance, "lattice8_scalar", path("lattice8.vtu"), ["--field", "scalar"])
jc, _, _ = run_case("lattice8_x", path("lattice8.vtu"), ["--field", "x"], tx)
check(jc is not None and sum(jc["interior"].values()) == 0, "lattice8 x: interior critical points %s" %
      (jc or {}).get("interior"))
# the lattice's own array (the default field: its first array)
run_case("lattice8_scalar", path("lattice8.vtu"), [], Truth(P8, T8, pd8["scalar"]), persistence="3%")

# three bumps on a 10^3 lattice: three interior maxima at the vertices nearest the centres
P10, T10, _ = lattice(10)
bumps = [((3.1, 3.2, 6.1), 2.0), ((7.9, 3.3, 5.8), 1.5), ((5.2, 7.8, 6.3), 1.0)]
fb = 0.02 * P10[:, 2]
for cb, h in bumps:
    fb = fb + h * np.exp(-((P10 - np.array(cb)) ** 2).sum(axis=1) / 2.0)
write_vtu(path("bumps10.vtu"), P10, T10, {"bumps": fb})
t = Truth(P10, T10, fb)
peaks = sorted(int(np.argmin(((P10 - np.array(cb)) ** 2).sum(axis=1))) for cb, _ in bumps)
interior_max = sorted(v for v in range(t.nv) if t.types[v] == 3 and not t.open[v])
check(interior_max == peaks, "bumps: test design: interior maxima %s, nearest vertices %s" % (interior_max, peaks))
jc, jm, desc = run_case("bumps10", path("bumps10.vtu"), ["--field", "bumps"], t, persistence="5%")
if jc:
    got = sorted(p["vertex"] for p in jc["critical_points"] if p["type"] == "maximum" and not p["boundary"])
    check(got == peaks, "bumps: interior maxima %s, expected %s" % (got, peaks))
if jm and desc is not None:
    labels = sorted(set(desc[desc >= 0].astype(int).tolist()))
    check(labels == peaks and jm["descending_cells"] == 3,
          "bumps --persistence 5%%: descending cells %s (%s), expected the peaks %s" %
          (labels, jm["descending_cells"], peaks))
    for p in peaks:
        around = np.nonzero(np.any(T10 == p, axis=1))[0]
        check(np.all(desc[around] == p), "bumps: tetrahedra around peak %d not labelled %d: %s" %
              (p, p, sorted(set(desc[around].tolist()))))

# noise (many critical points, degenerate ones) and plateaus (ties broken by the index)
P6, T6, _ = lattice(6)
noise = rng.uniform(-1, 1, len(P6))
plateaus = np.floor(3 * P6[:, 0] / 6) + np.floor(2 * P6[:, 2] / 6) + (rng.uniform(0, 1, len(P6)) < 0.1)
write_vtu(path("noise6.vtu"), P6, T6, {"noise": noise, "plateaus": plateaus})
t = Truth(P6, T6, noise)
c = t.counts()
check(c["interior"]["saddles_1"] > 0 and c["interior"]["saddles_2"] > 0 and c["interior"]["maxima"] > 2 and
      c["degenerate"] > 0, "noise: test design: %s" % c)
run_case("noise6", path("noise6.vtu"), ["--field", "noise"], t, persistence="0.2")
guarded("invariance", check_invariance, "noise6", path("noise6.vtu"), ["--field", "noise"], "10%")
run_case("plateaus6", path("noise6.vtu"), ["--field", "plateaus"], Truth(P6, T6, plateaus), persistence="25%")
# two separate copies of the 6^3 lattice and a vertex in no tetrahedron (index 150, the largest
# value, outside the range): two essential pairs of each kind, the unreferenced vertex regular
k = 150
P2 = np.concatenate([P6[:k], [[-5.0, -5.0, -5.0]], P6[k:], P6 + np.array([9.0, 0.5, 0.0])])
T2 = np.concatenate([np.where(T6 >= k, T6 + 1, T6), T6 + len(P6) + 1])
f2 = rng.uniform(-1, 1, len(P2))
f2[k] = 100.0
write_vtu(path("two6.vtu"), P2, T2, {"f": f2})
t = Truth(P2, T2, f2)
check(t.counts()["unreferenced"] == 1 and t.field_max < 100, "two6: test design")
jc, jm, _ = run_case("two6", path("two6.vtu"), ["--field", "f"], t, persistence="15%")
if jm:
    essential = sorted(p["type"] for p in jm["pairs"] if p["saddle"] is None)
    check(essential == ["minimum-saddle"] * 2 + ["saddle-maximum"] * 2,
          "two6: essential pairs %s, expected two of each kind (two components)" % essential)
    check(jm["field_max"] < 100, "two6: the unreferenced vertex counted in the field range")
if jc:
    check(k not in [p["vertex"] for p in jc["critical_points"]], "two6: the unreferenced vertex listed")
P7, T7, _ = lattice(7)
n7 = np.sin(1.7 * P7[:, 0]) * np.cos(1.3 * P7[:, 1]) + 0.5 * np.sin(2.1 * P7[:, 2] + P7[:, 0])
write_vtu(path("waves7.vtu"), P7, T7, {"waves": n7})
run_case("waves7", path("waves7.vtu"), ["--field", "waves"], Truth(P7, T7, n7), persistence="10%")

# --- the generated meshes (Medit, TetGen .vtu) ---------------------------------------------------
if TEST_DATA and os.path.isdir(TEST_DATA):
    for mesh, field in (("sphere.mesh", "z"), ("torus.mesh", "x"), ("cube.mesh", "y"), ("cube_tetgen.vtu", "x")):
        file = os.path.join(TEST_DATA, mesh)
        if not os.path.exists(file) or (mesh.endswith(".mesh") and meshio is None):
            summary.append("%s: absent, skipped" % mesh)
            continue
        if mesh.endswith(".mesh"):
            P, T = read_medit(file)
        else:
            P, T, _, _ = read_vtu(file)
        axis = "xyz".index(field)
        name = mesh.split(".")[0]
        run_case(name, file, ["--field", field], Truth(P, T, P[:, axis]), persistence="1%",
                 arcs=(mesh != "torus.mesh"))
        if mesh == "torus.mesh":
            # a noisy field on the solid torus (a .vtu copy), and the k_v / threads invariance
            f = np.sin(3 * P[:, 0]) * np.cos(2 * P[:, 1]) + 0.3 * P[:, 2] + 0.05 * rng.uniform(-1, 1, len(P))
            write_vtu(path("torus_field.vtu"), P, T, {"f": f})
            run_case("torus_f", path("torus_field.vtu"), ["--field", "f"], Truth(P, T, f), persistence="3%")
            guarded("invariance", check_invariance, "torus_f", path("torus_field.vtu"), ["--field", "f"], "3%")
else:
    summary.append("generated meshes: no TEST_DATA_DIR, skipped")

# --- the shared TetGen mesh ---------------------------------------------------------------------
t13 = os.path.join(SHARED, "t13_data.1.node") if SHARED else ""
if t13 and os.path.exists(t13) and os.path.exists(t13[:-5] + ".ele"):
    P, T = read_tetgen(t13)
    tt = Truth(P, T, P[:, 0])
    run_case("t13", t13, ["--field", "x"], tt, arcs=False)
    lo, hi = P.min(axis=0), P.max(axis=0)
    q = (P - lo) / (hi - lo)
    f = np.cos(5 * q[:, 0]) * np.sin(4 * q[:, 1] + 1) + q[:, 2] ** 2
    write_vtu(path("t13_field.vtu"), P, T, {"wave": f})
    run_case("t13_wave", path("t13_field.vtu"), ["--field", "wave"], Truth(P, T, f), persistence="5%")
else:
    summary.append("t13_data.1.node: no shared data, skipped")
# the SPX volume-rendering mesh (tet-OFF, most tetrahedra negatively oriented) and its own scalar,
# with many ties (0.2 at most of its boundary)
spx = os.path.join(SHARED, "spx_zsweep.off") if SHARED else ""
if spx and os.path.exists(spx):
    with open(spx) as fh:
        tok = fh.read().split()
    nv_, nt_ = int(tok[0]), int(tok[1])
    body = np.array(tok[2:2 + 4 * nv_], dtype=float).reshape(nv_, 4)
    T = np.array(tok[2 + 4 * nv_:2 + 4 * nv_ + 4 * nt_], dtype=np.int64).reshape(nt_, 4)
    run_case("spx", spx, [], Truth(body[:, :3], T, body[:, 3]), persistence="5%")

# --- 8. errors -----------------------------------------------------------------------------------
r = prstar("critical", path("noise6.vtu"), "--field", "nosuch", expect=None)
check(r.returncode in (1, 2) and "nosuch" in r.stderr and "noise" in r.stderr and "plateaus" in r.stderr,
      "unknown --field: exit %d, stderr %r" % (r.returncode, r.stderr))
r = prstar("morse", path("noise6.vtu"), "--field", "nosuch", expect=None)
check(r.returncode in (1, 2) and "nosuch" in r.stderr and "noise" in r.stderr,
      "morse unknown --field: exit %d, stderr %r" % (r.returncode, r.stderr))
bad_vertex = 17
nanf = noise.copy()
nanf[bad_vertex] = np.nan
write_vtu(path("nan6.vtu"), P6, T6, {"f": nanf})
P, T, pd, _ = read_vtu(path("nan6.vtu"))
check(np.isnan(pd["f"][bad_vertex]) and np.isfinite(np.delete(pd["f"], bad_vertex)).all(),
      "the NaN field was not written")
# The .vtu reader refuses the value itself ("DataArray 'f': value 17 is not finite"), before the
# field is taken; through HDF5 (XDMF) the value reaches the field check ("not finite at vertex 17").
nan_files = [("nan6.vtu", ("not finite at vertex %d" % bad_vertex, "'f': value %d is not finite" % bad_vertex))]
try:
    meshio.write(path("nan6.xdmf"), meshio.Mesh(P6, [("tetra", T6)], point_data={"f": nanf}))
    nan_files.append(("nan6.xdmf", ("not finite at vertex %d" % bad_vertex,)))
except Exception as e:  # no meshio or no h5py
    summary.append("NaN through XDMF/HDF5: skipped (%s)" % e)
for file, messages in nan_files:
    for cmd in ("critical", "morse"):
        r = prstar(cmd, path(file), "--field", "f", expect=None)
        check(r.returncode == 1 and any(m in r.stderr for m in messages) and r.stderr.count("\n") == 1,
              "%s %s with a NaN at vertex %d: exit %d, stderr %r (expected one of %s)" %
              (cmd, file, bad_vertex, r.returncode, r.stderr, messages))
r = prstar("morse", path("noise6.vtu"), "--field", "noise", "--persistence", "2", expect=2)
check("--persistence" in r.stderr, "--persistence 2: stderr %r" % r.stderr)
r = prstar("morse", path("noise6.vtu"), "--field", "noise", "--persistence", "abc", expect=2)
missing = path("no_such_mesh.vtu")
for cmd in ("critical", "morse"):
    r = prstar(cmd, missing, "--field", "x", expect=1)
    check("no_such_mesh.vtu" in r.stderr, "%s on a missing file: stderr %r" % (cmd, r.stderr))
r = prstar("critical", path("noise6.vtu"), "--field", "noise", "--kv", "0", expect=2)

seconds = time.time() - START
print("prstar critical / morse against brute-force links, union-find persistence, steepest descent:")
for s in summary:
    print("  " + s)
print("%d checks, %d failed, %.1f s" % (checks[0], len(failures), seconds))
sys.exit(1 if failures else 0)
