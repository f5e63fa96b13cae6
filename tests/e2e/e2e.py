#!/usr/bin/env python3
"""Helpers of the end-to-end tests of the "Low-stretch parameterization" filter through the real
meshlabserver 2020.09 (under xvfb-run), and the tool that makes the private prefix they run in
(MeshLab 2020.09 loads plugins only from beside its binary):

  e2e.py prefix --prefix P --plugin libfilter_lowstretch.so

The tests themselves are pytest tests in test_e2e.py (disk, bad, charts, deleted, replace; see
there) and tests/meshlab2025/test_meshlab2025.py, which both use check_result below: it asserts
what a successful run must show (per-wedge texcoords in [0,1]^2 equal to the per-vertex ones, no
flipped or zero-area triangle for Square and Circle, per-vertex and per-face quality equal to the
stretch recomputed here from the saved positions and texcoords (filter_lowstretch/core/METHOD.md
section 2) and, with a tool, to the quality the `lowstretch` tool writes for the same mesh; the
log holds every pass's metrics and the kept pass, which has the lowest L2 stretch and matches the
recomputed one). bake.py uses meshlabserver below.
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

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
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
# The note of the last step (atlas/measure/valid_as_stored.h) when the stored map needed cutting.
REPAIRED_RE = re.compile(r"note: flipped or zero-area UV triangles as stored: ")
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


def wedge_uv(ply):
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
    assert disagree == 0, f"every vertex has one texcoord on all its wedges ({disagree} wedges disagree)"
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

def check_result(args, input_name, boundary, proc, out_ply):
    """Asserts everything a successful run must show, on meshlabserver's output and log; returns
    the saved PLY. args: work (folder), tool (the lowstretch executable, or "" to skip it)."""
    log = proc.stdout
    failure = FAIL_RE.search(log)
    assert proc.returncode == 0 and os.path.isfile(out_ply), (
        f"meshlabserver succeeds on {input_name} ({boundary}) and writes {os.path.basename(out_ply)} "
        f"(exit code {proc.returncode}; filter message: {failure.group(1) if failure else '(none)'})")
    ply = meshio.read_ply(out_ply)
    vertices, faces = ply.vertices(), ply.faces()
    face_el, vert_el = ply.elements["face"], ply.elements["vertex"]

    loaded = LOADED_RE.search(log)
    header = HEADER_RE.search(log)
    assert (loaded is not None and header is not None and header.groups() == loaded.groups()
            and (len(vertices), len(faces)) == tuple(map(int, loaded.groups()))), (
        f"log and PLY agree on the size: loaded {loaded and loaded.groups()}, filter saw "
        f"{header and header.groups()}, saved {len(vertices)} vertices {len(faces)} faces")

    # Texture coordinates.
    assert face_el.has("texcoord") and all(len(tc) == 6 for tc in face_el.data["texcoord"]), \
        "the PLY has per-wedge texcoords (3 (u,v) pairs per face)"
    if REPAIRED_RE.search(log):
        return check_repaired(log, ply, boundary)
    uv = wedge_uv(ply)
    values = [x for tc in face_el.data["texcoord"] for x in tc]
    assert all(math.isfinite(x) and GUTTER - 1e-6 <= x <= 1 - GUTTER + 1e-6 for x in values), \
        f"texcoords are 2 texels of 1024 inside [0,1]: range [{min(values):.6g}, {max(values):.6g}]"
    assert vert_el.has("texture_u"), "the PLY has per-vertex texcoords (texture_u, texture_v)"
    per_vertex = list(zip(vert_el.data["texture_u"], vert_el.data["texture_v"]))
    assert all(uv[i] is None or uv[i] == per_vertex[i] for i in range(len(uv))), \
        "per-vertex texcoords equal the per-wedge ones"
    textures = ply.texture_files()
    assert len(textures) == 1 and textures[0].endswith("checkerboard.png") and os.path.isfile(textures[0]), \
        f"the checkerboard texture is attached and exists: {textures}"

    # Orientation: count parameter triangles that are not strictly counter-clockwise.
    uv_or_zero = [p if p is not None else (0.0, 0.0) for p in uv]
    areas = [0.5 * ((uv_or_zero[j][0] - uv_or_zero[i][0]) * (uv_or_zero[k][1] - uv_or_zero[i][1]) -
                    (uv_or_zero[k][0] - uv_or_zero[i][0]) * (uv_or_zero[j][1] - uv_or_zero[i][1]))
             for i, j, k in faces]
    flipped = sum(1 for a in areas if a < 0)
    zero = sum(1 for a in areas if a == 0)
    if boundary in ("square", "circle"):
        assert flipped == 0 and zero == 0, (f"no flipped and no zero-area triangle in the saved texcoords "
                                            f"({flipped} flipped, {zero} zero-area)")
    else:
        print(f"info:   {flipped} flipped and {zero} zero-area triangles (natural boundary: reported, not required)")

    # Quality = stretch, recomputed here from the saved positions and texcoords.
    recomputed = Stretch(vertices, faces, uv_or_zero)
    assert vert_el.has("quality") and face_el.has("quality"), "the PLY has per-vertex and per-face quality"
    for what, saved, values, errs in (("vertex", vert_el.data["quality"], recomputed.vertex, recomputed.vertex_err),
                                      ("face", face_el.data["quality"], recomputed.face, recomputed.face_err)):
        wrong = [i for i, (q, v, e) in enumerate(zip(saved, values, errs))
                 if not Stretch.agrees(q, v, e, recomputed.scale_rel_err)]
        d, i = worst((q, v) for q, v in zip(saved, values) if v is not None)
        assert not wrong, (f"per-{what} quality = recomputed {what} stretch within the float rounding of the "
                           f"texcoords: {len(wrong)} disagree" + (f" (first: {what} {wrong[0]}, saved {saved[wrong[0]]}, "
                           f"recomputed {values[wrong[0]]} +- {2 * errs[wrong[0]]:.2g})" if wrong else "") +
                           f"; largest relative difference {d:.1e}")
    if recomputed.skipped:
        print(f"info:   {recomputed.skipped} vertices next to a flipped or zero-area triangle not recomputed")

    # The log: one line per pass, the kept pass is the best and is what was saved.
    passes, kept = parse_log(log)
    for p in passes:
        print(f"        pass {p['pass']}: L2 {p['l2']:.6g}  Linf {p['linf']:.6g}  edge {p['edge']:.4g}  "
              f"angle {p['angle']:.4g}  area {p['area']:.4g}  flipped {p['flipped']}  {p['seconds']:.3f} s")
    assert len(passes) >= 1 and [p["pass"] for p in passes] == list(range(len(passes))), \
        f"the log has the metrics of passes 0..{len(passes) - 1}"
    assert kept is not None, "the log names the kept pass and the stop reason"
    print(f"        kept pass {kept.group(1)}, L2 stretch {kept.group(2)}, stop reason '{kept.group(3)}'")
    chosen = [p for p in passes if p["pass"] == int(kept.group(1))]
    assert len(chosen) == 1, "the kept pass is one of the logged passes"
    best = min(p["l2"] for p in passes)
    assert chosen[0]["l2"] == best, f"the kept pass has the lowest L2 stretch ({chosen[0]['l2']} vs {best})"
    assert Stretch.agrees(chosen[0]["l2"], recomputed.total, recomputed.total_err, recomputed.scale_rel_err), (
        f"the kept pass's logged L2 stretch {chosen[0]['l2']} = recomputed {recomputed.total:.6g} "
        f"+- {2 * recomputed.total_err:.1g}")
    if boundary in ("square", "circle"):
        assert chosen[0]["flipped"] == 0 and chosen[0]["degenerate"] == 0, \
            "the kept pass logs no flipped or degenerate triangle"

    if args.tool:
        compare_with_tool(args, boundary, out_ply, ply, passes, kept)
    else:
        print("info:   no --tool given: quality checked against the recomputed stretch only")
    return ply


def check_repaired(log, ply, boundary):
    """A disk whose map, as stored, folded or collapsed faces (a natural boundary can), cut by the
    filter's last step (atlas/measure/valid_as_stored.h): in the file, every face with 3D area has
    a positive UV triangle inside the gutter, per-vertex texcoords only where they equal every
    wedge's (no seam), and the log still has the passes and the kept pass."""
    vertices, faces = ply.vertices(), ply.faces()
    texcoords = ply.elements["face"].data["texcoord"]
    values = [x for tc in texcoords for x in tc]
    assert all(math.isfinite(x) and GUTTER - 1e-6 <= x <= 1 - GUTTER + 1e-6 for x in values), \
        f"texcoords are 2 texels of 1024 inside [0,1]: range [{min(values):.6g}, {max(values):.6g}]"
    bad = 0
    for face, tc in zip(faces, texcoords):
        area = edges_and_area(*(vertices[v] for v in face))[2]
        area_uv = 0.5 * ((tc[2] - tc[0]) * (tc[5] - tc[1]) - (tc[4] - tc[0]) * (tc[3] - tc[1]))
        bad += area > 0 and not area_uv > 0
    assert bad == 0, f"no flipped or zero-area UV triangle on a face with area in the file ({bad})"
    vert_el = ply.elements["vertex"]
    if vert_el.has("texture_u"):  # only where every vertex has one texcoord (no seam)
        uv = wedge_uv(ply)
        assert all(uv[i] is None or uv[i] == t for i, t in enumerate(zip(vert_el.data["texture_u"], vert_el.data["texture_v"]))), \
            "per-vertex texcoords equal the per-wedge ones"
    passes, kept = parse_log(log)
    assert passes and kept is not None, "the log has the passes and the kept pass"
    print(f"info:   {boundary}: the stored map folded or collapsed faces, cut out by the filter's last step")
    return ply


