"""End-to-end tests of the "Low-stretch parameterization" filter through the real meshlabserver
2020.09 (under xvfb-run), with the plugin in the private prefix made by `e2e.py prefix`.

  python3 -B -m pytest -p no:cacheprovider tests/e2e/test_e2e.py --prefix P --resources DIR \
      --runner lowstretch_plugin_runner --plugin libfilter_lowstretch.so [--tool lowstretch] \
      [--cgal-meshes DIR] [--shared-meshes DIR] [--basetemp DIR]

test_disk[BOUNDARY_MESH]: the saved PLY has per-wedge texcoords in [0,1]^2 equal to the per-vertex
ones, no flipped or zero-area triangle for Square and Circle, per-vertex and per-face quality
equal to the stretch recomputed from the saved positions and texcoords and, with --tool, to the
quality the `lowstretch` tool writes for the same mesh; the log holds every pass's metrics and the
kept pass, which has the lowest L2 stretch and matches the recomputed one (e2e.check_result).
test_bad[MESH], test_bad_option[NAME] (a bad mesh, or an invalid parameter value): meshlabserver
prints the filter's message and fails without writing the output; the runner (which, unlike
meshlabserver, saves after a failing filter) shows the mesh and its data masks unchanged.
test_charts[MESH]: a non-disk with "Non-disk input: Make charts" gets a valid atlas, the tool's.
test_deleted_elements: vertices and faces deleted (not compacted) by earlier filters in the same
script give exactly the result of the mesh without them. test_second_run_replaces: Circle then
Square in one script gives exactly Square alone. test_repack: "Pack again only" after the atlas in
one script keeps its charts, at another texture size and gutter. Meshes: generated, Debian's CGAL demo meshes
(--cgal-meshes) and the shared ones when --shared-meshes exists. Each test works in its tmp_path.
"""
import json
import math
import os
import re
import shutil
import subprocess
import sys
import types
import xml.etree.ElementTree as ET

import pytest

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import e2e  # noqa: E402
import generate  # noqa: E402
import meshio  # noqa: E402
import pytest_options  # noqa: E402
from e2e import FAIL_RE, FILTER, GUTTER, HEADER_RE, CHARTS_RE, check_result, check_same_output  # noqa: E402
from e2e import core_message, meshlabserver, mlx, prepare, rel_diff, run_tool  # noqa: E402
from uv_charts import uv_charts  # noqa: E402

BOUNDARIES = ("square", "circle", "natural")
GENERATED_DISKS = ("wavy_grid", "hemisphere", "grid_with_unused_vertices")
CGAL_DISKS = ("mannequin-devil", "lion-head", "mushroom", "three_peaks", "nefertiti")
SHARED_DISKS = ("disk_*.off", "disk_*.ply", "disk_*.obj", "seams_*.obj")
GENERATED_BAD = ("two_components", "tetrahedron", "octahedron", "three_holes", "point_cloud", "unwelded")
SHARED_BAD = ("bad/*.off", "bad/*.ply", "bad/*.obj", "holes*.off")
GENERATED_NON_DISKS = ("two_components", "three_holes", "octahedron", "torus", "sphere")
# The shared non-disks that are manifold and oriented (holes, closed, several components, genus 1).
SHARED_NON_DISKS = ("holes*.off", "bad/bad_closed_*", "bad/bad_components*", "bad/bad_genus1_*", "bad/bad_holes*",
                    "bad/bad_quads*", "bad/bad_nonmanifold*")
# Invalid parameter values in a script: the same failure path as a bad mesh.
BAD_OPTIONS = {"exponent_zero": ("exponent=0", "Exponent"), "exponent_above_one": ("exponent=1.5", "Exponent"),
               "max_passes": ("maxPasses=-1", "Max passes"), "boundary": ("boundaryShape=3", "Boundary shape"),
               "non_disk": ("nonDisk=3", "Non-disk input"), "max_stretch": ("maxStretch=0.5", "Max chart stretch")}


