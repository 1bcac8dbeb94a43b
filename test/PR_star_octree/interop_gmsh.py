#!/usr/bin/python3
"""Interoperability of the gmsh .msh and Medit .meshb readers and writers with gmsh and meshio.

Usage: interop_gmsh.py TEST_IO_GMSH WORKDIR

TEST_IO_GMSH is the test program (its --dump FILE prints what our reader read as JSON, its
--convert IN OUT [--msh22] [--binary] [--meshb-version V] writes OUT with our writer).

1. gmsh meshes a box made of two physical volumes (and a physical surface) in every .msh variant
   (4.1 and 2.2, ASCII and binary, second order, partitioned); our reader must get exactly the node count and
   element count gmsh reports when it reads the file, and the tetrahedra and the label histogram
   of gmsh's own 2.2 ASCII conversion of it (parsed here) and of meshio's reading of the file.
2. Our writer's files (every variant) are read by gmsh (converted to 2.2 ASCII: same counts and
   labels) and by meshio (same counts, labels and physical names).
3. .meshb: files written by meshio are read by us, ours (versions 1-4) are read by meshio.
4. .msh files written by meshio (gmsh22 and gmsh 4.1, ASCII and binary) are read by us.
5. Point and cell data: our files (every variant, the tetrahedra reordered so that the two labels
   alternate, two point arrays and two cell arrays) are read by meshio (exactly one tetra block per
   label, the arrays equal to ours, the cell values grouped by label in the order of the mesh) and
   by gmsh (the file read without error, every view kept, its values equal to ours by node tag =
   vertex index + 1 and element tag = tetrahedron index + 1); meshio's files with point and cell
   data (every variant) are read by us with the same arrays.  meshio 5.0 refuses the binary data
   whose tags do not run 1, 2, ... in the order of the file (our 4.1 binary file with alternating
   labels): that refusal is checked, and the same file with grouped labels is read.
Exits 77 (skipped) when neither gmsh nor meshio is available; parts needing the missing one are
skipped with a message.
"""
import collections
import json
import math
import os
import re
import shutil
import subprocess
import sys

prog, work = os.path.abspath(sys.argv[1]), sys.argv[2]
os.makedirs(work, exist_ok=True)
os.chdir(work)

gmsh = shutil.which("gmsh")
try:
    import meshio
    import numpy as np
except ImportError:
    meshio = None
if gmsh is None and meshio is None:
    print("SKIPPED: neither gmsh nor meshio is installed")
    sys.exit(77)
if gmsh is None:
    print("SKIPPED (part): gmsh is not installed, only meshio is used")
if meshio is None:
    print("SKIPPED (part): meshio is not installed, only gmsh is used")

failures = []
checks = 0


def check(cond, msg):
    global checks
    checks += 1
    if not cond:
        failures.append(msg)
        print("FAIL:", msg)


def dump(path):
    r = subprocess.run([prog, "--dump", path], capture_output=True, text=True)
    if r.returncode != 0:
        failures.append("our reader refused %s: %s" % (path, r.stderr.strip()))
        print("FAIL: our reader refused", path, r.stderr.strip())
        return None
    d = json.loads(r.stdout)
    d["labels"] = {int(k): v for k, v in d["labels"].items()}
    d["label_names"] = {int(k): v for k, v in d["label_names"].items()}
    return d


def convert(src, dst, *options):
    r = subprocess.run([prog, "--convert", src, dst] + list(options), capture_output=True, text=True)
    check(r.returncode == 0, "our writer failed on %s: %s" % (dst, r.stderr.strip()))


def gmsh_reports(path):
    """Node and element counts gmsh prints when reading `path`, and its own 2.2 ASCII conversion."""
    out = path + ".gmsh22.msh"
    r = subprocess.run([gmsh, path, "-0", "-o", out, "-format", "msh22"], capture_output=True, text=True)
    check(r.returncode == 0 and os.path.exists(out), "gmsh could not read %s: %s" % (path, r.stdout[-500:]))
    text = r.stdout + r.stderr
    nodes = re.findall(r"Info\s*:\s*(\d+) nodes", text)
    elements = re.findall(r"Info\s*:\s*(\d+) elements", text)
    return (int(nodes[0]) if nodes else None, int(elements[0]) if elements else None, parse_msh22(out))


