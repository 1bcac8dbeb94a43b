#!/usr/bin/python3
# Copyright (c) 2026 The PR-star octree project.
# SPDX-License-Identifier: LGPL-3.0-or-later
#
# The everyday commands of the prstar tool checked with readers that are not ours (meshio, VTK) and
# meshes made by other tools (meshio, the gmsh binary):
# - convert: a round trip through every pair of formats keeps the vertices bit for bit, the
#   tetrahedra, the labels, the point and cell data wherever both formats hold them; --strict refuses
#   to drop anything and writes nothing;
# - info: counts, bounding box, labels and their names against meshio;
# - boundary --surface: the boundary and interface triangles against a brute-force count of the faces,
#   outward oriented, with their label pair;
# - curvature: every row of the summary filled, both values in the CSV;
# - messages and exit statuses: one-line usage errors, "did you mean", --version, help CMD, output
#   folders checked before any work, percentages, --keep, memory sizes in readable units.
# - the README's table of commands is the tool's list.
# Usage: test_cli_everyday.py PRSTAR WORKDIR [README.md].  Exit 77 (skipped) without meshio, numpy or VTK.
import json
import os
import shutil
import subprocess
import sys
import time

try:
    import meshio
    import numpy as np
    from vtkmodules.vtkIOXML import vtkXMLPolyDataReader
    from vtkmodules.util.numpy_support import vtk_to_numpy
except ImportError as e:
    print("skipped: %s" % e)
    sys.exit(77)

PRSTAR, WORK = sys.argv[1], sys.argv[2]
shutil.rmtree(WORK, ignore_errors=True)
os.makedirs(WORK)
failures = []


def check(ok, what):
    if not ok:
        failures.append(what)
        print("FAILED: " + what)


def prstar(*args, expect=0):
    r = subprocess.run([PRSTAR] + [str(a) for a in args], cwd=WORK, capture_output=True, text=True, timeout=600)
    if expect is not None:
        check(r.returncode == expect,
              "prstar %s: exit %d, expected %d\n%s%s" % (" ".join(map(str, args)), r.returncode, expect, r.stdout,
                                                          r.stderr))
    return r


def path(name):
    return os.path.join(WORK, name)


# ---------------------------------------------------------------------------------------------
# The source mesh, written by meshio: a jittered 4^3 lattice, two labels, two point arrays and one
# cell array with values no short decimal holds.
rng = np.random.default_rng(19)
n = 4
g = np.arange(n + 1, dtype=float)
pts = np.array([[x, y, z] for z in g for y in g for x in g]) + rng.uniform(-0.2, 0.2, ((n + 1) ** 3, 3)) / 3
tets = []
for k in range(n):
    for j in range(n):
        for i in range(n):
            c = [i + (n + 1) * (j + (n + 1) * k) + dx + (n + 1) * (dy + (n + 1) * dz)
                 for dz in (0, 1) for dy in (0, 1) for dx in (0, 1)]
            # the 6 tetrahedra of the Kuhn subdivision along the diagonal c[0]-c[7]
            for a, b in ((1, 3), (3, 2), (2, 6), (6, 4), (4, 5), (5, 1)):
                tets.append([c[0], c[a], c[b], c[7]])
tets = np.array(tets, dtype=np.int64)
# positively oriented
v = pts[tets]
vol = np.einsum("ij,ij->i", np.cross(v[:, 1] - v[:, 0], v[:, 2] - v[:, 0]), v[:, 3] - v[:, 0])
tets[vol < 0] = tets[vol < 0][:, [0, 2, 1, 3]]
labels = np.where(pts[tets].mean(axis=1)[:, 0] < n / 2, 1, 2).astype(np.int32)
scalar = np.sin(pts[:, 0]) * np.exp(pts[:, 1] / 7)
temperature = pts[:, 2] ** 2 / 3
quality = rng.uniform(0, 1, len(tets))
meshio.write(path("source.vtu"),
             meshio.Mesh(pts, [("tetra", tets)], point_data={"scalar": scalar, "temperature": temperature},
                         cell_data={"label": [labels], "quality": [quality]}), binary=False)
