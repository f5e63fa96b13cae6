#!/usr/bin/env python3
"""The tool's files say what its JSON says: `lowstretch MESH -o out.obj --json` and `-o out.ply`,
then the L2 and Linf stretch and the flipped and zero-area triangles recomputed from each file's
texture coordinates (and the PLY's per-face quality) against the JSON's `layout`, the metrics of
the texture coordinates as stored. They agree within 1e-6 relative (the promise is 1e-3): the core
rounds the coordinates to float before measuring, and both files keep every digit of a float.

  tool_files.py --tool lowstretch --mesh MESH --work DIR [-- EXTRA TOOL ARGUMENTS]
"""
import argparse
import json
import math
import os
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import meshio  # noqa: E402
from e2e import rel_diff  # noqa: E402
from script_checks import Checks  # noqa: E402
from stretch_formula import map_linf, map_stretch  # noqa: E402


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--tool", required=True)
    parser.add_argument("--mesh", required=True)
    parser.add_argument("--work", required=True)
    parser.add_argument("extra", nargs="*", help="more arguments for the tool (after --)")
    args = parser.parse_args()
    shutil.rmtree(args.work, ignore_errors=True)
    os.makedirs(args.work)
    check = Checks()
    for ext in ("obj", "ply"):
        out = os.path.join(args.work, "out." + ext)
        proc = subprocess.run([args.tool, args.mesh, "-o", out, "--json"] + args.extra, capture_output=True, text=True,
                              timeout=900)
        if not check(proc.returncode == 0, f"{ext}: the tool runs (exit code {proc.returncode}) {proc.stderr[-300:]}"):
            continue
        layout = json.loads(proc.stdout)["layout"]
        if ext == "obj":
            vertices, faces, corner_uv = meshio.read_obj_with_texcoords(out)
            quality = None
        else:
            ply = meshio.read_ply(out)
            vertices, faces = ply.vertices(), ply.faces()
            corner_uv = [(t[2 * k], t[2 * k + 1]) for t in ply.elements["face"].data["texcoord"] for k in range(3)]
            quality = ply.elements["face"].data.get("quality")
        area_u, sigma, l2, _ = map_stretch(vertices, faces, corner_uv)
        flipped, zero = sum(1 for a in area_u if a < 0), sum(1 for a in area_u if a == 0)
        json_l2 = math.inf if layout["l2_stretch"] is None else layout["l2_stretch"]
        check(rel_diff(l2, json_l2) <= 1e-6, f"{ext}: L2 stretch of the file {l2:.9g} = the JSON's {json_l2:.9g}")
        if layout["flipped"] + layout["degenerate"] == 0:
            linf = map_linf(vertices, faces, corner_uv)
            check(rel_diff(linf, layout["linf_stretch"]) <= 1e-6,
                  f"{ext}: Linf stretch of the file {linf:.9g} = the JSON's {layout['linf_stretch']:.9g}")
        check((flipped, zero) == (layout["flipped"], layout["degenerate"]),
              f"{ext}: flipped and zero-area triangles of the file {(flipped, zero)} = the JSON's "
              f"{(layout['flipped'], layout['degenerate'])}")
        if quality is not None:
            worst = max((rel_diff(q, s) for q, s in zip(quality, sigma) if math.isfinite(s)), default=0.0)
            check(worst <= 1e-6, f"{ext}: per-face quality = face stretch of the file (largest relative difference "
                                 f"{worst:.1e})")
    print(f"{len(check.failed)} check(s) failed" if check.failed else "all checks passed")
    return 1 if check.failed else 0


if __name__ == "__main__":
    sys.exit(main())
