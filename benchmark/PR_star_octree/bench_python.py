#!/usr/bin/python3
# Copyright (c) 2026 The PR-star octree project.
# SPDX-License-Identifier: LGPL-3.0-or-later
"""The Python module against the C++ API on the same arrays (issue 21).

Target: ``prstar.boundary`` on a 10M-tetrahedron lattice from numpy arrays takes at most 1.05x the
time of the C++ API on the same arrays, and its peak RSS is at most 1.1x, plus the input arrays.

The driver makes a jittered Kuhn lattice of N^3 cubes (6 N^3 tetrahedra, (N+1)^3 vertices; N = 120
gives 10.4M) with numpy, saves it as POINTS.npy (float64, (n, 3)) and TETS.npy (int64, (m, 4)) in a
temporary folder, then runs, alternately, each in a fresh process, R times each and for
surface=False and surface=True:

  (a) ``bench_python_api POINTS.npy TETS.npy [--surface] --kv K`` (the C++ API: the octree built
      from the arrays with the module's parameters, compute_boundary, boundary_surface);
  (b) a Python process that ``np.load``s the same files and times
      ``prstar.Octree(points, tets, bucket_size=K)`` + ``prstar.boundary(tree, surface=...)``.

Each prints one JSON line: build, boundary and total seconds, the counts, order-dependent checksums
of the vertex codes and surface triangles, peak RSS (VmHWM, read before the checksums) and the RSS
after loading the arrays.  The counts and checksums of the two sides must agree (exit 3 otherwise).
The Markdown table (min and median of each, Python/C++ ratios of time and peak RSS, and the peak
RSS minus the input arrays' size) goes to --out with the machine's load, date, commit and cores.

usage: /usr/bin/python3 bench_python.py --prstar-python BUILD/python \\
           --cpp BUILD/benchmark/PR_star_octree/bench_python_api [--cells 120] [--repeat 3] [--kv 50]
           [--threads N] [--out results/python.md]

Wall-clock times on a shared machine are only as good as its quiet: each run also reports its CPU
time (user + system, all threads) and "others", the cores that the machine's other processes used
meanwhile (from /proc/stat less the run's own CPU time), so that a disturbed run can be told apart.
"""

from __future__ import annotations

import argparse
import datetime
import json
import os
import resource
import statistics
import subprocess
import sys
import tempfile
import time
from typing import Any, Dict, List, Optional, Tuple

# The Python side: run in a fresh interpreter as `bench_python.py _python POINTS TETS SURFACE KV`.
# Kept in this file so that both sides are visible together.


def status_kib(key: str) -> int:
    """A field of /proc/self/status in KiB (VmRSS, VmHWM)."""
    with open("/proc/self/status") as f:
        for line in f:
            if line.startswith(key):
                return int(line.split()[1])
    return 0


def python_side(points_file: str, tets_file: str, surface: bool, kv: int, threads: int) -> None:
    """Loads the arrays, times prstar.Octree + prstar.boundary, prints the JSON line."""
    import numpy as np
    import prstar

    points = np.load(points_file)
    tets = np.load(tets_file)
    input_bytes = points.nbytes + tets.nbytes
    rss_after_load = status_kib("VmRSS:")

    c0, t0 = time.process_time(), time.perf_counter()
    tree = prstar.Octree(points, tets, bucket_size=kv, threads=threads or None)
    t1, c1 = time.perf_counter(), time.process_time()
    result = prstar.boundary(tree, surface=surface)
    t2, c2 = time.perf_counter(), time.process_time()
    peak = status_kib("VmHWM:")  # before the checksums' temporaries

    codes = result.vertex_types.astype(np.uint64)
    code_sum = int(np.sum(codes * np.arange(1, codes.size + 1, dtype=np.uint64), dtype=np.uint64))
    counts = {k: int(v) for k, v in result.counts.items()}
    tri_sum = 0
    if surface:
        tri = result.triangles.reshape(-1).astype(np.uint64)
        tri_sum = int(np.sum(tri * np.arange(1, tri.size + 1, dtype=np.uint64), dtype=np.uint64))
        counts["surface_triangles"] = int(result.triangles.shape[0])
    print(json.dumps({
        "side": "python", "surface": surface, "kv": kv, "threads": threads,
        "build_s": t1 - t0, "boundary_s": t2 - t1, "total_s": t2 - t0,
        "build_cpu_s": c1 - c0, "boundary_cpu_s": c2 - c1, "total_cpu_s": c2 - c0,
        "counts": counts, "code_checksum": code_sum, "triangle_checksum": tri_sum,
        "input_bytes": input_bytes, "rss_after_load_kib": rss_after_load, "peak_rss_kib": peak,
    }), flush=True)


