#!/usr/bin/python3
# Copyright (c) 2026 The PR-star octree project.
# SPDX-License-Identifier: LGPL-3.0-or-later
#
# `mpiexec -np N prstar stats|boundary|curvature|validate` against the one-process `prstar`, end to
# end: the JSON summaries equal (but for the seconds and the distribution's own keys), and the
# per-vertex arrays of the outputs identical bit for bit, read back with VTK's Python bindings (an
# independent reader): the .pvtu's pieces without their ghost cells and points give the input's
# counts, and each vertex's values, found by GlobalPointIds, are those of the one-process output.
# Also: the gathered single-file output, a mesh smaller than the number of ranks, a malformed file
# (every rank exits non-zero with the message, within seconds), and simplify under mpirun (exit 2).
#
# usage: test_distributed_cli.py PRSTAR WORK MPIEXEC [MPIEXEC FLAGS...] -- MESH...
# exit 77 (skipped) without VTK's Python bindings.

import json
import os
import subprocess
import sys
import time

try:
    import numpy as np
    import vtk
    from vtk.util.numpy_support import vtk_to_numpy
except ImportError:
    print("VTK's Python bindings are missing: skipped")
    sys.exit(77)

prstar, work = sys.argv[1], sys.argv[2]
sep = sys.argv.index("--")
mpiexec = sys.argv[3:sep]
meshes = sys.argv[sep + 1:]
os.makedirs(work, exist_ok=True)
failures = 0
checks = 0


def check(cond, what):
    global failures, checks
    checks += 1
    if not cond:
        failures += 1
        print("FAILED:", what)


def run(args, ranks=None, timeout=600):
    cmd = ([*mpiexec[:1], "-np", str(ranks), *mpiexec[1:]] if ranks else []) + [prstar] + args
    start = time.time()
    p = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout)
    return p, time.time() - start


def summary(args, ranks=None):
    """The JSON summary, or the exit status and the error message when the command fails."""
    p, _ = run(args + ["--json"], ranks)
    if p.returncode not in (0, 3):
        messages = [l for l in p.stderr.splitlines() if l.startswith("prstar ")]  # not mpiexec's banner
        check(len(messages) == 1, f"{args} on {ranks} ranks: one message: {p.stderr}")
        return (p.returncode, messages[0] if messages else "")
    lines = [l for l in p.stdout.splitlines() if l.strip()]
    check(len(lines) == 1, f"{args} on {ranks} ranks: one JSON line (rank 0 only), got {len(lines)}")
    return json.loads(lines[0])


DISTRIBUTION_KEYS = {"ranks", "ghost_tetrahedra", "ghost_fraction", "ghost_vertices", "max_rank_tetrahedra",
                     "bytes_sent"}


def same_summary(one, dist, what):
    if isinstance(one, tuple) or isinstance(dist, tuple):  # a failure: the same exit status and message
        check(isinstance(one, tuple) and isinstance(dist, tuple) and one[0] == dist[0], f"{what}: {one} / {dist}")
        if isinstance(one, tuple) and isinstance(dist, tuple):
            check(one[1].split(": ", 1)[-1] == dist[1].split(": ", 1)[-1], f"{what}: message {one[1]} / {dist[1]}")
        return
    for k, v in dist.items():
        if k in DISTRIBUTION_KEYS or k in ("seconds", "output", "streamed"):  # (how the file was read)
            continue
        if k not in one and k in one.get("storage", {}):  # stats: how the octree stores the mesh
            check(one["storage"][k] == v, f"{what}: {k} = {v}, one process: {one['storage'][k]}")
            continue
        if k == "kv" and v == "auto":  # each rank chose k_v for its part: the one process chose too
            check(dist.get("kv_automatic") is True and one.get("kv_automatic") is True,
                  f"{what}: kv auto, one process: {one.get('kv')} (automatic: {one.get('kv_automatic')})")
            continue
        if k == "kv_automatic":
            continue
        check(k in one and one[k] == v, f"{what}: {k} = {v}, one process: {one.get(k)}")


