#!/usr/bin/env python3
"""End-to-end tests of the "Low-stretch parameterization" filter through the real meshlabserver
2020.09 (under xvfb-run), with the plugin in a private prefix (as MeshLab 2020.09 loads plugins only from beside its binary).

  e2e.py prefix  --prefix P --plugin libfilter_lowstretch.so
  e2e.py disk    --prefix P --resources DIR --work DIR --boundary B (--mesh FILE | --generate NAME) [--tool=EXE]
  e2e.py bad     --prefix P --resources DIR --work DIR --runner EXE --plugin SO (--mesh FILE | --generate NAME)
                 [--set NAME=VALUE --expect WORDS] [--tool=EXE]
  e2e.py deleted --prefix P --resources DIR --work DIR [--tool=EXE]

disk: the saved PLY has per-wedge texcoords in [0,1]^2 equal to the per-vertex ones, no flipped or
zero-area triangle for Square and Circle, per-vertex and per-face quality equal to the stretch
recomputed here from the saved positions and texcoords (filter_lowstretch/core/METHOD.md section 2) and, with
--tool, to the quality the `lowstretch` tool writes for the same mesh; the log holds every pass's
metrics and the kept pass, which has the lowest L2 stretch and matches the recomputed one.
bad (a bad mesh, or an invalid parameter value given with --set): meshlabserver prints the
filter's message and fails without writing the output; the runner
(which, unlike meshlabserver, saves after a failing filter) shows the mesh and its data masks
unchanged. deleted: a mesh whose vertices and faces have been deleted (not compacted) by earlier
filters in the same script gives exactly the result of the same mesh without them.
Each check prints what it compared; the exit code is 1 when any check failed.
"""
import argparse
import json
import math
import os
import re
import shutil
import struct
import subprocess
import sys
import xml.etree.ElementTree as ET

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
import generate  # noqa: E402
import meshio  # noqa: E402
from stretch_formula import edges_and_area, face_sigma  # noqa: E402

FILTER = "Low-stretch parameterization"
MLX = {"square": "lowstretch.mlx", "circle": "lowstretch_circle.mlx", "natural": "lowstretch_natural.mlx"}
SYSTEM_LIB = "/usr/lib/x86_64-linux-gnu/meshlab"
LIB_IN_PREFIX = "lib/x86_64-linux-gnu/meshlab"
NUM = r"([-+0-9.eEinfa]+)"
PASS_RE = re.compile(rf"pass (\d+): L2 stretch {NUM}, Linf stretch {NUM}, edge distortion {NUM}, "
                     rf"angle distortion {NUM}, area distortion {NUM}, flipped (\d+), degenerate (\d+), {NUM} s, (multigrid, \d+ iterations|direct[^\n]*)")
KEPT_RE = re.compile(rf"kept pass (\d+) \(L2 stretch {NUM}\); stop reason: (.+?); total {NUM} s")
HEADER_RE = re.compile(rf"{FILTER}: (\d+) vertices, (\d+) faces;")
FAIL_RE = re.compile(rf"{FILTER} failed: (.*)")
CHARTS_RE = re.compile(rf"(\d+) charts \(largest chart L2 stretch {NUM}\), seam length {NUM}, coverage {NUM}, "
                       rf"efficiency {NUM} \(coverage / L2\^2\); whole layout: L2 stretch {NUM}, "
                       rf"Linf stretch {NUM}, edge distortion {NUM}, angle distortion {NUM}, area distortion {NUM}, "
                       rf"flipped (\d+), degenerate (\d+)")
STORED_RE = re.compile(rf"texture coordinates as stored \(float\): L2 stretch {NUM}, Linf stretch {NUM}, "
                       rf"flipped (\d+), degenerate (\d+), coverage {NUM}; (\d+) UV triangles smaller than a texel")
LOADED_RE = re.compile(r"loaded has (\d+) vn (\d+) fn")
# What README.md of ../shared/meshes says is wrong with each bad mesh, as words of the message.
EXPECTED = {
    "bad_closed_fandisk_6475v.off": "closed",
    "bad_closed_maxplanck_5272v.obj": "closed",
    "bad_components3_blobby_3cc_1820v.off": "3 connected components",
    "bad_holes7_holes_4291v.off": "7 boundary loops",
    "bad_quads_halftunnel_831v.off": "3 boundary loops",
    "bad_genus1_oneloop_punctured_torus_4599v.obj": "genus 1",
    "bad_orientation_oblong_shuffled_424v.off": "orient",
    "bad_nonmanifold_holes_non_manif_hole_432v.ply": "non-manifold",
    "bad_nonmanifold_polygon_mesh_16344v.off": "non-manifold",
    "holes3_head_1487v.off": "3 boundary loops",
    "holes5_lion_7529v.off": "5 boundary loops",
    "two_components": "2 connected components",
    "tetrahedron": "closed",
    "octahedron": "closed",
    "three_holes": "3 boundary loops",
    "point_cloud": "no faces",
    "unwelded": "not welded",
}
GUTTER = 2 / 1024  # the default gutter (texels) over the default texture size: where UV stays
TOOL_WEIGHTS = "floater"  # the .mlx scripts use the default initial weights