def compare_with_tool(args, boundary, out_ply, ply, passes, kept):
    """The tool run on the mesh MeshLab saved (same vertices and faces, same float coordinates that
    the filter saw) must give the same quality, texcoords and pass metrics."""
    tool_ply = os.path.join(args.work, "tool.ply")
    proc = run_tool(args.tool, args.work, out_ply, tool_ply, boundary)
    assert proc.returncode == 0 and os.path.isfile(tool_ply), (
        f"the lowstretch tool succeeds on the same mesh (exit code {proc.returncode}) {proc.stderr.strip()[:200]}")
    try:
        report = json.loads(proc.stdout)
    except ValueError:
        report = None
    assert isinstance(report, dict), "the tool's --json output is one JSON object"
    tool_passes = report.get("passes", [])
    keys = (("l2_stretch", "l2"), ("linf_stretch", "linf"), ("edge_distortion", "edge"),
            ("angle_distortion", "angle"), ("area_distortion", "area"))
    same = len(tool_passes) == len(passes) and all(  # JSON has no infinity: the tool writes null
        all(rel_diff(math.inf if t[k] is None else t[k], p[ours]) <= 1e-5 for k, ours in keys) and
        t["flipped"] == p["flipped"] and t["degenerate"] == p["degenerate"] for t, p in zip(tool_passes, passes))
    assert same, f"the logged metrics of every pass = the tool's JSON ({len(passes)} passes vs {len(tool_passes)})"
    if kept:
        assert report.get("chosen_pass") == int(kept.group(1)), \
            f"the kept pass = the tool's chosen_pass ({kept.group(1)} vs {report.get('chosen_pass')})"
    try:
        theirs = meshio.read_ply(tool_ply)
    except (ValueError, struct.error) as e:
        raise AssertionError(f"the tool's PLY is a valid PLY file ({e})") from e
    ours_q, theirs_q = ply.elements["vertex"].data["quality"], theirs.elements["vertex"].data.get("quality", [])
    assert len(ours_q) == len(theirs_q), f"the tool's PLY has a quality per vertex ({len(theirs_q)})"
    d, i = worst(zip(ours_q, theirs_q))
    assert d <= 1e-5, f"per-vertex quality = the tool's: max relative difference {d:.2e} (vertex {i}) <= 1e-5"
    ours_tc, theirs_tc = ply.elements["face"].data["texcoord"], theirs.elements["face"].data.get("texcoord", [])
    assert len(ours_tc) == len(theirs_tc), f"the tool's PLY has per-wedge texcoords ({len(theirs_tc)} faces)"
    diff = max((abs(a - b) for x, y in zip(ours_tc, theirs_tc) for a, b in zip(x, y)), default=0.0)
    assert diff <= 1e-6, f"per-wedge texcoords = the tool's: max difference {diff:.2e} <= 1e-6"


def check_same_output(result, reference, what):
    """Texture coordinates and quality written by the filter, equal in two PLY files."""
    for element, props in (("vertex", ("texture_u", "texture_v", "quality")), ("face", ("texcoord", "quality"))):
        for prop in props:
            assert result.elements[element].data.get(prop) == reference.elements[element].data.get(prop), \
                f"same {element} {prop} {what}"


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("command", choices=("prefix",))
    parser.add_argument("--prefix", required=True, help="private MeshLab prefix (emptied first)")
    parser.add_argument("--plugin", required=True, help="libfilter_lowstretch.so under test")
    args = parser.parse_args()
    make_prefix(args.prefix, args.plugin)
    return 0


if __name__ == "__main__":
    sys.exit(main())