def read_vtu(path):
    r = vtk.vtkXMLPUnstructuredGridReader() if path.endswith(".pvtu") else vtk.vtkXMLUnstructuredGridReader()
    r.SetFileName(path)
    r.Update()
    return r.GetOutput()


def point_arrays(grid, names):
    pd = grid.GetPointData()
    return {n: vtk_to_numpy(pd.GetArray(n)) for n in names if pd.GetArray(n) is not None}


def compare_outputs(mesh, args, arrays, ranks):
    command, options = args[0], args[1:]
    stem = os.path.join(work, os.path.splitext(os.path.basename(mesh))[0] + "_" + command)
    one_out = stem + "_one.vtu"
    p, _ = run([command, mesh, *options, "-o", one_out, "--force", "--quiet"])
    check(p.returncode == 0, f"{command} -o {one_out}: {p.stderr}")
    one = read_vtu(one_out)
    ref = point_arrays(one, arrays)
    check(set(ref) == set(arrays), f"{one_out}: arrays {arrays}")
    n_points, n_cells = one.GetNumberOfPoints(), one.GetNumberOfCells()

    # the pieces: without ghosts, the input's counts; values by global id equal bit for bit
    pvtu = f"{stem}_{ranks}.pvtu"
    p, _ = run([command, mesh, *options, "-o", pvtu, "--force", "--quiet"], ranks)
    check(p.returncode == 0, f"{command} -o {pvtu} on {ranks} ranks: {p.stderr}")
    grid = read_vtu(pvtu)
    pd, cd = grid.GetPointData(), grid.GetCellData()
    check(pd.GetGlobalIds() is not None and cd.GetGlobalIds() is not None, pvtu + ": global ids")
    point_ghost = vtk_to_numpy(pd.GetArray("vtkGhostType"))
    cell_ghost = vtk_to_numpy(cd.GetArray("vtkGhostType"))
    gids = vtk_to_numpy(pd.GetGlobalIds())
    cell_ids = vtk_to_numpy(cd.GetGlobalIds())
    owned = (point_ghost & 1) == 0
    check(int(np.count_nonzero(owned)) == n_points, f"{pvtu}: {np.count_nonzero(owned)} owned points, {n_points}")
    check(int(np.count_nonzero((cell_ghost & 1) == 0)) == n_cells,
          f"{pvtu}: {np.count_nonzero((cell_ghost & 1) == 0)} cells without ghosts, {n_cells}")
    check(len(np.unique(gids[owned])) == n_points, pvtu + ": each vertex owned once")
    check(len(np.unique(cell_ids[(cell_ghost & 1) == 0])) == n_cells, pvtu + ": each cell once")
    got = point_arrays(grid, arrays)
    for name in arrays:
        # every point of every piece, ghosts included, carries its owner's value
        same = np.array_equal(got[name].view(np.uint64), ref[name][gids].view(np.uint64))
        check(same, f"{pvtu}: array {name} differs from the one-process output")
    # the owned points are where the one-process output has them
    pts = vtk_to_numpy(grid.GetPoints().GetData())
    ref_pts = vtk_to_numpy(one.GetPoints().GetData())
    check(np.array_equal(pts, ref_pts[gids]), pvtu + ": coordinates by global id")
    # removing the ghost cells with VTK's own filter gives the input's count
    if hasattr(vtk, "vtkRemoveGhosts"):
        rg = vtk.vtkRemoveGhosts()
        rg.SetInputData(grid)
        rg.Update()
        check(rg.GetOutput().GetNumberOfCells() == n_cells, pvtu + ": vtkRemoveGhosts")

    # the .pvtu read back by the ranks (pieces merged by GlobalPointIds, ghost cells dropped): the
    # same mesh as the input
    same_summary(summary(["validate", mesh]), summary(["validate", pvtu], 2), f"validate {pvtu} on 2 ranks")

    # gathered into one file: the same arrays in the same order
    gathered = f"{stem}_{ranks}_gathered.vtu"
    p, _ = run([command, mesh, *options, "-o", gathered, "--force", "--quiet"], ranks)
    check(p.returncode == 0, f"{command} -o {gathered} on {ranks} ranks: {p.stderr}")
    g = read_vtu(gathered)
    check(g.GetNumberOfPoints() == n_points and g.GetNumberOfCells() == n_cells, gathered + ": counts")
    got = point_arrays(g, arrays)
    for name in arrays:
        check(np.array_equal(got[name].view(np.uint64), ref[name].view(np.uint64)), f"{gathered}: array {name}")