class Checks:
    """Collects failed checks instead of stopping at the first one."""

    def __init__(self):
        self.failed = []

    def __call__(self, ok, what):
        print(("ok:     " if ok else "FAILED: ") + what)
        if not ok:
            self.failed.append(what)
        return ok


def core_message(message):
    """The core's message without the adapter's own hint (the filter names its parameter, the
    tool its option, after the core's words): what the filter and the tool share."""
    return message.split(" (set \"Non-disk input\"")[0]


def rel_diff(a, b):
    if a == b:  # also inf == inf
        return 0.0
    if math.isinf(a) or math.isinf(b) or math.isnan(a) or math.isnan(b):
        return math.inf
    return abs(a - b) / max(abs(a), abs(b), 1e-30)


# ---------------------------------------------------------------------------------------------
# Running meshlabserver and the other programs

def make_prefix(prefix, plugin):
    """<prefix>/bin/meshlabserver and meshlab are copies (a symlink would resolve to /usr/bin and
    load the system plugins); the library and every system plugin are symlinks, plus ours."""
    shutil.rmtree(prefix, ignore_errors=True)
    plugins = os.path.join(prefix, LIB_IN_PREFIX, "plugins")
    os.makedirs(plugins)
    os.makedirs(os.path.join(prefix, "bin"))
    for program in ("meshlabserver", "meshlab"):
        shutil.copy2(os.path.join("/usr/bin", program), os.path.join(prefix, "bin", program))
    os.symlink(os.path.join(SYSTEM_LIB, "libmeshlab-common.so"),
               os.path.join(prefix, LIB_IN_PREFIX, "libmeshlab-common.so"))
    ours = "libfilter_lowstretch.so"
    for name in sorted(os.listdir(os.path.join(SYSTEM_LIB, "plugins"))):
        if name.endswith(".so") and name != ours:  # an installed copy of ours is not the one under test
            os.symlink(os.path.join(SYSTEM_LIB, "plugins", name), os.path.join(plugins, name))
    os.symlink(os.path.abspath(plugin), os.path.join(plugins, ours))
    print(f"prefix {prefix}: {len(os.listdir(plugins))} plugins")


def meshlabserver(prefix, work, log_name, args, timeout=900):
    """Runs meshlabserver under xvfb-run -a in `work`; keeps stdout and stderr in work/log_name.
    xvfb-run -a can lose a race for a display number when tests run in parallel: retry then."""
    command = ["xvfb-run", "-a", "-s", "-screen 0 800x600x24", os.path.join(prefix, "bin", "meshlabserver")] + args
    for _ in range(3):
        proc = subprocess.run(command, cwd=work, capture_output=True, text=True, errors="replace", timeout=timeout)
        if "Xvfb failed to start" not in proc.stderr and "server already running" not in proc.stderr:
            break
    with open(os.path.join(work, log_name), "w") as f:
        f.write("$ " + " ".join(command) + f"\nexit code {proc.returncode}\n--- stdout ---\n{proc.stdout}"
                f"\n--- stderr ---\n{proc.stderr}")
    print(f"meshlabserver {' '.join(args)}: exit code {proc.returncode}, log in {os.path.join(work, log_name)}")
    return proc


def run_tool(tool, work, input_path, output_path, boundary, disk_only=None):
    """The tool with the options of the boundary's script: the circle and natural scripts are
    disk only (Non-disk input: Reject), lowstretch.mlx makes charts of a non-disk (the default)."""
    if disk_only is None:
        disk_only = boundary != "square"
    command = [tool, input_path, "-o", output_path, "--boundary", boundary, "--weights", TOOL_WEIGHTS,
               "--exponent", "1", "--max-passes", "10", "--json"] + (["--non-disk", "reject"] if disk_only else [])
    proc = subprocess.run(command, cwd=work, capture_output=True, text=True, errors="replace", timeout=900)
    with open(os.path.join(work, "tool.log"), "w") as f:
        f.write("$ " + " ".join(command) + f"\nexit code {proc.returncode}\n--- stdout ---\n{proc.stdout}"
                f"\n--- stderr ---\n{proc.stderr}")
    return proc


def prepare(args, name_for_generated):
    """Fresh work dir; the input mesh (given, or generated into the work dir). An OBJ is handed to
    meshlabserver as OFF with the same vertices and faces: meshlabserver 2020.09 aborts on an
    assertion in vcglib's OBJ importer for many OBJ files (all those of ../shared/meshes)."""
    shutil.rmtree(args.work, ignore_errors=True)
    os.makedirs(args.work)
    if args.mesh and args.mesh.lower().endswith(".obj"):
        vertices, faces = meshio.read_obj(args.mesh)
        path = os.path.join(args.work, os.path.basename(args.mesh)[:-4] + ".off")
        meshio.write_off(path, vertices, faces)
        print(f"{args.mesh} converted to {path} ({len(vertices)} vertices, {len(faces)} faces)")
        return path, os.path.basename(args.mesh)
    if args.mesh:
        return os.path.abspath(args.mesh), os.path.basename(args.mesh)
    vertices, faces = name_for_generated[args.generate]()
    path = os.path.join(args.work, args.generate + ".off")
    meshio.write_off(path, vertices, faces)
    return path, args.generate


