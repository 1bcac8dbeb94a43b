#!/usr/bin/python3
# Copyright (c) 2026 The PR-star octree project.
# SPDX-License-Identifier: LGPL-3.0-or-later
"""The ParaView plugin's boundary filter against `prstar boundary` on the same file (issue 23).

Target: PRStar Boundary on a 10M-tetrahedron lattice in pvpython takes at most 1.2x the time of
`prstar boundary` on the same file (ParaView's read excluded on one side, the tool's on the other),
and its peak RSS is at most 1.3x the tool's.

The driver makes a jittered Kuhn lattice with `prstar generate --shape lattice --cells N` (6 N^3
tetrahedra; N = 119 gives 10.1M) as a .meshb, then runs alternately, each in a fresh process,
R times each:

  (a) `prstar boundary LATTICE.meshb -o OUT.vtu --json --kv K`: its "seconds" (octree and
      classification, the read and the write excluded; with -o the tool keeps the vertex
      permutation, as the filter does to give the codes in the grid's order), its peak RSS;
  (b) pvpython: the plugin's reader reads LATTICE.meshb into a vtkUnstructuredGrid (not timed), then
      PRStar Boundary (BucketSize K, no surface) is updated and timed; peak RSS (VmHWM) and the RSS
      after the read.

Both sides' boundary vertex counts must agree (exit 3 otherwise).  The Markdown table (min and
median, the ratios) goes to --out with the load, the date, the commit and the cores; "others" is the
cores the machine's other processes used during the run (from /proc/stat less the run's own CPU).

usage: /usr/bin/python3 bench_paraview.py --prstar BUILD/tools/prstar/prstar
           --plugin BUILD/lib/paraview-5.11/plugins/PRStarOctree/PRStarOctree.so
           [--cells 119] [--repeat 3] [--kv 50] [--out results/paraview.md] [--keep DIR]
"""

import argparse
import datetime
import json
import os
import statistics
import subprocess
import sys
import tempfile

PV_SIDE = r'''
import json, os, sys, time
def kib(key):
    for line in open("/proc/self/status"):
        if line.startswith(key):
            return int(line.split()[1])
    return 0
from paraview.simple import LoadPlugin
from paraview import servermanager as sm
plugin, mesh, kv = sys.argv[1], sys.argv[2], int(sys.argv[3])
LoadPlugin(plugin, remote=False, ns=globals())
r = PRStarMeshReader(FileName=mesh)
r.UpdatePipeline()
rss_read = kib("VmRSS")
t0 = time.perf_counter(); c0 = os.times()
b = PRStarBoundary(Input=r, GenerateSurface=0, BucketSize=kv)
b.UpdatePipeline()
t1 = time.perf_counter(); c1 = os.times()
peak = kib("VmHWM")
out = b.GetClientSideObject().GetOutputDataObject(0)
fd = out.GetFieldData()
print(json.dumps({"seconds": t1 - t0, "cpu": (c1.user - c0.user) + (c1.system - c0.system),
                  "filter_seconds": fd.GetArray("seconds").GetValue(0),
                  "boundary_vertices": int(fd.GetArray("boundary_vertices").GetValue(0)),
                  "peak_kib": peak, "rss_after_read_kib": rss_read}), flush=True)
os._exit(0)
'''


def cpu_jiffies():
    with open("/proc/stat") as f:
        v = list(map(int, f.readline().split()[1:]))
    return sum(v) - v[3] - v[4]  # busy: all but idle and iowait