for mesh in meshes:
    for args in (["stats"], ["boundary"], ["curvature"], ["curvature", "--field", "y"], ["validate"]):
        one = summary(args[:1] + [mesh] + args[1:])
        for ranks in (1, 2, 3, 4):
            same_summary(one, summary(args[:1] + [mesh] + args[1:], ranks), f"{args} {mesh} on {ranks} ranks")
    compare_outputs(mesh, ["boundary"], ["boundary"], 3)
    compare_outputs(mesh, ["curvature", "--field", "x"], ["boundary", "distortion", "domain_curvature"], 4)

# the local octrees compact, with float coordinates: the summaries of one process with the same options
if meshes:
    for args in (["stats"], ["boundary"], ["curvature"], ["validate"]):
        for storage in (["--compact"], ["--coordinates", "float32"], ["--compact", "--coordinates", "float32"]):
            one = summary(args[:1] + [meshes[0]] + args[1:] + storage)
            dist = summary(args[:1] + [meshes[0]] + args[1:] + storage, 3)
            same_summary(one, dist, f"{args} {storage} {meshes[0]} on 3 ranks")
            if not isinstance(dist, tuple) and "compact_tetrahedra" in dist:
                check(dist["compact_tetrahedra"] == ("--compact" in storage), f"{args} {storage}: {dist}")

# more ranks than vertices: ranks with nothing
tiny = os.path.join(work, "one_tetrahedron.mesh")
with open(tiny, "w") as f:
    f.write("MeshVersionFormatted 2\nDimension 3\nVertices\n4\n0 0 0 1\n1 0 0 1\n0 1 0 1\n0 0 1 1\n"
            "Tetrahedra\n1\n1 2 3 4 7\nEnd\n")
for command in ("stats", "boundary", "validate"):
    same_summary(summary([command, tiny]), summary([command, tiny], 4), f"{command} {tiny} on 4 ranks")

# a malformed file: every rank exits non-zero with the message, within seconds
if meshes:
    data = open(meshes[0], "rb").read()
    bad = os.path.join(work, "truncated.vtu")
    with open(bad, "wb") as f:
        f.write(data[: len(data) * 2 // 3])
    for target in (bad, os.path.join(work, "missing.vtu")):
        p, seconds = run(["boundary", target], 3, timeout=120)
        check(p.returncode == 1, f"boundary {target} on 3 ranks: exit {p.returncode}")
        check(os.path.basename(target) in p.stderr, f"boundary {target}: the message names the file: {p.stderr}")
        check(seconds < 60, f"boundary {target}: {seconds:.1f} s")

# simplify is not distributed: exit 2, said once
p, _ = run(["simplify", tiny, "--target", "0.5", "-o", os.path.join(work, "s.mesh")], 2)
check(p.returncode == 2, f"simplify on 2 ranks: exit {p.returncode}")
check(p.stderr.count("not distributed yet") == 1, "simplify on 2 ranks: said once: " + p.stderr)

print(f"test_distributed_cli: {checks} checks, {failures} failures")
sys.exit(1 if failures or checks == 0 else 0)