def mlx(args, boundary="square"):
    return os.path.join(os.path.abspath(args.resources), MLX[boundary])


# ---------------------------------------------------------------------------------------------
# Reading the results

def parse_log(text):
    passes = [dict(zip(("pass", "l2", "linf", "edge", "angle", "area", "flipped", "degenerate", "seconds"),
                       (int(m[1]), *map(float, m.groups()[1:6]), int(m[7]), int(m[8]), float(m[9]))))
              for m in PASS_RE.finditer(text)]
    kept = KEPT_RE.search(text)
    return passes, kept


def wedge_uv(check, ply):
    """Per-vertex (u, v) from the per-wedge texcoords, checking that each vertex has one value."""
    faces = ply.faces()
    texcoords = ply.elements["face"].data["texcoord"]
    uv = [None] * len(ply.elements["vertex"].data["x"])
    disagree = 0
    for face, tc in zip(faces, texcoords):
        for k, vi in enumerate(face):
            value = (tc[2 * k], tc[2 * k + 1])
            if uv[vi] is None:
                uv[vi] = value
            elif uv[vi] != value:
                disagree += 1
    check(disagree == 0, f"every vertex has one texcoord on all its wedges ({disagree} wedges disagree)")
    return uv


HALF_ULP = 2.0 ** -25  # largest rounding error of a texcoord in [0, 1] stored as a float
STEP = 1e-9            # finite-difference step for the sensitivity to that rounding


class Stretch:
    """The stretch of a saved parameterization (filter_lowstretch/core/METHOD.md section 2), recomputed from the
    PLY's float positions and texcoords, with a bound on how far the float rounding of the
    texcoords can move each value (the filter computed them from the unrounded doubles).
    Normalized by sqrt(sum |A_U| / sum A) as the core does. Vertices next to a flipped or
    zero-area parameter triangle are left out (`skipped`): the core gives them a finite
    reweighting value of its own, and the comparison with the tool covers them."""

    def __init__(self, vertices, faces, uv):
        face_raw, face_err, face_area = [], [], []
        total_a = total_au = total_au_err = 0.0
        for i, j, k in faces:
            e1, e2, area = edges_and_area(vertices[i], vertices[j], vertices[k])
            tc = (*uv[i], *uv[j], *uv[k])
            sigma, area_u = face_sigma(e1, e2, tc)
            err = 0.0
            if math.isfinite(sigma):  # sum over the 6 texcoords of |d sigma / d texcoord| * HALF_ULP
                for n in range(6):
                    moved = list(tc)
                    moved[n] += STEP
                    err += abs(face_sigma(e1, e2, moved)[0] - sigma) / STEP * HALF_ULP
            face_raw.append(sigma)
            face_err.append(err)
            face_area.append(area)
            total_a += area
            total_au += abs(area_u)
            s1, t1, s2, t2, s3, t3 = tc
            total_au_err += 0.5 * HALF_ULP * (abs(t2 - t3) + abs(t3 - t1) + abs(t1 - t2) +
                                              abs(s3 - s2) + abs(s1 - s3) + abs(s2 - s1))
        scale = math.sqrt(total_au / total_a)
        self.scale_rel_err = 0.5 * total_au_err / total_au
        self.face = [scale * s for s in face_raw]
        self.face_err = [scale * e for e in face_err]

        num, den, err = [0.0] * len(vertices), [0.0] * len(vertices), [0.0] * len(vertices)
        bad, used = [False] * len(vertices), [False] * len(vertices)
        for face, sigma, e, area in zip(faces, face_raw, face_err, face_area):
            for vi in face:
                used[vi] = True
                if not math.isfinite(sigma):
                    bad[vi] = True
                    continue
                num[vi] += area * sigma * sigma
                den[vi] += area
                err[vi] += area * sigma * e
        self.vertex, self.vertex_err, self.skipped = [], [], 0
        for n, d, e, b, u in zip(num, den, err, bad, used):
            if b or d == 0 or n == 0:
                self.vertex.append(None)  # flipped neighbourhood, zero 3D area, or unused vertex
                self.vertex_err.append(0.0)
                self.skipped += u
            else:
                self.vertex.append(scale * math.sqrt(n / d))
                self.vertex_err.append(scale * e / (d * math.sqrt(n / d)))
        per_face = list(zip(face_area, face_raw, face_err))
        if all(math.isfinite(s) for _, s, _ in per_face):
            l2 = math.sqrt(sum(a * s * s for a, s, _ in per_face) / total_a)
            self.total = scale * l2
            self.total_err = scale * sum(a * s * e for a, s, e in per_face) / (total_a * l2)
        else:
            self.total, self.total_err = math.inf, 0.0

    @staticmethod
    def agrees(saved, value, err, scale_rel_err):
        """saved (a float from the PLY or %.6g from the log) equals value up to its rounding error."""
        if value is None:
            return True
        if math.isinf(value) or math.isinf(saved):
            return saved == value
        return abs(saved - value) <= 2 * err + (1e-5 + 2 * scale_rel_err) * abs(value)