def generated(name):
    return {"mesh": None, "generate": name}


def given(path):
    return {"mesh": path, "generate": None}


def pytest_generate_tests(metafunc):
    """The meshes of each test, with ids that make the ctest names (CMakeLists.txt)."""
    config = metafunc.config
    cgal = config.getoption("cgal_meshes")
    if "disk_case" in metafunc.fixturenames:
        cases = {}
        for boundary in BOUNDARIES:
            cases.update({f"{boundary}_{m}": (boundary, generated(m)) for m in GENERATED_DISKS})
            cases.update({f"{boundary}_cgal_{m}": (boundary, given(os.path.join(cgal, m + ".off"))) for m in CGAL_DISKS})
            cases.update({f"{boundary}_shared_{m}": (boundary, given(p))
                          for m, p in pytest_options.shared(config, *SHARED_DISKS)})
        metafunc.parametrize("disk_case", list(cases.values()), ids=list(cases))
    if "bad_case" in metafunc.fixturenames:
        cases = {m: generated(m) for m in GENERATED_BAD}
        cases.update({f"shared_{m}": given(p) for m, p in pytest_options.shared(config, *SHARED_BAD)})
        metafunc.parametrize("bad_case", list(cases.values()), ids=list(cases))
    if "charts_case" in metafunc.fixturenames:
        cases = {m: generated(m) for m in GENERATED_NON_DISKS}
        cases.update({f"shared_{m}": given(p) for m, p in pytest_options.shared(config, *SHARED_NON_DISKS)})
        metafunc.parametrize("charts_case", list(cases.values()), ids=list(cases))
    if "bad_option" in metafunc.fixturenames:
        metafunc.parametrize("bad_option", list(BAD_OPTIONS.values()), ids=list(BAD_OPTIONS))


@pytest.fixture
def args(request, tmp_path):
    """What the helpers of e2e.py read: the work folder (this test's tmp_path), the programs."""
    config = request.config
    return types.SimpleNamespace(work=str(tmp_path), prefix=pytest_options.required(config, "prefix"),
                                 resources=os.path.abspath(pytest_options.required(config, "resources")),
                                 tool=config.getoption("tool"), runner=config.getoption("runner"),
                                 plugin=config.getoption("plugin"), mesh=None, generate=None, set=[], expect=None)


def with_input(args, case):
    args.mesh, args.generate = case["mesh"], case["generate"]
    assert not args.mesh or os.path.isfile(args.mesh), f"input mesh {args.mesh} exists"
    return args


def test_disk(args, disk_case):
    boundary, case = disk_case
    with_input(args, case)
    input_path, name = prepare(args, generate.DISKS)
    out = os.path.join(args.work, "out.ply")
    proc = meshlabserver(args.prefix, args.work, "meshlabserver.log",
                         ["-i", input_path, "-o", out, "-m", "vt", "wt", "vq", "fq", "-s", mlx(args, boundary)])
    check_result(args, name, boundary, proc, out)


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


# meshlabserver's save masks: binary PLY, ASCII PLY ("sa"), OBJ; each must hold the atlas as made.
SAVED_FORMATS = {"binary_ply": ("out.ply", ["-m", "wt", "vq", "fq"]), "ascii_ply": ("out.ply", ["-m", "wt", "vq", "fq", "sa"]),
                 "obj": ("out.obj", ["-m", "wt"])}


def area3(p, q, r):
    u, v = [q[k] - p[k] for k in range(3)], [r[k] - p[k] for k in range(3)]
    return math.dist((0, 0, 0), (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])) / 2