def parse_msh22(path):
    """Tetrahedra (types 4, 11) and their physical tags in an ASCII 2.2 file written by gmsh."""
    lines = open(path).read().split("\n")
    i = lines.index("$Elements")
    n = int(lines[i + 1])
    hist = collections.Counter()
    tets = 0
    for line in lines[i + 2:i + 2 + n]:
        f = line.split()
        if f[1] in ("4", "11"):
            tets += 1
            hist[int(f[3]) if int(f[2]) > 0 else 0] += 1
    j = lines.index("$Nodes")
    return {"vertices": int(lines[j + 1]), "tetrahedra": tets, "labels": dict(hist), "elements": n}


def meshio_reads(path):
    """Vertices, tetrahedra, label histogram, names of 3-D physical groups as meshio reads them."""
    m = meshio.read(path)
    tets = 0
    hist = collections.Counter()
    key = "gmsh:physical" if "gmsh:physical" in m.cell_data else ("medit:ref" if "medit:ref" in m.cell_data else None)
    for k, block in enumerate(m.cells):
        if block.type in ("tetra", "tetra10"):
            tets += len(block.data)
            if key is not None:
                for v in np.asarray(m.cell_data[key][k]).ravel():
                    hist[int(v)] += 1
    names = {}
    for name, value in m.field_data.items():
        value = list(np.asarray(value).ravel())
        if len(value) == 2 and int(value[1]) == 3:
            names[int(value[0])] = name
    return {"vertices": len(m.points), "tetrahedra": tets, "labels": dict(hist), "names": names}


def labels_of(d):
    return {k: v for k, v in d["labels"].items()}


GEO = """SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 1, 1, 1};
Box(2) = {1, 0, 0, 1, 0.5, 1};
BooleanFragments{ Volume{1}; Delete; }{ Volume{2}; Delete; }
Physical Volume("left part", 7) = {1};
Physical Volume("right", 12) = {2};
Physical Surface("bottom", 3) = {5};
Mesh.CharacteristicLengthMax = 0.25;
"""
VARIANTS = [("msh41", []), ("msh41", ["-bin"]), ("msh22", []), ("msh22", ["-bin"])]

reference = None  # a file of gmsh's, the input of the writer tests
if gmsh:
    with open("box.geo", "w") as f:
        f.write(GEO)
    for fmt, extra in VARIANTS + [("msh41", ["-order", "2"]), ("msh22", ["-order", "2", "-bin"]),
                                          ("msh41", ["-part", "2"]), ("msh41", ["-part", "3", "-bin"])]:
        name = "gmsh_%s%s.msh" % (fmt, "".join(extra).replace("-", "_"))
        r = subprocess.run([gmsh, "-3", "box.geo", "-format", fmt, "-o", name] + extra, capture_output=True, text=True)
        check(r.returncode == 0, "gmsh could not mesh box.geo (%s): %s" % (name, r.stdout[-500:]))
        ours = dump(name)
        if ours is None:
            continue
        nodes, elements, conv = gmsh_reports(name)
        what = "gmsh's " + name
        print("%s: ours %d vertices %d tetrahedra labels %s skipped %s" %
              (what, ours["vertices"], ours["tetrahedra"], ours["labels"], ours["skipped_cells"]))
        check(nodes == ours["vertices"], "%s: gmsh reports %s nodes, we read %d" % (what, nodes, ours["vertices"]))
        check(elements == ours["tetrahedra"] + sum(ours["skipped_cells"].values()),
              "%s: gmsh reports %s elements, we read %d tetrahedra + %s skipped" %
              (what, elements, ours["tetrahedra"], ours["skipped_cells"]))
        check(conv["tetrahedra"] == ours["tetrahedra"], "%s: gmsh's conversion has %d tetrahedra, we read %d" %
              (what, conv["tetrahedra"], ours["tetrahedra"]))
        check(conv["labels"] == labels_of(ours), "%s: gmsh's labels %s, ours %s" % (what, conv["labels"], ours["labels"]))
        check(set(ours["labels"]) == {7, 12}, "%s: labels %s, expected 7 and 12" % (what, ours["labels"]))
        check(ours["label_names"] == {7: "left part", 12: "right"}, "%s: names %s" % (what, ours["label_names"]))
        if "-order" in extra:
            check(list(ours["skipped_cells"]) == ["triangle6"], "%s: skipped %s" % (what, ours["skipped_cells"]))
        elif "-part" in extra:  # partition boundaries add lines and triangles
            check("triangle" in ours["skipped_cells"], "%s: skipped %s" % (what, ours["skipped_cells"]))
        else:
            check(list(ours["skipped_cells"]) == ["triangle"], "%s: skipped %s" % (what, ours["skipped_cells"]))
        if meshio and "-part" in extra:
            print("(meshio 5.0 cannot read partitioned files: %s checked against gmsh only)" % name)
        elif meshio:
            mi = meshio_reads(name)
            check(mi["vertices"] == ours["vertices"] and mi["tetrahedra"] == ours["tetrahedra"],
                  "%s: meshio reads %s, ours %s" % (what, mi, ours))
            check(mi["labels"] == labels_of(ours), "%s: meshio labels %s, ours %s" % (what, mi["labels"], ours["labels"]))
            check(mi["names"] == ours["label_names"], "%s: meshio names %s, ours %s" % (what, mi["names"], ours["label_names"]))
        if fmt == "msh41" and not extra:
            reference = name