def worst(pairs):
    """Largest relative difference over (a, b) pairs, and its index."""
    best = (0.0, -1)
    for index, (a, b) in enumerate(pairs):
        d = rel_diff(a, b)
        if d > best[0]:
            best = (d, index)
    return best


# ---------------------------------------------------------------------------------------------
# The tests

def check_result(check, args, input_name, boundary, proc, out_ply):
    """Everything a successful run must show, on meshlabserver's output and log."""
    log = proc.stdout
    if not check(proc.returncode == 0 and os.path.isfile(out_ply),
                 f"meshlabserver succeeds on {input_name} ({boundary}) and writes {os.path.basename(out_ply)}"):
        failure = FAIL_RE.search(log)
        print("  filter message: " + (failure.group(1) if failure else "(none)"))
        return None
    ply = meshio.read_ply(out_ply)
    vertices, faces = ply.vertices(), ply.faces()
    face_el, vert_el = ply.elements["face"], ply.elements["vertex"]

    loaded = LOADED_RE.search(log)
    header = HEADER_RE.search(log)
    check(loaded is not None and header is not None and header.groups() == loaded.groups()
          and (len(vertices), len(faces)) == tuple(map(int, loaded.groups())),
          f"log and PLY agree on the size: loaded {loaded and loaded.groups()}, filter saw "
          f"{header and header.groups()}, saved {len(vertices)} vertices {len(faces)} faces")

    # Texture coordinates.
    if not check(face_el.has("texcoord") and all(len(tc) == 6 for tc in face_el.data["texcoord"]),
                 "the PLY has per-wedge texcoords (3 (u,v) pairs per face)"):
        return None
    uv = wedge_uv(check, ply)
    values = [x for tc in face_el.data["texcoord"] for x in tc]
    check(all(math.isfinite(x) and GUTTER - 1e-6 <= x <= 1 - GUTTER + 1e-6 for x in values),
          f"texcoords are 2 texels of 1024 inside [0,1]: range [{min(values):.6g}, {max(values):.6g}]")
    if vert_el.has("texture_u"):
        per_vertex = list(zip(vert_el.data["texture_u"], vert_el.data["texture_v"]))
        check(all(uv[i] is None or uv[i] == per_vertex[i] for i in range(len(uv))),
              "per-vertex texcoords equal the per-wedge ones")
    else:
        check(False, "the PLY has per-vertex texcoords (texture_u, texture_v)")
    textures = ply.texture_files()
    check(len(textures) == 1 and textures[0].endswith("checkerboard.png") and os.path.isfile(textures[0]),
          f"the checkerboard texture is attached and exists: {textures}")

    # Orientation: count parameter triangles that are not strictly counter-clockwise.
    uv_or_zero = [p if p is not None else (0.0, 0.0) for p in uv]
    areas = [0.5 * ((uv_or_zero[j][0] - uv_or_zero[i][0]) * (uv_or_zero[k][1] - uv_or_zero[i][1]) -
                    (uv_or_zero[k][0] - uv_or_zero[i][0]) * (uv_or_zero[j][1] - uv_or_zero[i][1]))
             for i, j, k in faces]
    flipped = sum(1 for a in areas if a < 0)
    zero = sum(1 for a in areas if a == 0)
    if boundary in ("square", "circle"):
        check(flipped == 0 and zero == 0, f"no flipped and no zero-area triangle in the saved texcoords "
              f"({flipped} flipped, {zero} zero-area)")
    else:
        print(f"info:   {flipped} flipped and {zero} zero-area triangles (natural boundary: reported, not required)")

    # Quality = stretch, recomputed here from the saved positions and texcoords.
    recomputed = Stretch(vertices, faces, uv_or_zero)
    if check(vert_el.has("quality") and face_el.has("quality"), "the PLY has per-vertex and per-face quality"):
        for what, saved, values, errs in (("vertex", vert_el.data["quality"], recomputed.vertex, recomputed.vertex_err),
                                          ("face", face_el.data["quality"], recomputed.face, recomputed.face_err)):
            wrong = [i for i, (q, v, e) in enumerate(zip(saved, values, errs))
                     if not Stretch.agrees(q, v, e, recomputed.scale_rel_err)]
            d, i = worst((q, v) for q, v in zip(saved, values) if v is not None)
            check(not wrong, f"per-{what} quality = recomputed {what} stretch within the float rounding of the "
                  f"texcoords: {len(wrong)} disagree" + (f" (first: {what} {wrong[0]}, saved {saved[wrong[0]]}, "
                  f"recomputed {values[wrong[0]]} +- {2 * errs[wrong[0]]:.2g})" if wrong else "") +
                  f"; largest relative difference {d:.1e}")
        if recomputed.skipped:
            print(f"info:   {recomputed.skipped} vertices next to a flipped or zero-area triangle not recomputed")

    # The log: one line per pass, the kept pass is the best and is what was saved.
    passes, kept = parse_log(log)
    check(len(passes) >= 1 and [p["pass"] for p in passes] == list(range(len(passes))),
          f"the log has the metrics of passes 0..{len(passes) - 1}")
    if check(kept is not None, "the log names the kept pass and the stop reason"):
        print(f"        kept pass {kept.group(1)}, L2 stretch {kept.group(2)}, stop reason '{kept.group(3)}'")
        chosen = [p for p in passes if p["pass"] == int(kept.group(1))]
        if check(len(chosen) == 1, "the kept pass is one of the logged passes"):
            best = min(p["l2"] for p in passes)
            check(chosen[0]["l2"] == best, f"the kept pass has the lowest L2 stretch ({chosen[0]['l2']} vs {best})")
            check(Stretch.agrees(chosen[0]["l2"], recomputed.total, recomputed.total_err, recomputed.scale_rel_err),
                  f"the kept pass's logged L2 stretch {chosen[0]['l2']} = recomputed {recomputed.total:.6g} "
                  f"+- {2 * recomputed.total_err:.1g}")
            if boundary in ("square", "circle"):
                check(chosen[0]["flipped"] == 0 and chosen[0]["degenerate"] == 0,
                      "the kept pass logs no flipped or degenerate triangle")
    for p in passes:
        print(f"        pass {p['pass']}: L2 {p['l2']:.6g}  Linf {p['linf']:.6g}  edge {p['edge']:.4g}  "
              f"angle {p['angle']:.4g}  area {p['area']:.4g}  flipped {p['flipped']}  {p['seconds']:.3f} s")

    if args.tool:
        compare_with_tool(check, args, boundary, out_ply, ply, passes, kept)
    else:
        print("info:   no --tool given: quality checked against the recomputed stretch only")
    return ply