def peak_of(cmd):
    """Peak RSS (KiB) of cmd through /usr/bin/time -f %M, and its stdout."""
    r = subprocess.run(["/usr/bin/time", "-f", "PEAK %M"] + cmd, capture_output=True, text=True)
    if r.returncode != 0:
        raise RuntimeError("%s: exit %d\n%s" % (" ".join(cmd), r.returncode, r.stderr[-2000:]))
    peak = int([line for line in r.stderr.splitlines() if line.startswith("PEAK ")][-1].split()[1])
    return r.stdout, peak


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--prstar", required=True)
    ap.add_argument("--plugin", required=True)
    ap.add_argument("--cells", type=int, default=119)
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--kv", type=int, default=50)
    ap.add_argument("--out")
    ap.add_argument("--keep", help="folder for the lattice (kept between runs)")
    a = ap.parse_args()
    folder = a.keep or tempfile.mkdtemp(prefix="bench_paraview_")
    os.makedirs(folder, exist_ok=True)
    mesh = os.path.join(folder, "lattice_%d.meshb" % a.cells)
    if not os.path.exists(mesh):
        subprocess.run([a.prstar, "generate", "--shape", "lattice", "--cells", str(a.cells), "-o", mesh,
                        "--quiet"], check=True)
    script = os.path.join(folder, "pv_side.py")
    open(script, "w").write(PV_SIDE)
    load = os.getloadavg()[0]
    rows = {"tool": [], "filter": []}
    for i in range(a.repeat):
        out, peak = peak_of([a.prstar, "boundary", mesh, "-o", os.path.join(folder, "out.vtu"), "--force",
                             "--json", "--quiet", "--kv", str(a.kv)])
        j = json.loads(out)
        rows["tool"].append({"seconds": j["seconds"], "peak_kib": peak, "boundary_vertices": j["boundary_vertices"]})
        j0 = cpu_jiffies()
        t0 = os.times()
        out, peak2 = peak_of(["pvpython", script, a.plugin, mesh, str(a.kv)])
        t1 = os.times()
        own = (t1.children_user - t0.children_user) + (t1.children_system - t0.children_system)
        others = max(0.0, ((cpu_jiffies() - j0) / os.sysconf("SC_CLK_TCK") - own) / (t1.elapsed - t0.elapsed))
        p = json.loads([line for line in out.splitlines() if line.startswith("{")][-1])
        p["others"] = others
        rows["filter"].append(p)
        print("run %d: tool %.3f s %d MiB; filter %.3f s (RequestData %.3f s) %d MiB (after read %d MiB), "
              "others %.2f cores"
              % (i + 1, j["seconds"], peak // 1024, p["seconds"], p["filter_seconds"], p["peak_kib"] // 1024,
                 p["rss_after_read_kib"] // 1024, others), flush=True)
    if len({r["boundary_vertices"] for r in rows["tool"] + rows["filter"]}) != 1:
        print("the boundary vertex counts differ", file=sys.stderr)
        sys.exit(3)

    def mm(side, key):
        v = [r[key] for r in rows[side]]
        return min(v), statistics.median(v)

    ts, tf = mm("tool", "seconds"), mm("filter", "seconds")
    tr = mm("filter", "filter_seconds")
    ps, pf = mm("tool", "peak_kib"), mm("filter", "peak_kib")
    ra = mm("filter", "rss_after_read_kib")
    commit = subprocess.run(["git", "-C", os.path.dirname(os.path.abspath(__file__)), "rev-parse", "--short",
                             "HEAD"], capture_output=True, text=True).stdout.strip()
    nt = 6 * a.cells ** 3
    lines = [
        "# ParaView plugin: PRStar Boundary in pvpython against `prstar boundary` (issue 23)",
        "",
        "%s, commit %s, %d cores, load %.2f at the start; others' cores during the filter runs: max %.2f."
        % (datetime.date.today().isoformat(), commit, os.cpu_count(), load, max(r["others"] for r in rows["filter"])),
        "Lattice of %d^3 cubes (%.1fM tetrahedra, .meshb), k_v = %d, %d runs each, alternated, fresh processes."
        % (a.cells, nt / 1e6, a.kv, a.repeat),
        "",
        "| | time min / median (s) | peak RSS min / median (MiB) |",
        "|---|---:|---:|",
        "| `prstar boundary -o` (octree + classification; read and write excluded) | %.3f / %.3f | %d / %d |"
        % (ts[0], ts[1], ps[0] // 1024, ps[1] // 1024),
        "| PRStar Boundary in pvpython (filter update; the read excluded) | %.3f / %.3f | %d / %d |"
        % (tf[0], tf[1], pf[0] // 1024, pf[1] // 1024),
        "| the filter's RequestData alone (its field data `seconds`: octree and classification) | %.3f / %.3f | |"
        % (tr[0], tr[1]),
        "| pvpython RSS after the read, before the filter | | %d / %d |" % (ra[0] // 1024, ra[1] // 1024),
        "| **ratio filter / tool** (target 1.2 time, 1.3 peak RSS) | **%.2f** (medians) | **%.2f** (medians) |"
        % (tf[1] / ts[1], pf[1] / ps[1]),
        "| RequestData alone / tool; the filter's own peak (peak - RSS after the read) / tool's peak | %.2f | %.2f |"
        % (tr[1] / ts[1], (pf[1] - ra[1]) / ps[1]),
        "",
    ]
    text = "\n".join(lines)
    print(text)
    if a.out:
        open(a.out, "w").write(text)


if __name__ == "__main__":
    main()