@pytest.mark.parametrize("saved_format", list(SAVED_FORMATS))
def test_saved_atlas(args, saved_format):
    """An atlas with seams (a sphere cut open), saved by meshlabserver as binary PLY, ASCII PLY
    and OBJ: every face's wedge texcoords in the file make a counter-clockwise triangle of positive
    area. (MeshLab's ASCII PLY writer takes per-vertex texcoords for the wedges when a mesh has
    them: the filter leaves none on an atlas.)"""
    with_input(args, generated("sphere"))
    input_path, name = prepare(args, generate.NON_DISKS)
    file_name, mask = SAVED_FORMATS[saved_format]
    out = os.path.join(args.work, file_name)
    proc = meshlabserver(args.prefix, args.work, "meshlabserver.log",
                         ["-i", input_path, "-o", out] + mask + ["-s", os.path.join(args.resources, "lowstretch.mlx")])
    assert proc.returncode == 0 and os.path.isfile(out), f"meshlabserver applies the filter (exit code {proc.returncode})"
    summary = CHARTS_RE.search(proc.stdout)
    assert summary is not None and float(summary.group(3)) > 0, "the sphere is cut open (seams)"
    if saved_format == "obj":
        vertices, faces, corners = meshio.read_obj_with_texcoords(out)
        triangles = [tuple(corners[3 * f:3 * f + 3]) for f in range(len(faces))]
    else:
        ply = meshio.read_ply(out)
        assert ply.format == ("ascii" if saved_format == "ascii_ply" else "binary_little_endian"), ply.format
        vertices, faces = ply.vertices(), ply.faces()
        triangles = [((tc[0], tc[1]), (tc[2], tc[3]), (tc[4], tc[5])) for tc in ply.elements["face"].data["texcoord"]]
    assert len(faces) == len(meshio.read_off(input_path)[1]) and all(None not in t for t in triangles), \
        "every face is saved with its wedge texcoords"
    bad = sum(1 for f, t in zip(faces, triangles) if area3(*(vertices[v] for v in f)) > 0 and not signed_area(*t) > 0)
    assert bad == 0, f"no flipped or zero-area UV triangle in the {saved_format} file ({bad} of {len(faces)})"


def test_charts(args, charts_case):
    """A mesh that is not a disk, with "Non-disk input: Make charts" (the default): per-wedge texcoords in
    [0,1]^2 on every face, no flipped or zero-area triangle, no overlap; the same charts, seams and
    stretch as the lowstretch tool on the same (float) input."""
    with_input(args, charts_case)
    input_path, name = prepare(args, generate.NON_DISKS)
    mask = ["-m", "wt", "vq", "fq"]
    reference = os.path.join(args.work, "reference.ply")
    proc = meshlabserver(args.prefix, args.work, "reference.log", ["-i", input_path, "-o", reference] + mask)
    assert proc.returncode == 0 and os.path.isfile(reference), f"meshlabserver loads {name} and saves it"
    out = os.path.join(args.work, "out.ply")
    proc = meshlabserver(args.prefix, args.work, "meshlabserver.log",
                         ["-i", reference, "-o", out] + mask + ["-s", os.path.join(args.resources, "lowstretch.mlx")])
    assert proc.returncode == 0 and os.path.isfile(out), f"meshlabserver applies the filter (exit code {proc.returncode})"
    summary = CHARTS_RE.search(proc.stdout)
    assert summary is not None, "the log has the charts summary line"
    charts, seam, l2 = int(summary.group(1)), float(summary.group(3)), float(summary.group(6))
    coverage, efficiency = float(summary.group(4)), float(summary.group(5))
    print(f"{name}: {charts} charts, seam length {seam}, L2 stretch {l2}, coverage {coverage}, efficiency {efficiency}")
    assert int(summary.group(11)) == 0 and int(summary.group(12)) == 0, \
        "the log reports no flipped and no degenerate triangle"
    assert rel_diff(efficiency, coverage / l2 ** 2) < 1e-3, f"efficiency is coverage / L2^2 ({coverage / l2 ** 2:.6g})"

    ply, ref = meshio.read_ply(out), meshio.read_ply(reference)
    assert ply.faces() == ref.faces(), f"the faces are the input's ({len(ref.faces())})"
    texcoords = ply.elements["face"].data.get("texcoord")
    assert texcoords is not None and len(texcoords) == len(ply.faces()), "every face has wedge texcoords"
    assert all(len(tc) == 6 and all(GUTTER - 1e-6 <= t <= 1 - GUTTER + 1e-6 for t in tc) for tc in texcoords), \
        "all wedge texcoords are 2 texels of 1024 inside [0,1]^2"
    triangles = [((tc[0], tc[1]), (tc[2], tc[3]), (tc[4], tc[5])) for tc in texcoords]
    bad = sum(1 for t in triangles if not signed_area(*t) > 0)
    assert bad == 0, f"no flipped or zero-area triangle in any chart ({bad})"
    overlaps = overlapping_pixels(triangles)
    assert overlaps == 0, f"no two triangles overlap (pixel centres of a 1024 raster covered twice: {overlaps})"

    if args.tool:
        command = [args.tool, reference, "--non-disk", "charts", "--json"]
        tool = subprocess.run(command, cwd=args.work, capture_output=True, text=True, errors="replace", timeout=900)
        assert tool.returncode == 0, f"the lowstretch tool makes charts too (exit code {tool.returncode})"
        result = json.loads(tool.stdout)
        assert (result["chart_count"] == charts and rel_diff(result["seam_length"], seam) < 1e-5
                and rel_diff(result["layout"]["l2_stretch"], l2) < 1e-5), (
            f"the tool agrees: {result['chart_count']} charts, seam length {result['seam_length']}, "
            f"L2 stretch {result['layout']['l2_stretch']} (the filter: {charts} charts, seam length {seam}, "
            f"L2 stretch {l2})")


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