def compare_with_tool(check, args, boundary, out_ply, ply, passes, kept):
    """The tool run on the mesh MeshLab saved (same vertices and faces, same float coordinates that
    the filter saw) must give the same quality, texcoords and pass metrics."""
    tool_ply = os.path.join(args.work, "tool.ply")
    proc = run_tool(args.tool, args.work, out_ply, tool_ply, boundary)
    if not check(proc.returncode == 0 and os.path.isfile(tool_ply), f"the lowstretch tool succeeds on the same mesh "
                 f"(exit code {proc.returncode}) {proc.stderr.strip()[:200]}"):
        return
    try:
        report = json.loads(proc.stdout)
    except ValueError:
        report = None
        check(False, "the tool's --json output is one JSON object")
    tool_passes = report.get("passes", []) if report else []
    keys = (("l2_stretch", "l2"), ("linf_stretch", "linf"), ("edge_distortion", "edge"),
            ("angle_distortion", "angle"), ("area_distortion", "area"))
    same = len(tool_passes) == len(passes) and all(  # JSON has no infinity: the tool writes null
        all(rel_diff(math.inf if t[k] is None else t[k], p[ours]) <= 1e-5 for k, ours in keys) and
        t["flipped"] == p["flipped"] and t["degenerate"] == p["degenerate"] for t, p in zip(tool_passes, passes))
    check(same, f"the logged metrics of every pass = the tool's JSON ({len(passes)} passes vs {len(tool_passes)})")
    if kept and report:
        check(report.get("chosen_pass") == int(kept.group(1)),
              f"the kept pass = the tool's chosen_pass ({kept.group(1)} vs {report.get('chosen_pass')})")
    try:
        theirs = meshio.read_ply(tool_ply)
    except (ValueError, struct.error) as e:
        check(False, f"the tool's PLY is a valid PLY file ({e})")
        return
    ours_q, theirs_q = ply.elements["vertex"].data["quality"], theirs.elements["vertex"].data.get("quality", [])
    if check(len(ours_q) == len(theirs_q), f"the tool's PLY has a quality per vertex ({len(theirs_q)})"):
        d, i = worst(zip(ours_q, theirs_q))
        check(d <= 1e-5, f"per-vertex quality = the tool's: max relative difference {d:.2e} (vertex {i}) <= 1e-5")
    ours_tc, theirs_tc = ply.elements["face"].data["texcoord"], theirs.elements["face"].data.get("texcoord", [])
    if check(len(ours_tc) == len(theirs_tc), f"the tool's PLY has per-wedge texcoords ({len(theirs_tc)} faces)"):
        diff = max((abs(a - b) for x, y in zip(ours_tc, theirs_tc) for a, b in zip(x, y)), default=0.0)
        check(diff <= 1e-6, f"per-wedge texcoords = the tool's: max difference {diff:.2e} <= 1e-6")


def cmd_disk(args):
    check = Checks()
    input_path, name = prepare(args, generate.DISKS)
    out = os.path.join(args.work, "out.ply")
    proc = meshlabserver(args.prefix, args.work, "meshlabserver.log",
                         ["-i", input_path, "-o", out, "-m", "vt", "wt", "vq", "fq", "-s", mlx(args, args.boundary)])
    check_result(check, args, name, args.boundary, proc, out)
    return check


def signed_area(a, b, c):
    return 0.5 * ((b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1]))