elif meshio:
    # no gmsh: a small two-label mesh written by meshio is the reference
    pts = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1], [1, 1, 1], [2, 0, 0]], dtype=float)
    cells = [("tetra", np.array([[0, 1, 2, 3], [1, 2, 3, 4], [1, 5, 2, 3]]))]
    mm = meshio.Mesh(pts, cells, cell_data={"gmsh:physical": [np.array([7, 12, 12])],
                                            "gmsh:geometrical": [np.array([1, 2, 2])]},
                     field_data={"left part": np.array([7, 3]), "right": np.array([12, 3])})
    meshio.write("meshio_ref.msh", mm, file_format="gmsh22", binary=False)
    reference = "meshio_ref.msh"

# 2. our writer, read by gmsh and meshio
if reference:
    ref = dump(reference)
    for opts in ([], ["--binary"], ["--msh22"], ["--msh22", "--binary"]):
        out = "ours%s.msh" % "".join(opts).replace("-", "_")
        convert(reference, out, *opts)
        ours = dump(out)
        what = "our " + out
        if ours is None or ref is None:
            continue
        check(ours["vertices"] == ref["vertices"] and ours["tetrahedra"] == ref["tetrahedra"] and
              ours["labels"] == ref["labels"] and ours["label_names"] == ref["label_names"],
              "%s: read back %s, written from %s" % (what, ours, ref))
        check(ours["coordinate_checksum"] == ref["coordinate_checksum"], "%s: coordinates changed" % what)
        if gmsh:
            nodes, elements, conv = gmsh_reports(out)
            check(nodes == ref["vertices"] and elements == ref["tetrahedra"],
                  "%s: gmsh reports %s nodes %s elements, written %d/%d" %
                  (what, nodes, elements, ref["vertices"], ref["tetrahedra"]))
            check(conv["tetrahedra"] == ref["tetrahedra"] and conv["labels"] == labels_of(ref),
                  "%s: gmsh's conversion %s, written %s" % (what, conv, ref["labels"]))
        if meshio:
            mi = meshio_reads(out)
            check(mi["vertices"] == ref["vertices"] and mi["tetrahedra"] == ref["tetrahedra"],
                  "%s: meshio reads %s, written %s" % (what, mi, ref))
            check(mi["labels"] == labels_of(ref), "%s: meshio labels %s, written %s" % (what, mi["labels"], ref["labels"]))
            check(mi["names"] == ref["label_names"], "%s: meshio names %s, written %s" % (what, mi["names"], ref["label_names"]))
        print("%s: checked" % what)

    # 3. .meshb with meshio
    if meshio and ref:
        for version in (1, 2, 3, 4):
            out = "ours_v%d.meshb" % version
            convert(reference, out, "--meshb-version", str(version))
            mi = meshio_reads(out)
            check(mi["vertices"] == ref["vertices"] and mi["tetrahedra"] == ref["tetrahedra"] and
                  mi["labels"] == labels_of(ref), "our %s: meshio reads %s, written %s" % (out, mi, ref))
            print("our %s: meshio reads %d vertices, %d tetrahedra, labels %s" %
                  (out, mi["vertices"], mi["tetrahedra"], mi["labels"]))
        m = meshio.read(reference)
        tets = np.concatenate([b.data for b in m.cells if b.type == "tetra"])
        refs = np.concatenate([np.asarray(m.cell_data["gmsh:physical"][k]) for k, b in enumerate(m.cells)
                               if b.type == "tetra"])
        mm = meshio.Mesh(m.points, [("tetra", tets)], cell_data={"medit:ref": [refs]})
        meshio.write("meshio.meshb", mm)
        ours = dump("meshio.meshb")
        if ours:
            check(ours["vertices"] == len(m.points) and ours["tetrahedra"] == len(tets) and
                  ours["labels"] == dict(collections.Counter(int(v) for v in refs)),
                  "meshio's meshio.meshb: we read %s" % ours)
            print("meshio's meshio.meshb: ours %d vertices %d tetrahedra labels %s" %
                  (ours["vertices"], ours["tetrahedra"], ours["labels"]))

    # 4. .msh written by meshio
    if meshio and ref:
        m = meshio.read(reference)
        for fmt in ("gmsh22", "gmsh"):
            for binary in (False, True):
                out = "meshio_%s_%s.msh" % (fmt, "bin" if binary else "ascii")
                meshio.write(out, m, file_format=fmt, binary=binary)
                ours = dump(out)
                mi = meshio_reads(out)
                if ours:
                    check(ours["vertices"] == mi["vertices"] and ours["tetrahedra"] == mi["tetrahedra"],
                          "meshio's %s: meshio %s, ours %s" % (out, mi, ours))
                    check(labels_of(ours) == mi["labels"], "meshio's %s: labels meshio %s, ours %s" %
                          (out, mi["labels"], ours["labels"]))
                    print("meshio's %s: ours %d vertices %d tetrahedra labels %s" %
                          (out, ours["vertices"], ours["tetrahedra"], ours["labels"]))