# ---------------------------------------------------------------------------------------------
# The driver
# ---------------------------------------------------------------------------------------------

def kuhn_lattice(cells: int, seed: int = 20260421) -> Tuple[Any, Any]:
    """A jittered Kuhn lattice of cells^3 unit cubes: (cells+1)^3 points (float64, jittered by at most
    0.15 of a cell in each coordinate), 6 cells^3 tetrahedra (int64), each cube split along its diagonal
    from (0,0,0) to (1,1,1) into the six paths that step once along each axis in some order."""
    import numpy as np

    n = cells + 1
    rng = np.random.default_rng(seed)
    g = np.arange(n, dtype=np.float64)
    x, y, z = np.meshgrid(g, g, g, indexing="ij")  # vertex (i, j, k) is i*n*n + j*n + k
    points = np.stack([x.ravel(), y.ravel(), z.ravel()], axis=1)
    del x, y, z
    points += rng.uniform(-0.15, 0.15, size=points.shape)
    c = np.arange(cells, dtype=np.int64)
    i, j, k = np.meshgrid(c, c, c, indexing="ij")
    base = (i * n * n + j * n + k).ravel()  # the (0,0,0) corner of each cube
    del i, j, k
    step = [n * n, n, 1]  # one step along x, y, z
    tets = np.empty((6 * base.size, 4), dtype=np.int64)
    perms = [(0, 1, 2), (0, 2, 1), (1, 0, 2), (1, 2, 0), (2, 0, 1), (2, 1, 0)]
    for p, (a, b, _) in enumerate(perms):  # cube-major order: the 6 tetrahedra of a cube together
        tets[p::6, 0] = base
        tets[p::6, 1] = base + step[a]
        tets[p::6, 2] = base + step[a] + step[b]
        tets[p::6, 3] = base + n * n + n + 1
    return points, tets


def busy_cpu_seconds() -> float:
    """The CPU seconds all processes of the machine have used (/proc/stat, all cores)."""
    with open("/proc/stat") as f:
        v = [int(x) for x in f.readline().split()[1:]]
    # user nice system idle iowait irq softirq steal ...: all but idle and iowait
    return (sum(v[:8]) - v[3] - v[4]) / os.sysconf("SC_CLK_TCK")


def run_json(cmd: List[str], env: Optional[Dict[str, str]] = None) -> Dict[str, Any]:
    """Runs `cmd`, returns its last stdout line as JSON (exits with its code on a failure), with
    "others": the cores the machine's other processes used on average while it ran (the machine's busy
    time less the child's own CPU time, over the wall time)."""
    ru0, busy0, w0 = resource.getrusage(resource.RUSAGE_CHILDREN), busy_cpu_seconds(), time.perf_counter()
    p = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=env)
    ru1, busy1, w1 = resource.getrusage(resource.RUSAGE_CHILDREN), busy_cpu_seconds(), time.perf_counter()
    if p.returncode != 0:
        sys.stderr.write(f"failed ({p.returncode}): {' '.join(cmd)}\n{p.stderr}")
        sys.exit(p.returncode or 1)
    res = json.loads(p.stdout.strip().splitlines()[-1])
    own = (ru1.ru_utime + ru1.ru_stime) - (ru0.ru_utime + ru0.ru_stime)
    res["others"] = max(0.0, (busy1 - busy0 - own) / (w1 - w0))
    return res


def machine_facts() -> Dict[str, str]:
    def out(cmd: List[str]) -> str:
        try:
            return subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True,
                                  cwd=os.path.dirname(os.path.abspath(__file__))).stdout.strip()
        except OSError:
            return "?"
    return {
        "date": datetime.datetime.now().astimezone().strftime("%Y-%m-%d %H:%M %Z"),
        "commit": out(["git", "rev-parse", "--short", "HEAD"]),
        "cores": str(os.cpu_count()),
        "uptime": out(["uptime"]),
    }


def mib(kib: float) -> str:
    return f"{kib / 1024:.0f}"


