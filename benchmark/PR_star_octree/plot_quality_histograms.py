#!/usr/bin/python3
# Copyright (c) 2026 The PR-star octree project.
# SPDX-License-Identifier: LGPL-3.0-or-later
"""The quality histograms of the remeshing benchmark, the package against CGAL, per mesh.

Reads the OUT_histograms.csv that `bench_simplification --side-by-side --csv OUT.csv` writes (columns
mesh, method, measure, bin_low, bin_high, count, share) and draws, for every mesh, the distribution of
the dihedral angles (the six of every tetrahedron, 5-degree bins) and of the radius ratio (0.05 bins)
of each output, as shares on a logarithmic axis (the tails, small and large angles, are what matters
to a solver), with the issue's limits (10 and 165 degrees, radius ratio 0.1) as dotted lines.

usage: /usr/bin/python3 plot_quality_histograms.py HISTOGRAMS.csv OUT.png
           [--methods "CGAL remeshing,simplify,remesh"] [--names "file=title,..."] [--width 10]

Needs matplotlib (Debian: python3-matplotlib; scripts/install_dependencies.sh --benchmarks).
"""

import argparse
import csv
import io
import sys
from collections import OrderedDict

STYLE = {  # method -> (colour, line style, label)
    "input": ("#999999", ":", "input"),
    "CGAL remeshing": ("#d62728", "-", "CGAL tetrahedral_isotropic_remeshing"),
    "simplify": ("#1f77b4", "-", "PR-star simplify()"),
    "simplify (optimization_rounds 0)": ("#9ecae1", "--", "PR-star simplify(), no optimisation"),
    "remesh": ("#2ca02c", "-", "PR-star remesh()"),
}


def read(path):
    """{mesh: {measure: {method: (lows, highs, shares)}}} in file order."""
    data = OrderedDict()
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            m = data.setdefault(row["mesh"], OrderedDict()).setdefault(row["measure"], OrderedDict())
            lows, highs, shares = m.setdefault(row["method"], ([], [], []))
            lows.append(float(row["bin_low"]))
            highs.append(float(row["bin_high"]))
            shares.append(float(row["share"]))
    return data


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("histograms")
    ap.add_argument("out")
    ap.add_argument("--methods", default="input,CGAL remeshing,simplify,remesh",
                    help="comma-separated methods to draw, in this order")
    ap.add_argument("--names", default="", help="mesh titles: file=title,file=title")
    ap.add_argument("--width", type=float, default=10, help="figure width in inches (100 dpi)")
    args = ap.parse_args()
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        sys.exit("plot_quality_histograms.py: needs matplotlib (apt-get install python3-matplotlib)")
    try:
        data = read(args.histograms)
    except (OSError, KeyError, ValueError) as e:
        sys.exit(f"plot_quality_histograms.py: {args.histograms}: {e}")
    if not data:
        sys.exit(f"plot_quality_histograms.py: {args.histograms}: no histogram")
    names = dict(item.split("=", 1) for item in args.names.split(",") if "=" in item)
    methods = [m for m in args.methods.split(",") if m]

    measures = [("dihedral", "dihedral angles (degrees)", (10, 165)), ("radius_ratio", "radius ratio", (0.1,))]
    rows = len(data)
    fig, axes = plt.subplots(rows, 2, figsize=(args.width, 2.6 * rows + 0.6), squeeze=False, dpi=100)
    for i, (mesh, per_measure) in enumerate(data.items()):
        for j, (measure, xlabel, limits) in enumerate(measures):
            ax = axes[i][j]
            for method in methods:
                if method not in per_measure.get(measure, {}):
                    continue
                lows, highs, shares = per_measure[measure][method]
                colour, style, label = STYLE.get(method, ("black", "-", method))
                # a step curve over the bins; empty bins drop to the bottom of the log axis
                xs = [lows[0]] + highs
                ys = [max(s, 1e-9) for s in shares]
                ax.stairs(ys, xs, color=colour, linestyle=style, linewidth=1.4 if method != "input" else 1,
                          label=label, baseline=None)
            for x in limits:
                ax.axvline(x, color="black", linestyle=":", linewidth=0.8)
            ax.set_yscale("log")
            ax.set_ylim(1e-7, 1)
            ax.set_xlim(0, 180 if measure == "dihedral" else 1)
            ax.set_xlabel(xlabel, fontsize=8)
            ax.set_ylabel("share", fontsize=8)
            ax.tick_params(labelsize=7)
            ax.set_title(f"{names.get(mesh, mesh)}: {xlabel.split(' (')[0]}", fontsize=9)
    handles, labels = axes[0][0].get_legend_handles_labels()
    fig.legend(handles, labels, loc="lower center", ncol=len(labels), fontsize=8, frameon=False)
    fig.tight_layout(rect=(0, 0.05, 1, 1))
    # a palette PNG when Pillow is there (5-10x smaller than RGBA for line plots)
    buffer = io.BytesIO()
    fig.savefig(buffer, format="png")
    try:
        from PIL import Image
        buffer.seek(0)
        Image.open(buffer).convert("RGB").quantize(colors=32).save(args.out, optimize=True)
    except ImportError:
        with open(args.out, "wb") as f:
            f.write(buffer.getvalue())


if __name__ == "__main__":
    main()