def overlapping_pixels(triangles, n=1024):
    """Pixel centres of an n x n raster strictly inside two triangles of the layout."""
    owner = {}
    overlaps = 0
    for a, b, c in triangles:
        a, b, c = [(p[0] * n, p[1] * n) for p in (a, b, c)]
        area = signed_area(a, b, c)
        if area <= 0:
            continue
        eps = 1e-9 * area
        for y in range(max(0, math.floor(min(a[1], b[1], c[1]))), min(n - 1, math.ceil(max(a[1], b[1], c[1]))) + 1):
            for x in range(max(0, math.floor(min(a[0], b[0], c[0]))), min(n - 1, math.ceil(max(a[0], b[0], c[0]))) + 1):
                p = (x + 0.5, y + 0.5)
                if signed_area(a, b, p) > eps and signed_area(b, c, p) > eps and signed_area(c, a, p) > eps:
                    overlaps += (x, y) in owner
                    owner[(x, y)] = True
    return overlaps


def cmd_charts(args):
    """A mesh that is not a disk, with "Non-disk input: Make charts" (the default): per-wedge texcoords in
    [0,1]^2 on every face, no flipped or zero-area triangle, no overlap; the same charts, seams and
    stretch as the lowstretch tool on the same (float) input."""
    check = Checks()
    input_path, name = prepare(args, generate.NON_DISKS)
    mask = ["-m", "wt", "vq", "fq"]
    reference = os.path.join(args.work, "reference.ply")
    proc = meshlabserver(args.prefix, args.work, "reference.log", ["-i", input_path, "-o", reference] + mask)
    if not check(proc.returncode == 0 and os.path.isfile(reference), f"meshlabserver loads {name} and saves it"):
        return check
    out = os.path.join(args.work, "out.ply")
    proc = meshlabserver(args.prefix, args.work, "meshlabserver.log",
                         ["-i", reference, "-o", out] + mask + ["-s", os.path.join(args.resources, "lowstretch.mlx")])
    if not check(proc.returncode == 0 and os.path.isfile(out), f"meshlabserver applies the filter (exit code {proc.returncode})"):
        return check
    summary = CHARTS_RE.search(proc.stdout)
    if not check(summary is not None, "the log has the charts summary line"):
        return check
    charts, seam, l2 = int(summary.group(1)), float(summary.group(3)), float(summary.group(6))
    coverage, efficiency = float(summary.group(4)), float(summary.group(5))
    print(f"{name}: {charts} charts, seam length {seam}, L2 stretch {l2}, coverage {coverage}, efficiency {efficiency}")
    check(int(summary.group(11)) == 0 and int(summary.group(12)) == 0, "the log reports no flipped and no degenerate triangle")
    check(rel_diff(efficiency, coverage / l2 ** 2) < 1e-3, f"efficiency is coverage / L2^2 ({coverage / l2 ** 2:.6g})")

    ply, ref = meshio.read_ply(out), meshio.read_ply(reference)
    check(ply.faces() == ref.faces(), f"the faces are the input's ({len(ref.faces())})")
    texcoords = ply.elements["face"].data.get("texcoord")
    if not check(texcoords is not None and len(texcoords) == len(ply.faces()), "every face has wedge texcoords"):
        return check
    check(all(len(tc) == 6 and all(GUTTER - 1e-6 <= t <= 1 - GUTTER + 1e-6 for t in tc) for tc in texcoords),
          "all wedge texcoords are 2 texels of 1024 inside [0,1]^2")
    triangles = [((tc[0], tc[1]), (tc[2], tc[3]), (tc[4], tc[5])) for tc in texcoords]
    bad = sum(1 for t in triangles if not signed_area(*t) > 0)
    check(bad == 0, f"no flipped or zero-area triangle in any chart ({bad})")
    overlaps = overlapping_pixels(triangles)
    check(overlaps == 0, f"no two triangles overlap (pixel centres of a 1024 raster covered twice: {overlaps})")

    if args.tool:
        command = [args.tool, reference, "--non-disk", "charts", "--json"]
        tool = subprocess.run(command, cwd=args.work, capture_output=True, text=True, errors="replace", timeout=900)
        if check(tool.returncode == 0, f"the lowstretch tool makes charts too (exit code {tool.returncode})"):
            result = json.loads(tool.stdout)
            check(result["chart_count"] == charts and rel_diff(result["seam_length"], seam) < 1e-5
                  and rel_diff(result["layout"]["l2_stretch"], l2) < 1e-5,
                  f"the tool agrees: {result['chart_count']} charts, seam length {result['seam_length']}, "
                  f"L2 stretch {result['layout']['l2_stretch']}")
    return check


def script_with(args, settings, path):
    """resources/lowstretch.mlx with some parameters changed (name=value), written to path."""
    script = ET.parse(mlx(args))
    for setting in settings:
        key, value = setting.split("=", 1)
        params = [p for p in script.getroot().iter("Param") if p.get("name") == key]
        if len(params) != 1:
            raise ValueError(f"{mlx(args)} has no parameter {key}")
        params[0].set("value", value)
    script.write(path)
    return path


