#!/usr/bin/env python3
"""pymeshlab 2025.7 loads the filter: a virtual environment gets pymeshlab==2025.7.post1 from PyPI,
then this script runs itself again with that environment's Python (--inside) and checks:
  - the MeshLab 2025.07 (float) build is refused by pymeshlab, whose MeshLab uses double scalars
    (this is why there is a pymeshlab build of the plugin);
  - pymeshlab.load_plugin(<pymeshlab build>) adds compute_texcoord_parametrization_low_stretch;
  - on a real disk, apply_filter returns the dict of output values (kept pass, L2/Linf stretch,
    distortions, flips, time), the mesh gets per-wedge texcoords 2 texels inside [0,1]^2 with no flipped
    triangle, the L2 stretch recomputed from those texcoords and the positions equals the returned
    one, per-face quality equals the recomputed face stretch, the Circle boundary works too, and
    refinestretch=True lowers the stretch without a flip;
  - on a mesh that is not a disk it raises PyMeshLabException with the core's message, and the mesh
    is unchanged;
  - with --readme: the README's Python snippet (the ```python block that calls
    pymeshlab.load_plugin), run as written from a folder whose build/ is this build tree.

  test_pymeshlab.py --plugin SO --float-plugin SO --disk OFF --bad OFF --expect WORDS --venv DIR --work DIR
                    [--readme README.md --build-dir DIR]
"""
import argparse
import json
import os
import re
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "e2e"))
from stretch_formula import map_stretch  # noqa: E402

PYMESHLAB = "pymeshlab==2025.7.post1"
NAME = "compute_texcoord_parametrization_low_stretch"
GUTTER = 2 / 1024  # the default gutter (texels) over the default texture size: where UV stays
KEYS = {"l2_stretch": float, "linf_stretch": float, "edge_distortion": float, "angle_distortion": float,
        "area_distortion": float, "flipped": int, "degenerate": int, "kept_pass": int, "passes": int,
        "initial_l2_stretch": float, "seconds": float, "charts": int, "seam_length": float, "coverage": float,
        "efficiency": float, "max_chart_stretch": float, "subtexel_triangles": int}


class Checks:
    def __init__(self):
        self.failed = []

    def __call__(self, ok, what):
        print(("ok:     " if ok else "FAILED: ") + what, flush=True)
        if not ok:
            self.failed.append(what)
        return ok


def venv_python(venv):
    """The environment's Python, with pymeshlab installed (pip runs only when it is missing or
    another version)."""
    python = os.path.join(venv, "bin", "python")
    if not os.path.isfile(python):
        subprocess.run([sys.executable, "-m", "venv", venv], check=True)
    have = subprocess.run([python, "-m", "pip", "show", "pymeshlab"], capture_output=True, text=True).stdout
    if "Version: 2025.7.post1" not in have:
        subprocess.run([python, "-m", "pip", "install", "-q", "--disable-pip-version-check", PYMESHLAB], check=True)
    return python


def stretch(np, V, F, wedge_uv):
    """stretch_formula.map_stretch (the Python tests' one stretch) over numpy arrays, as arrays."""
    area_u, sigma, l2, area = map_stretch(V.tolist(), F.tolist(), wedge_uv.tolist())
    return np.array(area_u), np.array(sigma), l2, np.array(area)


