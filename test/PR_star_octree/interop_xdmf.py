#!/usr/bin/env python3
"""XDMF against meshio, bit for bit.

- meshio writes .xdmf files (HDF5 heavy data and inline XML; tetrahedra alone or with triangles, a
  Mixed topology; float64 and float32 points; labels as gmsh:physical, name_to_read; point and
  cell data; a time series): our reader (test_io_xdmf --dump) gives the same points, tetrahedra,
  labels, point and cell data (values of the tetrahedra), and `prstar stats --json` reads them;
- our writer (test_io_xdmf --convert, HDF5 and inline XML) is read back by meshio.read with the same
  values.

Usage: interop_xdmf.py TEST_IO_XDMF PRSTAR WORK_DIR
Exit 77 (skipped) when meshio, numpy or h5py are missing.
"""
import json
import os
import subprocess
import sys

try:
    import h5py  # noqa: F401  (meshio's XDMF reader and writer need it)
    import meshio
    import numpy as np
except ImportError as e:
    print("interop_xdmf: skipped (%s)" % e)
    sys.exit(77)

tool, prstar, work = sys.argv[1], sys.argv[2], sys.argv[3]
os.makedirs(work, exist_ok=True)
failures = 0
checks = 0


def check(cond, what):
    global failures, checks
    checks += 1
    if not cond:
        failures += 1
        print("FAILED:", what)


def run(*args):
    p = subprocess.run(list(args), capture_output=True, text=True)
    if p.returncode != 0:
        raise RuntimeError("%s failed (%d): %s" % (" ".join(args), p.returncode, p.stderr))
    return p.stdout


def dump(path):
    return json.loads(run(tool, "--dump", path))


def bits(a):
    return np.ascontiguousarray(np.asarray(a, dtype=np.float64)).view(np.uint64)


rng = np.random.default_rng(7)
n = 60
points = rng.standard_normal((n, 3)) * np.array([1.0, 1e-3, 1e5])
points[0] = [0.1, 1.0 / 3.0, -0.0]
points[1] = [5e-324, 1e300, 0.30000000000000004]
tets = np.array([rng.choice(n, 4, replace=False) for _ in range(40)], dtype=np.int64)
tris = np.array([rng.choice(n, 3, replace=False) for _ in range(5)], dtype=np.int64)
phi = rng.standard_normal(n)
labels = rng.integers(-5, 1000, len(tets)).astype(np.int32)
quality = rng.random(len(tets))


def compare_ours(path, expected_points, expected_tets, expected_labels, point_data, cell_data, skipped=None):
    d = dump(path)
    name = os.path.basename(path)
    check(len(d["points"]) == len(expected_points), name + ": number of points")
    check(np.array_equal(bits(d["points"]), bits(expected_points)), name + ": points bit for bit")
    check(np.array_equal(np.array(d["tetrahedra"], dtype=np.int64).reshape(-1, 4), expected_tets),
          name + ": tetrahedra")
    check(d["labels"] == [int(x) for x in expected_labels], name + ": labels")
    check(sorted(d["point_data"]) == sorted(point_data), name + ": point data names %s" % list(d["point_data"]))
    for k, v in point_data.items():
        check(k in d["point_data"] and np.array_equal(bits(d["point_data"][k]), bits(v)), name + ": point data " + k)
    check(sorted(d["cell_data"]) == sorted(cell_data), name + ": cell data names %s" % list(d["cell_data"]))
    for k, v in cell_data.items():
        check(k in d["cell_data"] and np.array_equal(bits(d["cell_data"][k]), bits(v)), name + ": cell data " + k)
    if skipped is not None:
        check(d["skipped_cells"] == skipped, name + ": skipped cells %s" % d["skipped_cells"])
    # the tool reads it too (the format table)
    s = json.loads(run(prstar, "stats", path, "--json", "--quiet"))
    check(s["tetrahedra"] == len(expected_tets) or s["tetrahedra"] <= len(expected_tets),
          name + ": prstar stats tetrahedra")
    check(s["vertices"] == len(expected_points), name + ": prstar stats vertices")
    if len(expected_labels):
        check(sum(s.get("subdomains", {}).values()) == len(expected_tets), name + ": prstar stats subdomains")


