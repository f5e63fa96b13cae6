#!/usr/bin/env python3
"""Runs `lowstretch --non-disk charts --json` on meshes and prints a Markdown table: charts,
holes closed, seam length (in the mesh's units), L2 stretch of the whole layout and of the worst
chart, flips, coverage of the unit square, seconds.

usage: charts_table.py LOWSTRETCH MESH... [-- EXTRA lowstretch ARGUMENTS]
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "bench"))
from tool_table import l2, print_table  # noqa: E402


def row(d):
    layout = d["layout"]
    worst = max((c["l2_stretch"] for c in d["charts"]), key=lambda x: float("inf") if x is None else x)
    holes = sum(c["closed_holes"] for c in d["charts"])
    return [str(d["vertices"]), str(d["faces"]), str(d["chart_count"]), str(holes), f"{d['seam_length']:.4g}",
            l2(layout["l2_stretch"]), l2(worst), str(layout["flipped"]), f"{d['coverage']:.4f}",
            f"{d['seconds_total']:.3f}"]


if __name__ == "__main__":
    print_table(["mesh", "V", "F", "charts", "holes closed", "seam length", "L2 stretch", "worst chart L2", "flips",
                 "coverage", "seconds"], ["--non-disk", "charts"], row,
                rejected_text=lambda stderr: stderr.split(": ", 2)[-1])