def inside(args):
    """Runs in the virtual environment."""
    import numpy as np
    import pymeshlab

    check = Checks()
    print(f"pymeshlab {pymeshlab.__file__}", flush=True)
    try:
        pymeshlab.load_plugin(args.float_plugin)
        check(False, "pymeshlab refuses the float (MeshLab 2025.07) build")
    except pymeshlab.PyMeshLabException as e:
        check("different floating point precision" in str(e),
              f"pymeshlab refuses the float (MeshLab 2025.07) build: '{e}'")

    pymeshlab.load_plugin(args.plugin)
    check(NAME in pymeshlab.filter_list(), f"load_plugin adds {NAME} to pymeshlab.filter_list()")

    ms = pymeshlab.MeshSet()
    ms.load_new_mesh(args.disk)
    out = ms.apply_filter(NAME)
    print(f"        {json.dumps(out)}")
    check(isinstance(out, dict) and set(out) == set(KEYS) and all(type(out[k]) is t for k, t in KEYS.items()),
          f"apply_filter returns a dict of {len(KEYS)} output values with their types")
    check(out["flipped"] == 0 and out["degenerate"] == 0, "no flipped or degenerate triangle (square)")
    check(1 <= out["l2_stretch"] < out["initial_l2_stretch"] and 0 <= out["kept_pass"] < out["passes"],
          f"L2 stretch {out['l2_stretch']:.6g} < initial {out['initial_l2_stretch']:.6g}, kept pass "
          f"{out['kept_pass']} of {out['passes']}")
    m = ms.current_mesh()
    V, F = m.vertex_matrix(), m.face_matrix()
    if check(m.has_wedge_tex_coord(), "the mesh has per-wedge texcoords"):
        wtc = m.wedge_tex_coord_matrix()
        check(wtc.shape == (3 * len(F), 2) and wtc.min() >= GUTTER - 1e-6 and wtc.max() <= 1 - GUTTER + 1e-6,
              f"wedge texcoords: shape {wtc.shape} (3 x {len(F)} faces), range [{wtc.min():.6g}, {wtc.max():.6g}]")
        area_u, face_sigma, l2, area = stretch(np, V, F, wtc.astype(np.float64))
        check(int((area_u <= 0).sum()) == 0, f"no flipped or zero-area triangle in the texcoords "
              f"({int((area_u < 0).sum())} flipped, {int((area_u == 0).sum())} zero)")
        check(abs(l2 - out["l2_stretch"]) <= 1e-9 * out["l2_stretch"],
              f"L2 stretch recomputed from the wedge texcoords {l2:.6g} = returned {out['l2_stretch']:.6g}")
        if check(m.has_face_scalar(), "the mesh has per-face quality"):
            # The quality, the dict and the texcoords all describe the stored map.
            q = m.face_scalar_array()
            rel = np.abs(q - face_sigma) / np.maximum(face_sigma, 1e-30)
            check(float(rel.max()) <= 1e-6,
                  f"per-face quality = face stretch recomputed from the texcoords (largest relative difference "
                  f"{rel.max():.1e})")
            l2_quality = float(np.sqrt((area * q ** 2).sum() / area.sum()))
            check(abs(l2_quality - out["l2_stretch"]) <= 1e-9 * out["l2_stretch"],
                  f"sqrt(sum A q^2 / sum A) over the per-face quality {l2_quality:.10g} = returned L2 stretch")
        check(m.has_vertex_scalar(), "the mesh has per-vertex quality")
        check(m.texture_number() == 1, f"one texture (the checkerboard): {m.textures() if hasattr(m, 'textures') else ''}")

    ms.load_new_mesh(args.disk)
    circle = ms.apply_filter(NAME, boundaryshape="Circle", maxpasses=3)
    check(circle["flipped"] == 0 and circle["passes"] <= 4,
          f"boundaryshape='Circle', maxpasses=3: L2 stretch {circle['l2_stretch']:.6g}, {circle['passes']} passes, "
          f"no flip")

    ms.load_new_mesh(args.disk)
    refined = ms.apply_filter(NAME, refinestretch=True)
    wtc = ms.current_mesh().wedge_tex_coord_matrix().astype(np.float64)
    area_u, _, l2, _ = stretch(np, ms.current_mesh().vertex_matrix(), ms.current_mesh().face_matrix(), wtc)
    check(refined["l2_stretch"] < 0.99 * out["l2_stretch"] and refined["flipped"] + refined["degenerate"] == 0
          and int((area_u <= 0).sum()) == 0 and abs(l2 - refined["l2_stretch"]) <= 1e-9 * l2,
          f"refinestretch=True lowers the L2 stretch from {out['l2_stretch']:.6g} to {refined['l2_stretch']:.6g} "
          f"(recomputed from the texcoords {l2:.6g}), no flip")

    ms.load_new_mesh(args.bad)
    m = ms.current_mesh()
    before = (m.vertex_matrix().copy(), m.face_matrix().copy())
    try:
        ms.apply_filter(NAME, nondisk="Reject")
        check(False, "a mesh that is not a disk raises PyMeshLabException in disk-only mode")
    except pymeshlab.PyMeshLabException as e:
        check(args.expect in str(e), f"a mesh that is not a disk raises PyMeshLabException naming the problem "
              f"('{args.expect}'): '{' / '.join(str(e).splitlines())}'")
    m = ms.current_mesh()
    check((m.vertex_matrix() == before[0]).all() and (m.face_matrix() == before[1]).all()
          and not m.has_wedge_tex_coord(), "that mesh is unchanged and has no texcoords")

    charts = ms.apply_filter(NAME)
    print(f"        default (nondisk='Make charts'): {json.dumps(charts)}")
    check(set(charts) == set(KEYS) and charts["charts"] >= 1 and charts["flipped"] == 0 and charts["degenerate"] == 0
          and 0 < charts["coverage"] <= 1, f"by default it is parameterized as charts: {charts['charts']} charts, "
          f"coverage {charts['coverage']:.4g}, no flip")
    m = ms.current_mesh()
    if check(m.has_wedge_tex_coord(), "it now has per-wedge texcoords"):
        wtc = m.wedge_tex_coord_matrix().astype(np.float64)
        area_u = stretch(np, m.vertex_matrix(), m.face_matrix(), wtc)[0]
        check(wtc.shape == (3 * len(m.face_matrix()), 2) and wtc.min() >= GUTTER - 1e-6
              and wtc.max() <= 1 - GUTTER + 1e-6 and int((area_u <= 0).sum()) == 0,
              f"wedge texcoords 2 texels of 1024 inside [0,1]^2, no flipped or zero-area triangle ({int((area_u <= 0).sum())})")

    # The atlas of the disk, cut where it stretches more than 1.1, at another texture size.
    ms.load_new_mesh(args.disk)
    atlas = ms.apply_filter(NAME, nondisk="Atlas for any mesh", maxstretch=1.1, texturesize=512, gutter=3)
    m = ms.current_mesh()
    wtc = m.wedge_tex_coord_matrix().astype(np.float64)
    area_u, _, l2, _ = stretch(np, m.vertex_matrix(), m.face_matrix(), wtc)
    check(set(atlas) == set(KEYS) and atlas["charts"] > 1 and abs(l2 - atlas["l2_stretch"]) <= 1e-9 * l2
          and abs(atlas["efficiency"] - atlas["coverage"] / l2 ** 2) <= 1e-9 * atlas["efficiency"]
          and atlas["efficiency"] > out["coverage"] / out["l2_stretch"] ** 2,
          f"nondisk='Atlas for any mesh', maxstretch=1.1: {atlas['charts']} charts, L2 stretch {atlas['l2_stretch']:.6g} "
          f"(recomputed {l2:.6g}), efficiency {atlas['efficiency']:.4g} = coverage / L2^2, above the single chart's "
          f"{out['coverage'] / out['l2_stretch'] ** 2:.4g}")
    check(wtc.min() >= 3 / 512 - 1e-6 and wtc.max() <= 1 - 3 / 512 + 1e-6 and int((area_u <= 0).sum()) == 0,
          f"the atlas stays 3 texels of 512 inside [0,1]^2 ({wtc.min():.6g}, {wtc.max():.6g}), no flipped or "
          f"zero-area triangle")
    return check


