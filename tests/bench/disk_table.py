#!/usr/bin/env python3
"""Runs `lowstretch --non-disk reject --json` on meshes (the paper's method on a disk, its single
chart kept whatever it is) and prints a Markdown table of the results.

usage: disk_table.py LOWSTRETCH MESH... [-- EXTRA lowstretch ARGUMENTS]
"""
from tool_table import l2, print_table


def row(d):
    p = d["passes"]
    kept = p[d["chosen_pass"]]
    u1 = l2(p[1]["l2_stretch"]) if len(p) > 1 else "-"
    return [str(d["vertices"]), l2(p[0]["l2_stretch"]), u1, l2(kept["l2_stretch"]), str(d["chosen_pass"]),
            str(kept["flipped"]), str(kept["degenerate"]), f"{d['seconds_total']:.3f}"]


if __name__ == "__main__":
    print_table(["mesh", "V", "U0 L2", "U1 L2", "U_opt L2", "kept pass", "flips", "zero-area", "seconds"], ["--non-disk", "reject"], row,
                empty_cells=6)