def cmd_bad(args):
    """Bad input (a bad mesh, or a good one with --set of an invalid parameter value), in disk-only
    mode (Non-disk input: Reject) unless --set says otherwise."""
    check = Checks()
    input_path, name = prepare(args, {**generate.BAD, **generate.DISKS})
    if not any(s.startswith("nonDisk=") for s in args.set):
        args.set = ["nonDisk=0"] + args.set
    script = script_with(args, args.set, os.path.join(args.work, "script.mlx"))
    mask = ["-m", "vt", "wt", "vq", "fq"]
    reference = os.path.join(args.work, "reference.ply")
    proc = meshlabserver(args.prefix, args.work, "reference.log", ["-i", input_path, "-o", reference] + mask)
    if not check(proc.returncode == 0 and os.path.isfile(reference),
                 f"meshlabserver loads {name} and saves it without the filter"):
        return check

    out = os.path.join(args.work, "out.ply")
    proc = meshlabserver(args.prefix, args.work, "meshlabserver.log",
                         ["-i", input_path, "-o", out] + mask + ["-s", script])
    failure = FAIL_RE.search(proc.stdout)
    message = failure.group(1).strip() if failure else ""
    check(proc.returncode != 0 and f"Problem with filter: {FILTER}" in proc.stdout,
          f"meshlabserver reports that the filter failed (exit code {proc.returncode})")
    check(bool(message) and not message.startswith("internal error"), f"the log holds the filter's message: '{message}'")
    check(not os.path.exists(out), "no output mesh is written")
    expected = args.expect or EXPECTED.get(name)
    if expected:
        check(expected in message, f"the message names the problem ('{expected}')")

    if args.tool and args.set == ["nonDisk=0"]:
        tool_out = os.path.join(args.work, "tool.ply")
        tool = run_tool(args.tool, args.work, reference, tool_out, "square", disk_only=True)
        check(tool.returncode != 0 and message and core_message(message) in tool.stderr and not os.path.exists(tool_out),
              f"the lowstretch tool rejects the same mesh with the same message (exit code {tool.returncode}: "
              f"{tool.stderr.strip()[:300]})")

    # The mesh is left as it was: saved before and after the failing filter by the runner.
    before, after = os.path.join(args.work, "runner_before.ply"), os.path.join(args.work, "runner_after.ply")
    runner = subprocess.run([args.runner, args.plugin, reference, before, after] + args.set, cwd=args.work,
                            capture_output=True, text=True, errors="replace", timeout=900,
                            env=dict(os.environ, QT_QPA_PLATFORM="offscreen"))
    with open(os.path.join(args.work, "runner.log"), "w") as f:
        f.write(f"exit code {runner.returncode}\n--- stdout ---\n{runner.stdout}\n--- stderr ---\n{runner.stderr}")
    lines = dict(line.split(": ", 1) for line in runner.stdout.splitlines() if ": " in line)
    if not check(runner.returncode == 0 and lines.get("result") == "failed",
                 f"the runner applies the filter and it fails (exit code {runner.returncode}, result "
                 f"{lines.get('result')})"):
        return check
    check(lines.get("errorMessage") == message, f"errorMessage (shown by the GUI) is the logged message: "
          f"'{lines.get('errorMessage')}'")
    check(lines.get("dataMask before") == lines.get("dataMask after"),
          f"the data masks are unchanged ({lines.get('dataMask before')} -> {lines.get('dataMask after')})")
    with open(before, "rb") as f1, open(after, "rb") as f2:
        check(f1.read() == f2.read(), "the mesh saved after the failing filter is byte-identical to the one before")
    saved, ref = meshio.read_ply(after), meshio.read_ply(reference)
    check(saved.vertices() == ref.vertices() and saved.faces() == ref.faces(),
          f"it has the input's vertices and faces ({len(ref.vertices())} and {len(ref.faces())})")
    check(not saved.elements["face"].has("texcoord") and not saved.elements["vertex"].has("texture_u")
          and not saved.texture_files(), "it has no texcoords and no texture")
    return check


def cmd_deleted(args):
    """The filter after 'Select by Vertex Quality' + 'Delete Selected Faces and Vertices' in the same
    meshlabserver script (deleted elements stay in the vectors, interleaved with live ones) must
    give exactly what it gives on the mesh without the deleted part."""
    check = Checks()
    shutil.rmtree(args.work, ignore_errors=True)
    os.makedirs(args.work)
    n = 16
    vertices, faces, quality = generate.disk_with_flap(n)
    with_flap = os.path.join(args.work, "with_flap.ply")
    meshio.write_ply(with_flap, vertices, faces, quality)
    grid_v, grid_f = generate.wavy_grid(n)
    plain = os.path.join(args.work, "plain.ply")
    meshio.write_ply(plain, grid_v, grid_f, [0.0] * len(grid_v))

    script = ET.Element("FilterScript")
    select = ET.SubElement(script, "filter", name="Select by Vertex Quality")
    ET.SubElement(select, "Param", name="minQ", type="RichDynamicFloat", value="0.5", min="0", max="1")
    ET.SubElement(select, "Param", name="maxQ", type="RichDynamicFloat", value="1", min="0", max="1")
    ET.SubElement(select, "Param", name="Inclusive", type="RichBool", value="true")
    ET.SubElement(script, "filter", name="Delete Selected Faces and Vertices")
    script.append(ET.parse(mlx(args)).getroot().find("filter"))
    reference, proc, out_flap = square_and_script(check, args, plain, with_flap, script)
    deleted = sum(1 for q in quality if q > 0)
    check(f"Deleted 10 faces, {deleted} vertices." in proc.stdout,
          "the script deleted the flap's 10 faces and 12 vertices before the filter ran")
    header = HEADER_RE.search(proc.stdout)
    check(header is not None and header.groups() == (str(len(grid_v)), str(len(grid_f))),
          f"the filter saw only the live elements: {header and header.groups()}")
    if not check(proc.returncode == 0 and os.path.isfile(out_flap), "the filter succeeds after the deletion"):
        return check
    if reference is None:
        return check
    result = meshio.read_ply(out_flap)
    check(result.vertices() == reference.vertices() and result.faces() == reference.faces(),
          "same vertices and faces as the mesh without the flap")
    check_same_output(check, result, reference, "as the mesh without the flap")
    return check