def run_readme(check, args, python):
    with open(args.readme) as f:
        blocks = re.findall(r"```python\n(.*?)```", f.read(), re.S)
    snippet = [b for b in blocks if "pymeshlab.load_plugin" in b]
    if not check(bool(snippet), f"{args.readme} has a ```python block calling pymeshlab.load_plugin"):
        return
    folder = os.path.join(args.work, "readme")
    os.makedirs(folder, exist_ok=True)
    link = os.path.join(folder, "build")
    if os.path.islink(link):
        os.remove(link)
    os.symlink(os.path.abspath(args.build_dir), link)
    with open(os.path.join(folder, "snippet.py"), "w") as f:
        f.write(snippet[0])
    proc = subprocess.run([python, "snippet.py"], cwd=folder, capture_output=True, text=True, timeout=600)
    print("        README snippet output:\n" + "".join("        | " + line + "\n" for line in proc.stdout.splitlines()))
    check(proc.returncode == 0, f"the README's Python snippet runs (exit code {proc.returncode}) {proc.stderr[-500:]}")


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--plugin", required=True, help="the pymeshlab (double) build of libfilter_lowstretch.so")
    parser.add_argument("--float-plugin", required=True, help="the MeshLab 2025.07 (float) build")
    parser.add_argument("--disk", required=True, help="a disk mesh (OFF)")
    parser.add_argument("--bad", required=True, help="a mesh that is not a disk (OFF)")
    parser.add_argument("--expect", required=True, help="words of the message for --bad")
    parser.add_argument("--venv", help="virtual environment folder (created if missing)")
    parser.add_argument("--work", help="work folder")
    parser.add_argument("--readme", help="README.md whose Python snippet is run")
    parser.add_argument("--build-dir", help="the build tree the snippet's build/ paths refer to")
    parser.add_argument("--inside", action="store_true", help=argparse.SUPPRESS)
    args = parser.parse_args()
    if args.inside:
        check = inside(args)
        return 1 if check.failed else 0

    os.makedirs(args.work, exist_ok=True)
    python = venv_python(args.venv)
    check = Checks()
    proc = subprocess.run([python, os.path.abspath(__file__), "--inside", "--plugin", args.plugin,
                           "--float-plugin", args.float_plugin, "--disk", args.disk, "--bad", args.bad, "--expect", args.expect],
                          cwd=args.work, timeout=900)
    check(proc.returncode == 0, f"the checks inside the pymeshlab environment pass (exit code {proc.returncode})")
    if args.readme and args.build_dir:
        run_readme(check, args, python)
    print(f"{len(check.failed)} check(s) failed" if check.failed else "all checks passed")
    return 1 if check.failed else 0


if __name__ == "__main__":
    sys.exit(main())