# 5. point and cell data
def same_values(a, b):
    return len(a) == len(b) and all(float(x) == float(y) for x, y in zip(a, b))


def gmsh_views(path):
    """The views gmsh keeps when it reads `path`: {name: {tag: value}} for node and element data,
    from gmsh's own 4.1 ASCII output of each view."""
    with open(path + ".views.geo", "w") as f:
        f.write('Merge "%s";\nPostProcessing.SaveMesh = 0;\nMesh.MshFileVersion = 4.1;\nMesh.Binary = 0;\n'
                'For i In {0:PostProcessing.NbViews-1}\n  Save View[i] Sprintf("%s.view%%g.msh", i);\nEndFor\n'
                'Exit;\n' % (path, path))
    r = subprocess.run([gmsh, "-nopopup", path + ".views.geo", "-"], capture_output=True, text=True, timeout=300)
    check(r.returncode == 0 and "Error" not in r.stdout + r.stderr,
          "gmsh could not read the views of %s: %s" % (path, (r.stdout + r.stderr)[-500:]))
    views = {"NodeData": {}, "ElementData": {}}
    k = 0
    while os.path.exists("%s.view%d.msh" % (path, k)):
        lines = open("%s.view%d.msh" % (path, k)).read().split("\n")
        for i, line in enumerate(lines):
            if line in ("$NodeData", "$ElementData"):
                name = lines[i + 2].strip('"')
                j = i + 1 + int(lines[i + 1]) + 1
                j += int(lines[j]) + 1
                nint = int(lines[j])
                n = int(lines[j + 3])
                values = views[line[1:]].setdefault(name, {})
                for entry in lines[j + 1 + nint:j + 1 + nint + n]:
                    tag, value = entry.split()[:2]
                    values[int(tag)] = float(value)
        k += 1
    return views