# meshio's ASCII writer rounds to 12 digits: the truth is what the file holds, read by meshio
src = meshio.read(path("source.vtu"))
pts, tets = src.points, src.cells[0].data
scalar, temperature = src.point_data["scalar"], src.point_data["temperature"]
labels, quality = src.cell_data["label"][0], src.cell_data["quality"][0]

# What each format holds (from the formats' specifications, not from our table).
formats = ["vtu", "vtk", "xdmf", "msh", "node", "mesh", "meshb", "off"]
named_point_data = {"vtu", "vtk", "xdmf", "msh"}
named_cell_data = {"vtu", "vtk", "xdmf", "msh"}
holds_labels = {"vtu", "vtk", "xdmf", "msh", "node", "mesh", "meshb"}
label_key = {"vtu": "label", "vtk": "label", "xdmf": "label", "msh": "gmsh:physical", "node": "tetgen:ref",
             "mesh": "medit:ref", "meshb": "medit:ref"}


def read_independently(fmt, file):
    """points, tetrahedra (rows), labels or None, point data, cell data, read by meshio"""
    if fmt == "off":  # tet-OFF is not a format meshio knows: through our .vtu, itself checked by VTK
        prstar("convert", file, file + ".vtu", "--quiet", "--force")
        file, fmt = file + ".vtu", "vtu"
    m = meshio.read(file, file_format="tetgen" if fmt == "node" else None)
    blocks = [i for i, c in enumerate(m.cells) if c.type == "tetra"]
    t = np.concatenate([m.cells[i].data for i in blocks])
    cd = {k: np.concatenate([np.asarray(m.cell_data[k][i]).reshape(len(m.cells[i].data), -1)[:, 0] for i in blocks])
          for k in m.cell_data}
    lab = cd.get(label_key.get(fmt, ""), None)
    return m.points, t, lab, m.point_data, cd


def by_tetrahedron(t, values):
    return {tuple(sorted(row)): val for row, val in zip(t.tolist(), values.tolist())}


for a in formats:
    prstar("convert", "source.vtu", "a." + a, "--quiet")
    for b in formats:
        out = "%s_to_%s.%s" % (a, b, b)
        prstar("convert", "a." + a, out, "--quiet")
        P, T, L, PD, CD = read_independently(b, path(out))
        pair = "%s -> %s" % (a, b)
        check(P.shape == pts.shape and np.array_equal(P.astype(float).view(np.uint64), pts.view(np.uint64)),
              pair + ": the vertices are not the input's, bit for bit, in order")
        if "msh" in (a, b):  # gmsh groups the elements by entity: the same tetrahedra, by label
            check(sorted(map(tuple, T.tolist())) == sorted(map(tuple, tets.tolist())), pair + ": tetrahedra")
        else:
            check(np.array_equal(T, tets), pair + ": the tetrahedra are not the input's, in order")
        if a in holds_labels and b in holds_labels:
            check(L is not None and by_tetrahedron(T, L) == by_tetrahedron(tets, labels), pair + ": labels")
        for name, values in (("scalar", scalar), ("temperature", temperature)):
            if a in named_point_data and b in named_point_data:
                got = PD.get(name)
                check(got is not None and np.array_equal(np.asarray(got, float).ravel().view(np.uint64),
                                                         values.view(np.uint64)),
                      pair + ": point data " + name)
        if a in named_cell_data and b in named_cell_data:
            got = CD.get("quality")
            check(got is not None and by_tetrahedron(T, np.asarray(got, float).ravel()) ==
                  by_tetrahedron(tets, quality), pair + ": cell data quality")

left = [f for f in os.listdir(WORK) if "prstar-tmp" in f]
check(not left and os.path.exists(path("a.h5")), "temporaries left behind, or no a.h5: %s" % left)
with open(path("a.xdmf")) as f:
    check("a.h5:" in f.read(), "a.xdmf does not name a.h5")

# --strict: a format that cannot hold everything is an error, and nothing is written
r = prstar("convert", "source.vtu", "strict.mesh", "--strict", expect=1)
check("point data 'scalar', 'temperature'" in r.stderr and not os.path.exists(path("strict.mesh")),
      "convert --strict: " + r.stderr)