# ---- meshio writes, we read
for data_format in ["HDF", "XML"]:
    # tetrahedra only, labels as gmsh:physical, point and cell data
    f = os.path.join(work, "meshio_tet_%s.xdmf" % data_format)
    meshio.write(f, meshio.Mesh(points, [("tetra", tets)], point_data={"phi": phi},
                                cell_data={"gmsh:physical": [labels], "quality": [quality]}),
                 file_format="xdmf", data_format=data_format)
    compare_ours(f, points, tets, labels, {"phi": phi}, {"quality": quality}, {})
    # a Mixed topology: triangles before and after the tetrahedra
    f = os.path.join(work, "meshio_mixed_%s.xdmf" % data_format)
    meshio.write(f, meshio.Mesh(points, [("triangle", tris), ("tetra", tets), ("triangle", tris[:2])],
                                cell_data={"gmsh:physical": [np.arange(5), labels, np.arange(2)],
                                           "quality": [np.zeros(5), quality, np.ones(2)]}),
                 file_format="xdmf", data_format=data_format)
    compare_ours(f, points, tets, labels, {}, {"quality": quality}, {"triangle": 7})
    # float32 points, int32 labels named as the FEniCS tutorials name them
    f = os.path.join(work, "meshio_f32_%s.xdmf" % data_format)
    p32 = points.copy()
    p32[1] = [1e-45, 3e38, 0.1]  # a float32 denormal and a large one
    p32 = p32.astype(np.float32)
    meshio.write(f, meshio.Mesh(p32, [("tetra", tets.astype(np.int32))], cell_data={"name_to_read": [labels]}),
                 file_format="xdmf", data_format=data_format)
    if data_format == "HDF":
        compare_ours(f, p32.astype(np.float64), tets, labels, {}, {}, {})
    else:
        # meshio writes float32 in XML with 8 significant digits, not always enough to come back: we
        # read the decimals as doubles, meshio as float32; rounded to float32 they agree
        ours = np.array(dump(f)["points"], dtype=np.float64).astype(np.float32)
        check(np.array_equal(ours, meshio.read(f).points), f + ": float32 points as meshio reads them")

# a time series: the first step (meshio writes its .h5 in the working folder)
os.chdir(work)
f = os.path.join(work, "meshio_series.xdmf")
with meshio.xdmf.TimeSeriesWriter(f) as w:
    w.write_points_cells(points, [("tetra", tets)])
    w.write_data(0.0, point_data={"phi": phi})
    w.write_data(1.0, point_data={"phi": 2 * phi})
compare_ours(f, points, tets, [], {"phi": phi}, {}, {})

# ---- we write, meshio reads
src = os.path.join(work, "source.vtu")
meshio.write(src, meshio.Mesh(points, [("tetra", tets)], point_data={"phi": phi, "psi": -phi},
                              cell_data={"label": [labels], "quality": [quality]}), compression=None)
for mode in ["hdf", "xml"]:
    out = os.path.join(work, "ours_%s.xdmf" % mode)
    run(tool, "--convert", src, out, mode)
    check(os.path.exists(os.path.join(work, "ours_%s.h5" % mode)) == (mode == "hdf"), out + ": the .h5 file")
    m = meshio.read(out)
    check(np.array_equal(bits(m.points), bits(points)), out + ": points bit for bit")
    check(len(m.cells) == 1 and m.cells[0].type == "tetra", out + ": one block of tetrahedra")
    check(np.array_equal(m.cells[0].data.astype(np.int64), tets), out + ": tetrahedra")
    check(np.array_equal(bits(m.point_data["phi"]), bits(phi)) and np.array_equal(bits(m.point_data["psi"]),
                                                                                  bits(-phi)),
          out + ": point data")
    check(np.array_equal(m.cell_data["label"][0], labels) and m.cell_data["label"][0].dtype.kind == "i",
          out + ": labels")
    check(np.array_equal(bits(m.cell_data["quality"][0]), bits(quality)), out + ": cell data")
    # and we read it back
    compare_ours(out, points, tets, labels, {"phi": phi, "psi": -phi}, {"quality": quality}, {})

print("interop_xdmf: meshio %s, %d checks, %d failures" % (meshio.__version__, checks, failures))
sys.exit(1 if failures else 0)