def table(runs: Dict[Tuple[str, bool], List[Dict[str, Any]]], input_bytes: int) -> List[str]:
    """The Markdown rows: per surface setting, each quantity for C++ and Python (min / median) and the
    ratio Python/C++ of the medians (and of the minima)."""
    input_kib = input_bytes / 1024
    lines = ["| surface | quantity | C++ min | C++ median | Python min | Python median | "
             "Python/C++ (median) | Python/C++ (min) |",
             "|---|---|---:|---:|---:|---:|---:|---:|"]
    quantities = [
        ("build (s)", lambda r: r["build_s"], "{:.3f}"),
        ("boundary (s)", lambda r: r["boundary_s"], "{:.3f}"),
        ("**total (s)**", lambda r: r["total_s"], "{:.3f}"),
        ("build CPU (s)", lambda r: r["build_cpu_s"], "{:.3f}"),
        ("boundary CPU (s)", lambda r: r["boundary_cpu_s"], "{:.3f}"),
        ("total CPU (s)", lambda r: r["total_cpu_s"], "{:.3f}"),
        ("RSS after load (MiB)", lambda r: r["rss_after_load_kib"] / 1024, "{:.0f}"),
        ("**peak RSS (MiB)**", lambda r: r["peak_rss_kib"] / 1024, "{:.0f}"),
        ("peak RSS - input arrays (MiB)", lambda r: (r["peak_rss_kib"] - input_kib) / 1024, "{:.0f}"),
        ("peak RSS - RSS after load (MiB)", lambda r: (r["peak_rss_kib"] - r["rss_after_load_kib"]) / 1024,
         "{:.0f}"),
    ]
    for surface in (False, True):
        for name, get, fmt in quantities:
            c = [get(r) for r in runs[("cpp", surface)]]
            p = [get(r) for r in runs[("python", surface)]]
            cm, cmed, pm, pmed = min(c), statistics.median(c), min(p), statistics.median(p)
            lines.append(f"| {surface} | {name} | {fmt.format(cm)} | {fmt.format(cmed)} | {fmt.format(pm)} | "
                         f"{fmt.format(pmed)} | {pmed / cmed:.3f} | {pm / cm:.3f} |")
    return lines


