#!/usr/bin/env python3
"""Scans get a valid atlas with the tool's default options. `defects`: tests/bench/make_defects.py
puts fins (non-manifold edges), zero-area slivers, duplicate vertices, dust, holes and collapsed
edges into a closed mesh; `reconstructions`: tests/bench/make_reconstructions.py makes MeshLab's
ball pivoting, VCG and screened Poisson reconstructions and marching cubes on a quantized signed
distance of it (run by --python, a Python with its packages). For each file
`lowstretch FILE -o out.obj --json` must exit 0, write every input face with texture coordinates
inside the gutter, and leave no flipped UV triangle and no zero-area one on a face with 3D area (a
face of zero 3D area may have zero UV area, never a negative one), as read back from the OBJ; the
triangle soup of `defects` is refused with the weld message.

  scan_atlas.py defects --tool lowstretch --mesh CLOSED.off --work DIR
  scan_atlas.py reconstructions --python VENV/bin/python --tool lowstretch --mesh MESH.off --work DIR
"""
import argparse
import json
import os
import shutil
import subprocess
import sys

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, here)
import meshio  # noqa: E402
from script_checks import Checks  # noqa: E402

GUTTER = 2 / 1024  # the default gutter over the default texture size
ZERO_AREA = 1e-12  # of the layout's square, as tests/bench/atlas_table.py counts zero-area triangles
DEFECTS = ["fins", "slivers", "duplicates", "dust", "collapsed", "dropouts", "holes200", "all"]
RECONSTRUCTIONS = ["ball_pivoting", "vcg", "poisson", "sdf_mc"]


def area3(p, q, r):
    u = [q[k] - p[k] for k in range(3)]
    v = [r[k] - p[k] for k in range(3)]
    c = (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])
    return 0.5 * (c[0] ** 2 + c[1] ** 2 + c[2] ** 2) ** 0.5


def area_uv(a, b, c):
    return 0.5 * ((b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1]))


def check_atlas(check, tool, path, work):
    name = os.path.basename(path)
    out = os.path.join(work, name[:-4] + ".obj")
    proc = subprocess.run([tool, path, "-o", out, "--json"], capture_output=True, text=True, timeout=900)
    if not check(proc.returncode == 0, f"{name}: exit 0 ({proc.returncode}: {proc.stderr.strip()[:200]})"):
        return
    layout = json.loads(proc.stdout)["layout"]
    check(layout["flipped"] == 0 and layout["degenerate"] == 0, f"{name}: the JSON counts no flipped or zero-area triangle")
    in_vertices, in_faces = meshio.read_off(path)
    _, faces, corners = meshio.read_obj_with_texcoords(out)
    corner_uv = [corners[3 * f:3 * f + 3] for f in range(len(faces))]
    check([list(f) for f in faces] == [list(f) for f in in_faces], f"{name}: every input face written, as it was "
          f"({len(faces)} of {len(in_faces)})")
    check(all(c is not None and GUTTER - 1e-7 <= t <= 1 - GUTTER + 1e-7 for c in corners for t in (c or (0, 0))),
          f"{name}: every texture coordinate inside the gutter")
    flipped = zero = flat_negative = 0
    for f, uv in zip(faces, corner_uv):
        a = area_uv(*uv)
        if area3(*(in_vertices[v] for v in f)) > 0:  # in the input's own coordinates
            flipped += a < 0
            zero += abs(a) <= ZERO_AREA
        else:
            flat_negative += a < 0
    check(flipped == 0 and zero == 0 and flat_negative == 0,
          f"{name}: no flipped UV triangle ({flipped}), no zero-area one on a face with area ({zero}), no flat face "
          f"flipped ({flat_negative})")


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("scans", choices=("defects", "reconstructions"))
    parser.add_argument("--tool", required=True)
    parser.add_argument("--mesh", required=True, help="a closed, clean OFF mesh to make the scans of")
    parser.add_argument("--work", required=True)
    parser.add_argument("--python", default=sys.executable, help="reconstructions: a Python with numpy, pymeshlab, "
                        "scikit-image")
    args = parser.parse_args()
    shutil.rmtree(args.work, ignore_errors=True)
    os.makedirs(args.work)
    check = Checks()
    script, names = {"defects": ("make_defects.py", DEFECTS), "reconstructions": ("make_reconstructions.py", RECONSTRUCTIONS)}[args.scans]
    made = subprocess.run([args.python, os.path.join(here, "..", "bench", script), args.mesh, args.work],
                          capture_output=True, text=True)
    if not check(made.returncode == 0, f"{script} writes the meshes ({made.stderr.strip()[-300:]})"):
        sys.exit(1)
    for name in names:
        check_atlas(check, args.tool, os.path.join(args.work, name + ".off"), args.work)
    if args.scans == "reconstructions":
        print(f"scan_atlas: {len(check.failed)} check(s) failed")
        sys.exit(1 if check.failed else 0)
    soup = subprocess.run([args.tool, os.path.join(args.work, "soup.off"), "-o", os.path.join(args.work, "soup.obj")],
                          capture_output=True, text=True, timeout=900)
    check(soup.returncode == 3 and "not welded" in soup.stderr and not os.path.exists(os.path.join(args.work, "soup.obj")),
          f"soup.off: refused with the weld message, nothing written ({soup.returncode}: {soup.stderr.strip()[:120]})")
    print(f"scan_atlas: {len(check.failed)} check(s) failed")
    sys.exit(1 if check.failed else 0)


if __name__ == "__main__":
    main()