def run_bad(args):
    """Bad input (a bad mesh, or a good one with args.set holding an invalid parameter value), in
    disk-only mode (Non-disk input: Reject) unless args.set says otherwise."""
    assert args.runner and args.plugin, "give --runner and --plugin"
    input_path, name = prepare(args, {**generate.BAD, **generate.DISKS})
    if not any(s.startswith("nonDisk=") for s in args.set):
        args.set = ["nonDisk=0"] + args.set
    script = script_with(args, args.set, os.path.join(args.work, "script.mlx"))
    mask = ["-m", "vt", "wt", "vq", "fq"]
    reference = os.path.join(args.work, "reference.ply")
    proc = meshlabserver(args.prefix, args.work, "reference.log", ["-i", input_path, "-o", reference] + mask)
    assert proc.returncode == 0 and os.path.isfile(reference), \
        f"meshlabserver loads {name} and saves it without the filter"

    out = os.path.join(args.work, "out.ply")
    proc = meshlabserver(args.prefix, args.work, "meshlabserver.log",
                         ["-i", input_path, "-o", out] + mask + ["-s", script])
    failure = FAIL_RE.search(proc.stdout)
    message = failure.group(1).strip() if failure else ""
    assert proc.returncode != 0 and f"Problem with filter: {FILTER}" in proc.stdout, \
        f"meshlabserver reports that the filter failed (exit code {proc.returncode})"
    assert bool(message) and not message.startswith("internal error"), \
        f"the log holds the filter's message: '{message}'"
    assert not os.path.exists(out), "no output mesh is written"
    expected = args.expect or e2e.EXPECTED.get(name)
    if expected:
        assert expected in message, f"the message names the problem ('{expected}'): '{message}'"

    if args.tool and args.set == ["nonDisk=0"]:
        tool_out = os.path.join(args.work, "tool.ply")
        tool = run_tool(args.tool, args.work, reference, tool_out, "square", disk_only=True)
        assert (tool.returncode != 0 and message and core_message(message) in tool.stderr
                and not os.path.exists(tool_out)), (
            f"the lowstretch tool rejects the same mesh with the same message (exit code {tool.returncode}: "
            f"{tool.stderr.strip()[:300]}; the filter's: '{message}')")

    # The mesh is left as it was: saved before and after the failing filter by the runner.
    before, after = os.path.join(args.work, "runner_before.ply"), os.path.join(args.work, "runner_after.ply")
    runner = subprocess.run([args.runner, args.plugin, reference, before, after] + args.set, cwd=args.work,
                            capture_output=True, text=True, errors="replace", timeout=900,
                            env=dict(os.environ, QT_QPA_PLATFORM="offscreen"))
    with open(os.path.join(args.work, "runner.log"), "w") as f:
        f.write(f"exit code {runner.returncode}\n--- stdout ---\n{runner.stdout}\n--- stderr ---\n{runner.stderr}")
    lines = dict(line.split(": ", 1) for line in runner.stdout.splitlines() if ": " in line)
    assert runner.returncode == 0 and lines.get("result") == "failed", (
        f"the runner applies the filter and it fails (exit code {runner.returncode}, result {lines.get('result')})")
    assert lines.get("errorMessage") == message, \
        f"errorMessage (shown by the GUI) is the logged message: '{lines.get('errorMessage')}' vs '{message}'"
    assert lines.get("dataMask before") == lines.get("dataMask after"), \
        f"the data masks are unchanged ({lines.get('dataMask before')} -> {lines.get('dataMask after')})"
    with open(before, "rb") as f1, open(after, "rb") as f2:
        assert f1.read() == f2.read(), "the mesh saved after the failing filter is byte-identical to the one before"
    saved, ref = meshio.read_ply(after), meshio.read_ply(reference)
    assert saved.vertices() == ref.vertices() and saved.faces() == ref.faces(), \
        f"it has the input's vertices and faces ({len(ref.vertices())} and {len(ref.faces())})"
    assert (not saved.elements["face"].has("texcoord") and not saved.elements["vertex"].has("texture_u")
            and not saved.texture_files()), "it has no texcoords and no texture"


