#!/usr/bin/env python3
"""U_opt, --refine and the optimum for the same boundary, side by side. The optimum is the lowest
L2 stretch reached by minimizing the L2 stretch energy with the same fixed boundary, from U_opt,
by Newton steps (CHOLMOD, per-triangle projected Hessians where the exact one is not positive
definite) with a line search that never lets a triangle flip or collapse, run until it converged
or hit a time limit, made outside the repository: --refine's minimization (which projects every
triangle's Hessian) run to its own stop rule is `lowstretch MESH --boundary B --non-disk reject
--refine --refine-iterations 10000`. OPTIMUM.md is its Markdown table (mesh in the first column,
boundary in the third, L2 stretch in the seventh).
For every mesh and boundary of that table, runs `lowstretch --non-disk reject --json` with and
without --refine and prints a Markdown table (L2 and Linf stretch of the stored map, seconds of
core time, the time ratio measured within the refined run (its whole time over the time of its
passes, the refinement's own seconds coming from its note), Newton iterations, flipped +
zero-area triangles), then the median and worst refined / optimum over the rows whose boundary is
the one the optimum was computed for (on BENT_SIDES the optimum's square sides bow by a quarter,
the tool's bend by under 1%: those rows are listed, not counted).

usage: refine_table.py LOWSTRETCH OPTIMUM.md MESH_FOLDER
"""
import json
import os
import re
import statistics
import subprocess
import sys

BENT_SIDES = ("45045", "179730", "seams_camel")  # the optimum's square differs from the tool's here


def run(tool, path, boundary, *extra):
    # disk only: the paper's single chart, compared with the optimum for its boundary
    proc = subprocess.run([tool, path, "--boundary", boundary, "--non-disk", "reject", "--json", *extra],
                          capture_output=True, text=True)
    return json.loads(proc.stdout)


def main():
    tool, reference, folder = sys.argv[1:4]
    optimum = {}
    with open(reference) as f:
        for line in f:
            cells = [c.strip() for c in line.split("|")]
            if len(cells) > 8 and cells[1].startswith(("disk_", "seams_")):
                optimum[(cells[1], cells[3])] = float(cells[7])
    print("| mesh | boundary | L2 U_opt | L2 refined | L2 optimum | refined / optimum | Linf U_opt | Linf refined "
          "| s U_opt | s refined | time ratio (one run) | iterations | flipped + zero |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    counted = []
    for (mesh, boundary), best in sorted(optimum.items()):
        path = os.path.join(folder, mesh)
        plain, refined = run(tool, path, boundary), run(tool, path, boundary, "--refine")
        u, r = plain["layout"], refined["layout"]
        note = [n for n in refined["notes"] if n.startswith("refined")]
        found = re.search(r"in (\d+) iterations, ([0-9.e+-]+) s", note[0]) if note else None
        iterations = found.group(1) if found else "-"
        refining = float(found.group(2)) if found else 0.0
        time_ratio = refined["seconds_total"] / (refined["seconds_total"] - refining)
        ratio = r["l2_stretch"] / best
        same_boundary = not (boundary == "square" and any(k in mesh for k in BENT_SIDES))
        if same_boundary:
            counted.append(ratio)
        print(f"| {mesh} | {boundary} | {u['l2_stretch']:.4f} | {r['l2_stretch']:.4f} | {best:.4f} | {ratio:.4f}"
              f"{'' if same_boundary else ' (other boundary)'} | {u['linf_stretch']:.2f} | {r['linf_stretch']:.2f} | "
              f"{plain['seconds_total']:.3f} | {refined['seconds_total']:.3f} | "
              f"{time_ratio:.1f} | {iterations} | {r['flipped'] + r['degenerate']} |",
              flush=True)
    print(f"\nrefined / optimum over {len(counted)} rows: median {statistics.median(counted):.4f}, "
          f"worst {max(counted):.4f}")


if __name__ == "__main__":
    main()
