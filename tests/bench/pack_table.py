#!/usr/bin/env python3
"""The pack stage alone against xatlas's packers, on the same charts: our atlas's charts and
xatlas's, each laid out by our tool and by xatlas's default and brute-force packers, at one gutter.

usage: pack_table.py --tool build/lowstretch [--gutter G] [--markdown] MESH...

For each mesh two sets of charts: ours (`lowstretch MESH --atlas`) and xatlas's (its
charts and default packer, PackOptions padding G, resolution 1024). Each set is laid out
- by ours: our atlas as the tool made it; xatlas's charts packed again by `lowstretch OBJ
  --repack --gutter G` (its charts read from the texture coordinates; `*` where the tool kept
  xatlas's layout, scaled, because it used the texture better than packing it again);
- by xatlas and xatlas brute force: the charts given to Atlas.add_uv_mesh as their UV islands
  (each kept at its scale, turned as xatlas turns charts), padding G, resolution 1024.
Count and L2: the set's charts as given. Coverage, efficiency (coverage / L2^2) and overlap as
atlas_table.py measures them (atlas_metrics: coverage of the layout's bounding square, so xatlas's
atlas, which can come out a little larger than 1024, is measured on its own size). xatlas's
packers keep every chart; ours charts again those that overlap themselves or have no UV area.
Seconds: ours the whole process, xatlas the packing call. Runs under atlas_table.py's venv.
"""
import argparse
import os
import re
import subprocess
import sys
import tempfile
import time

sys.dont_write_bytecode = True  # importing atlas_table leaves no __pycache__ in the repository
import atlas_table  # noqa: E402
from atlas_table import atlas_metrics, ensure_venv, read_mesh  # noqa: E402

RESOLUTION = 1024


def write_obj(path, V, F, corner_uv):
    """V and F with one texture coordinate per face corner."""
    with open(path, "w") as out:
        out.writelines(f"v {x:.9g} {y:.9g} {z:.9g}\n" for x, y, z in V)
        out.writelines(f"vt {u:.9g} {v:.9g}\n" for u, v in corner_uv.reshape(-1, 2))
        out.writelines(f"f {a + 1}/{3 * i + 1} {b + 1}/{3 * i + 2} {c + 1}/{3 * i + 3}\n" for i, (a, b, c) in enumerate(F))


def xatlas_charts(V, F, gutter):
    """xatlas's atlas of the mesh (default packer): faces and corner UV, scaled uniformly into the
    unit square (xatlas divides u by its width and v by its height)."""
    import numpy as np
    import xatlas
    atlas = xatlas.Atlas()
    atlas.add_mesh(V, F)
    pack = xatlas.PackOptions()
    pack.padding, pack.resolution = round(gutter), RESOLUTION
    atlas.generate(pack_options=pack)
    vmapping, indices, uvs = atlas[0]
    texels = uvs * np.array([atlas.width, atlas.height])
    return vmapping[indices], texels[indices] / max(atlas.width, atlas.height)


def xatlas_packed(corner_uv, gutter, brute_force):
    """The charts of corner_uv (m x 3 x 2; faces sharing a corner position are one island) packed by
    xatlas; the new corner UV, scaled uniformly, and the seconds of the packing."""
    import numpy as np
    import xatlas
    corners, index = np.unique(corner_uv.reshape(-1, 2), axis=0, return_inverse=True)
    atlas = xatlas.Atlas()
    atlas.add_uv_mesh(corners.astype(np.float32), index.reshape(-1, 3).astype(np.uint32))
    pack = xatlas.PackOptions()
    pack.bruteForce, pack.padding, pack.resolution = brute_force, round(gutter), RESOLUTION
    start = time.perf_counter()
    atlas.generate(pack_options=pack)
    seconds = time.perf_counter() - start
    _, indices, uvs = atlas[0]  # a UV mesh keeps its faces' order
    texels = uvs * np.array([atlas.width, atlas.height])
    return texels[indices] / max(atlas.width, atlas.height), seconds