def test_bad(args, bad_case):
    run_bad(with_input(args, bad_case))


def test_bad_option(args, bad_option):
    setting, expect = bad_option
    with_input(args, generated("wavy_grid"))
    args.set, args.expect = [setting], expect
    run_bad(args)


def square_and_script(args, reference_mesh, script_mesh, script):
    """meshlabserver twice: the Square script alone on reference_mesh (checked like any run), and
    `script` (a FilterScript element) on script_mesh. Returns the reference PLY, the second run's
    process and its output path."""
    script_path = os.path.join(args.work, "script.mlx")
    ET.ElementTree(script).write(script_path)
    mask = ["-m", "vt", "wt", "vq", "fq"]
    out_reference = os.path.join(args.work, "reference_out.ply")
    proc = meshlabserver(args.prefix, args.work, "reference.log",
                         ["-i", reference_mesh, "-o", out_reference] + mask + ["-s", mlx(args)])
    reference = check_result(args, os.path.basename(reference_mesh), "square", proc, out_reference)
    out = os.path.join(args.work, "script_out.ply")
    proc = meshlabserver(args.prefix, args.work, "script.log", ["-i", script_mesh, "-o", out] + mask + ["-s", script_path])
    return reference, proc, out


def test_deleted_elements(args):
    """The filter after 'Select by Vertex Quality' + 'Delete Selected Faces and Vertices' in the same
    meshlabserver script (deleted elements stay in the vectors, interleaved with live ones) must
    give exactly what it gives on the mesh without the deleted part."""
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
    reference, proc, out_flap = square_and_script(args, plain, with_flap, script)
    deleted = sum(1 for q in quality if q > 0)
    assert f"Deleted 10 faces, {deleted} vertices." in proc.stdout, \
        "the script deleted the flap's 10 faces and 12 vertices before the filter ran"
    header = HEADER_RE.search(proc.stdout)
    assert header is not None and header.groups() == (str(len(grid_v)), str(len(grid_f))), \
        f"the filter saw only the live elements: {header and header.groups()}"
    assert proc.returncode == 0 and os.path.isfile(out_flap), "the filter succeeds after the deletion"
    result = meshio.read_ply(out_flap)
    assert result.vertices() == reference.vertices() and result.faces() == reference.faces(), \
        "same vertices and faces as the mesh without the flap"
    check_same_output(result, reference, "as the mesh without the flap")