r = prstar("convert", "source.vtu", "dropped.mesh", "--json")
j = json.loads(r.stdout)
check(any("scalar" in d for d in j["dropped"]) and any("quality" in d for d in j["dropped"]) and
      j["vertices"] == len(pts) and j["tetrahedra"] == len(tets), "convert --json: " + r.stdout)
r = prstar("convert", "source.vtu", "everything.vtk", "--json")
check(json.loads(r.stdout)["dropped"] == [], "convert to .vtk drops something: " + r.stdout)
prstar("convert", "source.vtu", "ascii.vtu", "--ascii", "--quiet")
check(b"format=\"ascii\"" in open(path("ascii.vtu"), "rb").read(), "convert --ascii: not an ASCII .vtu")
r = prstar("convert", "source.vtu", "x.mesh", "--binary", expect=2)
check(r.stderr.count("\n") == 2, "convert --binary to a text-only format: not a one-line usage error: " + r.stderr)

# ---------------------------------------------------------------------------------------------
# info against meshio, on the source and on a two-material mesh made by gmsh (physical names)
r = prstar("info", "source.vtu", "--json")
j = json.loads(r.stdout)
check(j["vertices"] == len(pts) and j["tetrahedra"] == len(tets), "info: counts")
check(j["bounding_box"]["min"] == pts.min(axis=0).tolist() and j["bounding_box"]["max"] == pts.max(axis=0).tolist(),
      "info: bounding box")
check({x["label"]: x["tetrahedra"] for x in j["labels"]} == {1: int((labels == 1).sum()), 2: int((labels == 2).sum())},
      "info: labels")
check(j["orientation"] == {"positive": len(tets), "negative": 0, "flat": 0}, "info: orientation")
check(sum(j["quality"]["radius_ratio_histogram"]) == len(tets), "info: histogram")
# the shape measures recomputed with numpy: dihedral angles from the face normals, radius ratio 3 r / R
X = pts[tets]
dihedrals = []
for a, b in ((0, 1), (0, 2), (0, 3), (1, 2), (1, 3), (2, 3)):  # the edge ab; c, d the other two
    c, d = [k for k in range(4) if k not in (a, b)]
    e = X[:, b] - X[:, a]
    n1, n2 = np.cross(e, X[:, c] - X[:, a]), np.cross(e, X[:, d] - X[:, a])
    cos = np.einsum("ij,ij->i", n1, n2) / np.linalg.norm(n1, axis=1) / np.linalg.norm(n2, axis=1)
    dihedrals.append(np.degrees(np.arccos(np.clip(cos, -1, 1))))
dihedrals = np.array(dihedrals)
A, B, C = X[:, 1] - X[:, 0], X[:, 2] - X[:, 0], X[:, 3] - X[:, 0]
six_v = np.abs(np.einsum("ij,ij->i", A, np.cross(B, C)))
area2 = sum(np.linalg.norm(np.cross(X[:, q] - X[:, p], X[:, r] - X[:, p]), axis=1)
            for p, q, r in ((0, 1, 2), (0, 1, 3), (0, 2, 3), (1, 2, 3)))
centre = (np.einsum("ij,ij->i", A, A)[:, None] * np.cross(B, C) + np.einsum("ij,ij->i", B, B)[:, None] *
          np.cross(C, A) + np.einsum("ij,ij->i", C, C)[:, None] * np.cross(A, B)) / (2 * six_v[:, None])
rr = 3 * (six_v / area2) / np.linalg.norm(centre, axis=1)
q = j["quality"]
check(abs(q["min_dihedral"] - dihedrals.min()) < 1e-9 and abs(q["max_dihedral"] - dihedrals.max()) < 1e-9 and
      abs(q["min_radius_ratio"] - rr.min()) < 1e-9 and
      q["radius_ratio_histogram"] == np.histogram(np.minimum(rr, 1), bins=10, range=(0, 1))[0].tolist(),
      "info: quality against numpy: %s" % q)
pd = {x["name"]: x for x in j["point_data"]}
check(pd["scalar"]["min"] == scalar.min() and pd["scalar"]["max"] == scalar.max() and pd["scalar"]["type"] == "real",
      "info: point data range")
r = prstar("info", "source.vtu")
check("radius ratio" in r.stdout and "temperature" in r.stdout, "info: table")

