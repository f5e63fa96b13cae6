#!/usr/bin/env python3
"""Runs `lowstretch --json` on meshes and prints a Markdown table of the results.

usage: disk_table.py LOWSTRETCH MESH... [-- EXTRA lowstretch ARGUMENTS]
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
    print("| mesh | V | U0 L2 | U1 L2 | U_opt L2 | kept pass | flips | zero-area | seconds |")
    print("|---|---|---|---|---|---|---|---|---|")
    for mesh in meshes:
        run = subprocess.run([tool, mesh, "--json"] + extra, capture_output=True, text=True)
        name = os.path.basename(mesh)
        if run.returncode != 0:
            print(f"| {name} | rejected: {run.stderr.strip()} |||||||")
            continue
        d = json.loads(run.stdout)
        p = d["passes"]
        kept = p[d["chosen_pass"]]
        l2 = lambda x: "inf" if x is None else f"{x:.4f}"
        u1 = l2(p[1]["l2_stretch"]) if len(p) > 1 else "-"
        print(f"| {name} | {d['vertices']} | {l2(p[0]['l2_stretch'])} | {u1} | {l2(kept['l2_stretch'])} | "
              f"{d['chosen_pass']} | {kept['flipped']} | {kept['degenerate']} | {d['seconds_total']:.3f} |")


if __name__ == "__main__":
    main()