def main() -> int:
    if len(sys.argv) > 1 and sys.argv[1] == "_python":
        python_side(sys.argv[2], sys.argv[3], sys.argv[4] == "1", int(sys.argv[5]), int(sys.argv[6]))
        return 0
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--cells", type=int, default=120, help="N: N^3 cubes, 6 N^3 tetrahedra (default 120)")
    ap.add_argument("--repeat", type=int, default=3, help="runs of each side and setting (default 3)")
    ap.add_argument("--kv", type=int, default=50, help="bucket_size / --kv (default 50)")
    ap.add_argument("--threads", type=int, default=0, help="threads of both sides (default 0: all cores)")
    ap.add_argument("--out", help="the Markdown file to write (default: stdout only)")
    ap.add_argument("--prstar-python", required=True, help="BUILD/python (the PYTHONPATH of prstar)")
    ap.add_argument("--cpp", required=True, help="BUILD/benchmark/PR_star_octree/bench_python_api")
    ap.add_argument("--workdir", help="where to write the .npy files (default: a temporary folder)")
    args = ap.parse_args()

    import numpy as np

    with tempfile.TemporaryDirectory(prefix="bench_python_", dir=args.workdir) as tmp:
        t0 = time.perf_counter()
        points, tets = kuhn_lattice(args.cells)
        points_file, tets_file = os.path.join(tmp, "POINTS.npy"), os.path.join(tmp, "TETS.npy")
        np.save(points_file, points)
        np.save(tets_file, tets)
        nv, nt = points.shape[0], tets.shape[0]
        input_bytes = points.nbytes + tets.nbytes
        del points, tets
        print(f"lattice {args.cells}^3: {nv} vertices, {nt} tetrahedra, {input_bytes / 2**20:.0f} MiB of "
              f"arrays ({time.perf_counter() - t0:.1f} s)", flush=True)

        env = dict(os.environ)
        env["PYTHONPATH"] = os.path.abspath(args.prstar_python) + (
            os.pathsep + env["PYTHONPATH"] if env.get("PYTHONPATH") else "")
        facts_before = machine_facts()
        runs: Dict[Tuple[str, bool], List[Dict[str, Any]]] = {
            (s, f): [] for s in ("cpp", "python") for f in (False, True)}
        sequence: List[Tuple[int, Dict[str, Any]]] = []  # (repetition, result) in run order
        for r in range(args.repeat):
            for surface in (False, True):
                # alternate which side goes first, so that neither always follows the other
                order = ("cpp", "python") if (r + surface) % 2 == 0 else ("python", "cpp")
                for side in order:
                    if side == "cpp":
                        cmd = [args.cpp, points_file, tets_file, "--kv", str(args.kv), "--threads",
                               str(args.threads)]
                        if surface:
                            cmd.append("--surface")
                        res = run_json(cmd)
                    else:
                        res = run_json([sys.executable, os.path.abspath(__file__), "_python", points_file,
                                        tets_file, "1" if surface else "0", str(args.kv),
                                        str(args.threads)], env)
                    runs[(side, surface)].append(res)
                    sequence.append((r + 1, res))
                    print(f"  run {r + 1} surface={surface} {side:6s}: build {res['build_s']:.3f} s, "
                          f"boundary {res['boundary_s']:.3f} s, total {res['total_s']:.3f} s (CPU "
                          f"{res['total_cpu_s']:.3f} s), peak RSS {mib(res['peak_rss_kib'])} MiB (after load "
                          f"{mib(res['rss_after_load_kib'])}), others {res['others']:.2f} cores",
                          flush=True)
        facts_after = machine_facts()

    # both sides must find the same boundary
    mismatches = []
    for surface in (False, True):
        ref = runs[("cpp", surface)][0]
        for res in runs[("cpp", surface)] + runs[("python", surface)]:
            for key in ("code_checksum", "triangle_checksum"):
                if res[key] != ref[key]:
                    mismatches.append(f"surface={surface} {res['side']}: {key} {res[key]} != {ref[key]}")
            for key, value in ref["counts"].items():
                if res["counts"].get(key) != value:
                    mismatches.append(f"surface={surface} {res['side']}: {key} {res['counts'].get(key)} != {value}")

    c = runs[("cpp", True)][0]["counts"]
    lines = [
        f"Lattice {args.cells}^3 cubes (jittered Kuhn): {nv:,} vertices, {nt:,} tetrahedra; input arrays "
        f"{input_bytes / 2**20:.0f} MiB (points float64 {nv * 24 / 2**20:.0f} MiB, tetrahedra int64 "
        f"{nt * 32 / 2**20:.0f} MiB); k_v = {args.kv}; "
        f"{'all cores (threads=None)' if not args.threads else f'threads={args.threads}'}; {args.repeat} runs "
        f"of each side and setting, alternating, each in a fresh process.  Times are wall-clock seconds of "
        f"the timed calls (CPU: user + system of all threads); peak RSS is VmHWM.",
        "",
        f"Counts (equal on both sides: {'yes' if not mismatches else 'NO'}): "
        f"{c['boundary_vertices']:,} boundary vertices, {c['interior_vertices']:,} interior, "
        f"{c['boundary_triangles']:,} boundary triangles.",
        "",
        *table(runs, input_bytes),
        "",
        "Each run, in order (others: the cores the machine's other processes used meanwhile, on average):",
        "",
        "| run | surface | side | build (s) | boundary (s) | total (s) | total CPU (s) | peak RSS (MiB) | others |",
        "|---:|---|---|---:|---:|---:|---:|---:|---:|",
        *[f"| {r} | {res['surface']} | {res['side']} | {res['build_s']:.3f} | {res['boundary_s']:.3f} | "
          f"{res['total_s']:.3f} | {res['total_cpu_s']:.3f} | {mib(res['peak_rss_kib'])} | {res['others']:.2f} |"
          for r, res in sequence],
        "",
        f"Machine: {facts_before['cores']} cores; date {facts_before['date']}; commit {facts_before['commit']}.",
        f"Load before: `{facts_before['uptime']}`",
        f"Load after: `{facts_after['uptime']}`",
        "",
        f"Command: `/usr/bin/python3 benchmark/PR_star_octree/bench_python.py --cells {args.cells} "
        f"--repeat {args.repeat} --kv {args.kv}{f' --threads {args.threads}' if args.threads else ''} "
        f"--prstar-python BUILD/python "
        f"--cpp BUILD/benchmark/PR_star_octree/bench_python_api`",
    ]
    text = "\n".join(lines) + "\n"
    print(text)
    if args.out:
        with open(args.out, "w") as f:
            f.write(text)
    if mismatches:
        sys.stderr.write("the two sides disagree:\n  " + "\n  ".join(mismatches) + "\n")
        return 3
    return 0


if __name__ == "__main__":
    sys.exit(main())