have_gmsh = shutil.which("gmsh") is not None
if have_gmsh:
    with open(path("two.geo"), "w") as f:
        f.write('SetFactory("OpenCASCADE");\nBox(1) = {0,0,0, 1,1,1};\nBox(2) = {1,0,0, 1,1,1};\n'
                'BooleanFragments{ Volume{1}; Delete; }{ Volume{2}; Delete; }\n'
                'Physical Volume("steel", 1) = {1};\nPhysical Volume("rubber", 2) = {2};\n'
                'Mesh.CharacteristicLengthMax = 0.3;\n')
    subprocess.run(["gmsh", "two.geo", "-3", "-format", "msh41", "-o", "two.msh"], cwd=WORK, capture_output=True,
                   check=True)
    # with every element saved (triangles, lines, points too): what is not a tetrahedron is named
    subprocess.run(["gmsh", "two.geo", "-3", "-save_all", "-format", "msh41", "-o", "all.msh"], cwd=WORK,
                   capture_output=True, check=True)
    r = prstar("convert", "all.msh", "all.vtu", "--strict", expect=1)
    check("triangle" in r.stderr and not os.path.exists(path("all.vtu")), "convert --strict, triangles: " + r.stderr)
    g = meshio.read(path("two.msh"))
    j = json.loads(prstar("info", "two.msh", "--json").stdout)
    names = {int(v[0]): k for k, v in g.field_data.items()}
    gl = np.concatenate([g.cell_data["gmsh:physical"][i] for i, c in enumerate(g.cells) if c.type == "tetra"])
    check({x["label"]: (x["tetrahedra"], x.get("name")) for x in j["labels"]} ==
          {int(l): (int((gl == l).sum()), names[int(l)]) for l in np.unique(gl)}, "info: gmsh physical names")

    # -------------------------------------------------------------------------------------------
    # boundary --surface against the faces counted by brute force
    gt = np.concatenate([c.data for c in g.cells if c.type == "tetra"])
    faces = {}
    for ti, t in enumerate(gt.tolist()):
        for k in range(4):
            f = [t[i] for i in range(4) if i != k]
            faces.setdefault(tuple(sorted(f)), []).append((ti, t[k]))
    expect_boundary = {f for f, around in faces.items() if len(around) == 1}
    expect_interface = {f for f, around in faces.items() if len(around) == 2 and gl[around[0][0]] != gl[around[1][0]]}
    r = prstar("boundary", "two.msh", "--surface", "surface.vtp", "--json")
    j = json.loads(r.stdout)
    check(j["boundary_triangles"] == len(expect_boundary) and j["interface_triangles"] == len(expect_interface),
          "boundary --surface: counts " + r.stdout)
    rd = vtkXMLPolyDataReader()
    rd.SetFileName(path("surface.vtp"))
    rd.Update()
    poly = rd.GetOutput()
    sp = vtk_to_numpy(poly.GetPoints().GetData())
    polys = vtk_to_numpy(poly.GetPolys().GetConnectivityArray()).reshape(-1, 3)
    vid = vtk_to_numpy(poly.GetPointData().GetArray("vertex"))
    inside = vtk_to_numpy(poly.GetCellData().GetArray("label_inside"))
    outside = vtk_to_numpy(poly.GetCellData().GetArray("label_outside"))
    interface = vtk_to_numpy(poly.GetCellData().GetArray("interface"))
    check(np.array_equal(sp, g.points[vid]), "boundary --surface: points are not the input's")
    got = [tuple(vid[t]) for t in polys]
    check({tuple(sorted(t)) for t, i in zip(got, interface) if i == 0} == expect_boundary, "surface: boundary")
    check({tuple(sorted(t)) for t, i in zip(got, interface) if i == 1} == expect_interface, "surface: interfaces")
    wrong = 0
    for t, i, lin, lout in zip(got, interface, inside, outside):
        around = faces[tuple(sorted(t))]
        # the tetrahedron the normal points out of: the one with the label `inside`
        ti, apex = [x for x in around if gl[x[0]] == lin][0]
        a, b, c = g.points[list(t)]
        wrong += np.dot(np.cross(b - a, c - a), g.points[apex] - a) >= 0
        if i == 1:
            wrong += not (lin < lout and {lin, lout} == {gl[x[0]] for x in around})
        else:
            wrong += lout != -1
    check(wrong == 0, "boundary --surface: %d triangles not outward or with a wrong label pair" % wrong)
    btype = vtk_to_numpy(poly.GetPointData().GetArray("boundary_type"))
    on_interface_only = {v for f in expect_interface for v in f} - {v for f in expect_boundary for v in f}
    check(all((btype[k] == 2) == (vid[k] in on_interface_only) for k in range(len(vid))),
          "boundary --surface: boundary_type of the interface vertices")
    for ext in ("off", "stl", "obj", "mesh"):  # (meshio 5 cannot read face properties of binary .ply)
        prstar("boundary", "two.msh", "--surface", "surface." + ext, "--quiet")
        m = meshio.read(path("surface." + ext))
        tri = np.concatenate([c.data for c in m.cells if c.type == "triangle"])
        check(len(tri) == len(expect_boundary) + len(expect_interface), "boundary --surface ." + ext)