def test_second_run_replaces(args):
    """Running the filter again replaces what the first run wrote: Circle then Square in one
    meshlabserver script gives exactly the texcoords and quality of Square alone."""
    shutil.rmtree(args.work, ignore_errors=True)
    os.makedirs(args.work)
    vertices, faces = generate.wavy_grid(12)
    mesh = os.path.join(args.work, "wavy_grid.off")
    meshio.write_off(mesh, vertices, faces)
    script = ET.Element("FilterScript")
    for boundary in ("circle", "square"):
        script.append(ET.parse(mlx(args, boundary)).getroot().find("filter"))
    reference, proc, out_twice = square_and_script(args, mesh, mesh, script)
    runs = set(re.findall(rf"{FILTER}: \d+ vertices, \d+ faces; boundary (\w+)", proc.stdout))
    assert runs == {"circle", "square"}, f"the script ran the filter with both boundaries: {sorted(runs)}"
    assert proc.returncode == 0 and os.path.isfile(out_twice), "the second run succeeds"
    check_same_output(meshio.read_ply(out_twice), reference, "after Circle then Square as after Square alone")


def test_repack(args):
    """The filter, then the filter with "Pack again only", 256 texels and an 8-texel gutter, in one
    meshlabserver script: the log says the charts were read and packed again (or kept where they
    are, scaled, where that keeps the gutter and uses the texture better), the saved PLY holds
    the charts of the filter alone, 8 texels of 256 inside [0,1]^2, no flipped or zero-area UV
    triangle."""
    shutil.rmtree(args.work, ignore_errors=True)
    os.makedirs(args.work)
    vertices, faces = generate.NON_DISKS["sphere"]()
    mesh = os.path.join(args.work, "sphere.off")
    meshio.write_off(mesh, vertices, faces)
    script = ET.Element("FilterScript")
    script.append(ET.parse(mlx(args)).getroot().find("filter"))
    repack = ET.parse(mlx(args)).getroot().find("filter")
    for name, value in (("repackOnly", "true"), ("textureSize", "256"), ("gutter", "8")):
        repack.find(f"Param[@name='{name}']").set("value", value)
    script.append(repack)
    script_path = os.path.join(args.work, "script.mlx")
    ET.ElementTree(script).write(script_path)
    runs = {}
    for name, path in (("reference", mlx(args)), ("script", script_path)):
        out = os.path.join(args.work, name + "_out.ply")
        proc = meshlabserver(args.prefix, args.work, name + ".log", ["-i", mesh, "-o", out, "-m", "wt", "-s", path])
        assert proc.returncode == 0 and os.path.isfile(out), f"the {name} run succeeds (exit code {proc.returncode})"
        runs[name] = proc
    reference = meshio.read_ply(os.path.join(args.work, "reference_out.ply"))
    proc = runs["script"]
    assert re.search(r"\d+ charts read from the texture coordinates (packed again|kept where they are)", proc.stdout), \
        "the log says so"
    result = meshio.read_ply(out)

    def triangles(ply):
        return [((t[0], t[1]), (t[2], t[3]), (t[4], t[5])) for t in ply.elements["face"].data["texcoord"]]

    assert uv_charts(result.faces(), triangles(result)) == uv_charts(reference.faces(), triangles(reference)), \
        "the same charts as the filter alone"
    g = 8 / 256
    uv = [c for t in triangles(result) for p in t for c in p]
    assert g - 1e-6 <= min(uv) and max(uv) <= 1 - g + 1e-6, f"8 texels of 256 inside ({min(uv)}, {max(uv)})"
    assert all(signed_area(*t) > 0 for t in triangles(result)), "no flipped or zero-area UV triangle"