def square_and_script(check, args, reference_mesh, script_mesh, script):
    """meshlabserver twice: the Square script alone on reference_mesh (checked like any run), and
    `script` (a FilterScript element) on script_mesh. Returns the reference PLY (None if that
    run failed), the second run's process and its output path."""
    script_path = os.path.join(args.work, "script.mlx")
    ET.ElementTree(script).write(script_path)
    mask = ["-m", "vt", "wt", "vq", "fq"]
    out_reference = os.path.join(args.work, "reference_out.ply")
    proc = meshlabserver(args.prefix, args.work, "reference.log",
                         ["-i", reference_mesh, "-o", out_reference] + mask + ["-s", mlx(args)])
    reference = check_result(check, args, os.path.basename(reference_mesh), "square", proc, out_reference)
    out = os.path.join(args.work, "script_out.ply")
    proc = meshlabserver(args.prefix, args.work, "script.log", ["-i", script_mesh, "-o", out] + mask + ["-s", script_path])
    return reference, proc, out


def check_same_output(check, result, reference, what):
    """Texture coordinates and quality written by the filter, equal in two PLY files."""
    for element, props in (("vertex", ("texture_u", "texture_v", "quality")), ("face", ("texcoord", "quality"))):
        for prop in props:
            check(result.elements[element].data.get(prop) == reference.elements[element].data.get(prop),
                  f"same {element} {prop} {what}")


def cmd_replace(args):
    """Running the filter again replaces what the first run wrote: Circle then Square in one
    meshlabserver script gives exactly the texcoords and quality of Square alone."""
    check = Checks()
    shutil.rmtree(args.work, ignore_errors=True)
    os.makedirs(args.work)
    vertices, faces = generate.wavy_grid(12)
    mesh = os.path.join(args.work, "wavy_grid.off")
    meshio.write_off(mesh, vertices, faces)
    script = ET.Element("FilterScript")
    for boundary in ("circle", "square"):
        script.append(ET.parse(mlx(args, boundary)).getroot().find("filter"))
    reference, proc, out_twice = square_and_script(check, args, mesh, mesh, script)
    runs = set(re.findall(rf"{FILTER}: \d+ vertices, \d+ faces; boundary (\w+)", proc.stdout))
    check(runs == {"circle", "square"}, f"the script ran the filter with both boundaries: {sorted(runs)}")
    if not check(proc.returncode == 0 and os.path.isfile(out_twice), "the second run succeeds") or reference is None:
        return check
    check_same_output(check, meshio.read_ply(out_twice), reference, "after Circle then Square as after Square alone")
    return check


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("command", choices=("prefix", "disk", "bad", "deleted", "charts", "replace"))
    parser.add_argument("--prefix", required=True, help="private MeshLab prefix")
    parser.add_argument("--plugin", help="libfilter_lowstretch.so under test")
    parser.add_argument("--resources", help="the repository's resources/ folder (the .mlx scripts)")
    parser.add_argument("--work", help="work folder of this test (emptied first)")
    parser.add_argument("--mesh", help="input mesh file")
    parser.add_argument("--generate", help="name of a generated input mesh")
    parser.add_argument("--boundary", choices=sorted(MLX), default="square")
    parser.add_argument("--tool", default="", help="the lowstretch executable, to compare with (optional)")
    parser.add_argument("--runner", help="lowstretch_plugin_runner executable (bad)")
    parser.add_argument("--set", action="append", default=[], metavar="NAME=VALUE",
                        help="bad: run the filter with this parameter value (an invalid one)")
    parser.add_argument("--expect", help="bad: words the filter's message must contain")
    args = parser.parse_args()
    if args.command == "prefix":
        make_prefix(args.prefix, args.plugin)
        return 0
    if args.mesh and not os.path.isfile(args.mesh):
        print(f"FAILED: input mesh {args.mesh} does not exist")
        return 1
    check = {"disk": cmd_disk, "bad": cmd_bad, "deleted": cmd_deleted, "charts": cmd_charts,
             "replace": cmd_replace}[args.command](args)
    print(f"{len(check.failed)} check(s) failed" if check.failed else "all checks passed")
    return 1 if check.failed else 0


if __name__ == "__main__":
    sys.exit(main())