# ---------------------------------------------------------------------------------------------
# curvature: every row filled; both values in the CSV
r = prstar("curvature", "source.vtu", "--field", "scalar", "--json", "--csv", "curv.csv")
j = json.loads(r.stdout)
for part in ("interior", "boundary"):
    check(all(k in j[part] for k in ("distortion_min", "distortion_max", "distortion_mean", "domain_curvature_min",
                                    "domain_curvature_max", "domain_curvature_mean")), "curvature --json " + part)
check(abs(j["interior"]["domain_curvature_max"]) < 1e-9, "curvature: the domain is flat inside")
rows = open(path("curv.csv")).read().splitlines()
check(rows[0] == "vertex,x,y,z,boundary,distortion,domain_curvature" and len(rows) == len(pts) + 1, "curvature csv")
# the CSV's columns are the values summarised: the means of the boundary rows
cols = [r.split(",") for r in rows[1:]]
b = [c for c in cols if c[4] == "1"]
check(len(b) == j["boundary"]["vertices"] and
      abs(sum(float(c[5]) for c in b) / len(b) - j["boundary"]["distortion_mean"]) < 1e-12 and
      abs(sum(float(c[6]) for c in b) / len(b) - j["boundary"]["domain_curvature_mean"]) < 1e-12, "curvature csv")
r = prstar("curvature", "source.vtu", "--field", "scalar")
table = [l for l in r.stdout.splitlines() if l.startswith(("interior", "boundary", "all manifold"))]
check(len(table) == 3 and all(len(l.split()) >= 8 for l in table), "curvature table: rows not filled\n" + r.stdout)

# ---------------------------------------------------------------------------------------------
# Messages and exit statuses, in every command
commands = ["demo", "info", "convert", "stats", "boundary", "curvature", "validate", "simplify", "remesh", "generate"]
for c in commands:
    r = prstar(c, "--frob", expect=2)
    check(r.stderr == "prstar %s: unknown option --frob\nsee 'prstar %s --help'\n" % (c, c), c + ": " + r.stderr)
    check(prstar("help", c).stdout == prstar(c, "--help").stdout, "help " + c)
for c in ["info", "stats", "boundary", "curvature", "validate"]:
    r = prstar(c, "no_such_file.vtu", expect=1)
    check("no_such_file.vtu" in r.stderr and "no such file" in r.stderr.lower(), c + ": missing file: " + r.stderr)
    r = prstar(c, ".", expect=1)
    check("is a directory" in r.stderr, c + ": a directory: " + r.stderr)
r = prstar("stats", "source.vtu", "--kvv", "3", expect=2)
check("(did you mean --kv?)" in r.stderr, "did you mean --kv: " + r.stderr)
r = prstar("stast", expect=2)
check("did you mean stats?" in r.stderr, "did you mean stats: " + r.stderr)
r = prstar("--version")
check(r.stdout.startswith("prstar ") and "CGAL" in r.stdout, "--version: " + r.stdout)
start = time.monotonic()
r = prstar("simplify", "source.vtu", "--target", "30%", "-o", "no_such_folder/x.vtu", expect=1)
check("no_such_folder: No such file or directory" in r.stderr, "an output folder that does not exist: " + r.stderr)
r1 = json.loads(prstar("simplify", "source.vtu", "--target", "20%", "-o", "t20.vtu", "--json").stdout)
r2 = json.loads(prstar("simplify", "source.vtu", "--keep", "0.8", "-o", "k80.vtu", "--json").stdout)
check(r1["output_tetrahedra"] == r2["output_tetrahedra"] and r1["removed_tetrahedra"] >= 0.2 * len(tets),
      "--target 20% and --keep 0.8 differ")
