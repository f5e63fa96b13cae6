#!/usr/bin/env python3
"""Runs `lowstretch --non-disk charts --json` on meshes and prints a Markdown table: charts,
holes closed, seam length (in the mesh's units), L2 stretch of the whole layout and of the worst
chart, flips, coverage of the unit square, seconds.

usage: charts_table.py LOWSTRETCH MESH... [-- EXTRA lowstretch ARGUMENTS]
"""
import json
import os
import subprocess
import sys


def main():
    args = sys.argv[1:]
    extra = []
    if "--" in args:
        extra = args[args.index("--") + 1:]
        args = args[:args.index("--")]
    tool, meshes = args[0], args[1:]
    print("| mesh | V | F | charts | holes closed | seam length | L2 stretch | worst chart L2 | flips | coverage | seconds |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    for mesh in meshes:
        run = subprocess.run([tool, mesh, "--non-disk", "charts", "--json"] + extra, capture_output=True, text=True)
        name = os.path.basename(mesh)
        if run.returncode != 0:
            print(f"| {name} | rejected: {run.stderr.strip().split(': ', 2)[-1]} ||||||||||")
            continue
        d = json.loads(run.stdout)
        layout = d["layout"]
        l2 = lambda x: "inf" if x is None else f"{x:.4f}"
        worst = max((c["l2_stretch"] for c in d["charts"]), key=lambda x: float("inf") if x is None else x)
        holes = sum(c["closed_holes"] for c in d["charts"])
        print(f"| {name} | {d['vertices']} | {d['faces']} | {d['chart_count']} | {holes} | {d['seam_length']:.4g} | "
              f"{l2(layout['l2_stretch'])} | {l2(worst)} | {layout['flipped']} | {d['coverage']:.4f} | "
              f"{d['seconds_total']:.3f} |")


if __name__ == "__main__":
    main()