if reference and meshio:
    for opts in ([], ["--binary"], ["--msh22"], ["--msh22", "--binary"]):
        for interleave in (True, False):
            if not interleave and opts != ["--binary"]:
                continue
            out = "data%s%s.msh" % ("".join(opts).replace("-", "_"), "_interleaved" if interleave else "")
            convert(reference, out, *(opts + ["--add-data"] + (["--interleave"] if interleave else [])))
            ours = dump(out)
            what = "our " + out
            if ours is None:
                continue
            check(sorted(ours["point_data"]) == ["p index", "px"] and sorted(ours["cell_data"]) == ["cq", "ct"],
                  "%s: we read back the arrays %s %s" % (what, list(ours["point_data"]), list(ours["cell_data"])))
            labels = ours["tetrahedron_labels"]
            if interleave:
                check(len(labels) > 2 and labels[0] != labels[1], "%s: the labels do not alternate" % what)
            try:
                mi = meshio.read(out, file_format="gmsh")
            except (Exception, SystemExit) as e:  # noqa: BLE001 (ReadError, or an exit when it guesses)
                if interleave and opts == ["--binary"]:
                    print("%s: meshio refuses the binary data of alternating labels, as documented (%s)" %
                          (what, type(e).__name__))
                    check(True, "")
                else:
                    check(False, "%s: meshio cannot read it: %r" % (what, e))
                mi = None
            if interleave and opts == ["--binary"] and mi is not None:
                check(False, "%s: meshio read binary data whose tags are not in file order" % what)
                mi = None
            if mi is not None:
                tetra = [k for k, b in enumerate(mi.cells) if b.type == "tetra"]
                if "--msh22" not in opts:
                    check(len(tetra) == len(set(labels)), "%s: meshio sees %d tetra blocks for the %d labels" %
                          (what, len(tetra), len(set(labels))))
                for name in ("px", "p index"):
                    check(same_values(mi.point_data.get(name, []), ours["point_data"].get(name, [None])),
                          "%s: meshio's point data %s differs from ours" % (what, name))
                # meshio lists the tetrahedra in the order of the file: grouped by label in 4.1
                physical = np.concatenate([np.asarray(mi.cell_data["gmsh:physical"][k]) for k in tetra])
                for name in ("cq", "ct"):
                    theirs = np.concatenate([np.asarray(mi.cell_data[name][k]) for k in tetra])
                    if "--msh22" in opts:
                        expected = ours["cell_data"][name]
                        check(list(physical) == labels, "%s: meshio's labels are not in the order of the mesh" % what)
                    else:
                        expected = [v for l in sorted(set(labels), key=labels.index)
                                    for v, l2 in zip(ours["cell_data"][name], labels) if l2 == l]
                    check(same_values(theirs, expected), "%s: meshio's cell data %s differs from ours" % (what, name))
            if gmsh:
                nodes, elements, conv = gmsh_reports(out)
                check(nodes == ours["vertices"] and elements == ours["tetrahedra"],
                      "%s: gmsh reports %s nodes %s elements, we wrote %d/%d" %
                      (what, nodes, elements, ours["vertices"], ours["tetrahedra"]))
                views = gmsh_views(out)
                for kind, key in (("NodeData", "point_data"), ("ElementData", "cell_data")):
                    for name, values in ours[key].items():
                        got = views[kind].get(name, {})
                        # gmsh writes 16 significant digits: equal within a few units in the last place
                        check(len(got) == len(values) and
                              all(math.isclose(got.get(i + 1, math.inf), v, rel_tol=1e-15) for i, v in enumerate(values)),
                              "%s: gmsh's view %s (%s) differs from ours: %d values" % (what, name, kind, len(got)))
            print("%s: checked" % what)

    # meshio's files with point and cell data, read by us
    m = meshio.read(reference)
    key = lambda p: (float(p[0]), float(p[1]), float(p[2]))
    temp = m.points[:, 0] / 3 + m.points[:, 1] * 7 - np.arange(len(m.points)) * 1e-3
    q = [np.arange(len(b.data), dtype=float) / 7 + k for k, b in enumerate(m.cells)]
    cd = {k: v for k, v in m.cell_data.items() if k in ("gmsh:physical", "gmsh:geometrical")}
    cd["q"] = q
    pd = {"temp": temp}
    if "gmsh:dim_tags" in m.point_data:
        pd["gmsh:dim_tags"] = m.point_data["gmsh:dim_tags"]
    mm = meshio.Mesh(m.points, m.cells, point_data=pd, cell_data=cd, field_data=m.field_data)
    of_point = {key(p): float(v) for p, v in zip(m.points, temp)}
    tet_q = list(np.concatenate([q[k] for k, b in enumerate(m.cells) if b.type == "tetra"]))
    for fmt in ("gmsh22", "gmsh"):
        for binary in (False, True):
            out = "meshio_data_%s_%s.msh" % (fmt, "bin" if binary else "ascii")
            meshio.write(out, mm, file_format=fmt, binary=binary)
            ours = dump(out)
            what = "meshio's " + out
            if ours is None:
                continue
            got = ours["point_data"].get("temp", [])
            check(len(got) == len(ours["points"]) and
                  all(of_point.get(key(p)) == v for p, v in zip(ours["points"], got)),
                  "%s: our point data temp differs from meshio's" % what)
            check(same_values(ours["cell_data"].get("q", []), tet_q), "%s: our cell data q differs from meshio's" % what)
            print("%s: ours point data %s, cell data %s" % (what, list(ours["point_data"]), list(ours["cell_data"])))

print("interop_gmsh: %d checks, %d failures" % (checks, len(failures)))
sys.exit(1 if failures or checks == 0 else 0)