r = prstar("stats", "source.vtu", "--max-memory", "1K", expect=1)
check("kB" in r.stderr and "0.00 GB" not in r.stderr, "--max-memory 1K: " + r.stderr)
r = prstar("generate", "--shape", "donut", "--cell-size", "0.1", "-o", "d.mesh", expect=2)
check("lattice" in r.stderr, "generate --shape donut: " + r.stderr)
prstar("generate", "--shape", "lattice", "--cells", "2", "-o", "lattice.mesh", "--quiet")
check(len(meshio.read(path("lattice.mesh")).cells[0].data) == 48, "generate --shape lattice -o .mesh")
# the streamed .vtu (raw appended, 32-bit connectivity and offsets), read by meshio: (N+1)^3
# points on the jittered lattice, 6 N^3 positively oriented tetrahedra, each the Kuhn tetrahedron
# of one cube from its corner 0 to its corner 7, and the point array x^2 / (N + 1) + y - z
prstar("generate", "--shape", "lattice", "--cells", "3", "-o", "lattice3.vtu", "--quiet")
with open(path("lattice3.vtu"), "rb") as f:
    head = f.read(2048).split(b"<AppendedData")[0].decode()
check('type="Int32" Name="connectivity"' in head and 'type="Int32" Name="offsets"' in head,
      "generate --shape lattice: 32-bit connectivity and offsets: " + head)
m = meshio.read(path("lattice3.vtu"))
P = np.asarray(m.points, dtype=float)
T = np.asarray(m.cells_dict.get("tetra", np.zeros((0, 4))), dtype=np.int64)
check(P.shape == (64, 3) and T.shape == (162, 4), "lattice3.vtu: %s points, %s tetrahedra" % (P.shape, T.shape))
if P.shape == (64, 3) and T.shape == (162, 4):
    g = np.array([[i % 4, i // 4 % 4, i // 16] for i in range(64)], dtype=float)
    check(np.abs(P - g).max() <= 0.1 and np.all(P[(g == 0) | (g == 3)] == g[(g == 0) | (g == 3)]),
          "lattice3.vtu: points off the jittered lattice")
    s = np.asarray(m.point_data["scalar"], dtype=float)
    check(np.allclose(s, P[:, 0] ** 2 / 4 + P[:, 1] - P[:, 2], rtol=0, atol=1e-12), "lattice3.vtu: scalar")
    lo, hi = g[T].min(axis=1), g[T].max(axis=1)
    check(np.all(hi - lo == 1), "lattice3.vtu: a tetrahedron not in one cube")
    check(all(any((g[t] == l).all() for t in tt) and any((g[t] == l + 1).all() for t in tt)
              for tt, l in zip(T, lo)), "lattice3.vtu: a tetrahedron without its cube's corners 0 and 7")
    d = P[T[:, 1:]] - P[T[:, :1]]
    check(np.all(np.linalg.det(d) > 0), "lattice3.vtu: a tetrahedron not positively oriented")
    check(len({tuple(sorted(t)) for t in T.tolist()}) == 162, "lattice3.vtu: a tetrahedron listed twice")

# The README's table of commands is the tool's own list
if len(sys.argv) > 3:
    listed = []
    in_list = False
    for line in prstar("--help").stdout.splitlines():
        if line == "commands:":
            in_list = True
        elif in_list and line.startswith("  "):
            name, summary = line.strip().split(None, 1)
            listed.append("| `%s` | %s |" % (name, summary))
        elif in_list:
            break
    with open(sys.argv[3]) as f:
        readme = [l for l in f.read().splitlines() if l.startswith("| `") and l.count("|") == 3]
    check(listed and all(l in readme for l in listed),
          "README's table of commands differs from prstar --help:\n" + "\n".join(l for l in listed if l not in readme))

if failures:
    print("%d failure(s)" % len(failures))
    sys.exit(1)
print("all checks passed")