def ours_repacked(tool, V, F, corner_uv, gutter, tmp):
    """corner_uv's charts packed again by our tool: its vertices, faces and corner UV, the seconds, and
    whether it kept the layout as given."""
    given, out = os.path.join(tmp, "given.obj"), os.path.join(tmp, "repacked.obj")
    write_obj(given, V, F, corner_uv)
    start = time.perf_counter()
    proc = subprocess.run([tool, given, "-o", out, "--repack", "--gutter", str(gutter), "--json"],
                          capture_output=True, text=True)
    if proc.returncode != 0:  # its first line on stderr says why
        raise atlas_table.ToolFailed((proc.stderr.strip().splitlines() or [""])[0], failed=True)
    seconds = time.perf_counter() - start
    import numpy as np
    vertices, faces, uv = atlas_table.read_obj_with_texcoords(out)
    kept = bool(re.search("kept where they are", proc.stdout + proc.stderr))
    return np.array(vertices), np.array(faces).reshape(-1, 3), np.array(uv, float).reshape(-1, 3, 2), seconds, kept


def cells_of(V_s, F_s, uv_s, ours, gutter):
    """The cells of one set of charts: count, L2 as given, then ours / xatlas / xatlas brute force
    for coverage, efficiency, overlap and seconds."""
    V_o, F_o, uv_o, s_o, kept = ours
    layouts = [(V_o, F_o, uv_o, s_o)] + [(V_s, F_s) + xatlas_packed(uv_s, gutter, bf) for bf in (False, True)]
    metrics = [atlas_metrics(V_l, F_l, uv) for V_l, F_l, uv, _ in layouts]
    given = atlas_metrics(V_s, F_s, uv_s)
    return [str(given["charts"]), f"{given['l2']:.3f}",
            " / ".join(f"{m['coverage']:.3f}" for m in metrics) + ("*" if kept else ""),
            " / ".join(f"{m['efficiency']:.3f}" for m in metrics),
            " / ".join(str(m["overlap"]) for m in metrics),
            " / ".join(f"{layout[-1]:.2f}" for layout in layouts)]


def row_of(tool, mesh, gutter, tmp):
    """One row: the mesh, then the cells of our charts and of xatlas's."""
    import numpy as np
    V, F = read_mesh(mesh)
    V_ours, F_ours, uv_ours, seconds = atlas_table.run_ours(tool, mesh, ["--atlas", "--gutter", str(gutter)], tmp)
    row = [os.path.basename(mesh)] + cells_of(V_ours, F_ours, uv_ours, (V_ours, F_ours, uv_ours, seconds, False), gutter)
    F_x, uv_x = xatlas_charts(V, F, gutter)
    F_x = np.asarray(F_x)
    try:
        return row + cells_of(V, F_x, uv_x, ours_repacked(tool, V, F_x, uv_x, gutter, tmp), gutter)
    except atlas_table.ToolFailed as failure:
        return row + [f"ours failed: {failure}"] + ["-"] * 5


SET = ["charts", "L2", "coverage: ours / xatlas / xatlas bf", "efficiency", "overlap px", "seconds"]
COLUMNS = ["mesh"] + [f"{name} ({source})" for source in ("our charts", "xatlas's charts") for name in SET]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--tool", required=True, help="the lowstretch binary")
    parser.add_argument("--venv", default="~/.cache/filter_lowstretch/atlas-venv")
    parser.add_argument("--gutter", type=float, default=2, help="texels between charts of a 1024 texture, for all")
    parser.add_argument("--markdown", action="store_true")
    parser.add_argument("meshes", nargs="+", metavar="MESH")
    args = parser.parse_args()
    venv = os.path.expanduser(args.venv)
    if os.path.realpath(sys.prefix) != os.path.realpath(venv):  # numpy and xatlas live in the venv
        python = ensure_venv(venv, False)
        os.execv(python, [python, os.path.abspath(__file__), *sys.argv[1:]])
    if args.markdown:
        print("| " + " | ".join(COLUMNS) + " |\n|" + "---|" * len(COLUMNS), flush=True)
    for mesh in args.meshes:
        with tempfile.TemporaryDirectory() as tmp:
            row = row_of(os.path.abspath(args.tool), mesh, args.gutter, tmp)
            print(("| " + " | ".join(row) + " |") if args.markdown else "  ".join(row), flush=True)


if __name__ == "__main__":
    main()
