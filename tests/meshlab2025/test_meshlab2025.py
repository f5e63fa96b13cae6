"""End-to-end tests of the "Low-stretch parameterization" filter for MeshLab 2025.07's FilterPlugin
API, headless, through lowstretch_meshlab2025_runner (runner.cpp: MeshLab's PluginManager loads the
plugin as pymeshlab does, vcglib reads the mesh, applyFilter, the mesh is saved before and after).
The assertions are those of the MeshLab 2020.09 end-to-end tests (tests/e2e/e2e.py's check_result,
used here as it is), plus the output values that applyFilter returns.

  python3 -B -m pytest -p no:cacheprovider tests/meshlab2025/test_meshlab2025.py \
      --ml2025-runner lowstretch_meshlab2025_runner --ml2025-plugin libfilter_lowstretch.so \
      [--tool lowstretch] [--cgal-meshes DIR] [--shared-meshes DIR] [--basetemp DIR]

test_disk[BOUNDARY_MESH]: the filter succeeds; the saved PLY has per-wedge texcoords in [0,1]^2
equal to the per-vertex ones, no flipped or zero-area triangle for Square and Circle, per-vertex
and per-face quality equal to the stretch recomputed from the saved file (and, with --tool, to the
lowstretch tool's), the checkerboard saved next to it; the log holds every pass and the kept pass;
the output values are the kept pass's logged metrics. test_bad[MESH], test_bad_option[NAME]:
applyFilter throws MLException with the core's message (also logged), and the mesh and its data
masks are left exactly as they were. test_deleted_elements: vertices and faces deleted (not
compacted) before the filter give exactly the result of the mesh without them.
"""
import os
import re
import subprocess
import sys
import types

import pytest

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "e2e"))
import e2e  # noqa: E402
import generate  # noqa: E402
import meshio  # noqa: E402
import pytest_options  # noqa: E402

BOUNDARY_INDEX = {"square": 0, "circle": 1, "natural": 2}
PYTHON_NAME = "compute_texcoord_parametrization_low_stretch"
TEXTURE_CLASS = 0x02000  # FilterPlugin::Texture
OUTPUT_RE = re.compile(r"^output: (\w+)=(\S+) \((\w+)\)$", re.M)
GENERATED_DISKS = ("wavy_grid", "hemisphere")
CGAL_DISKS = ("mannequin-devil", "lion-head", "mushroom", "three_peaks", "nefertiti")
SHARED_DISKS = ("disk_*.off", "disk_*.ply", "disk_*.obj", "seams_*.obj")  # Square only (2020.09: all three)
GENERATED_BAD = ("two_components", "tetrahedron", "octahedron", "three_holes", "unwelded")
SHARED_BAD = ("bad/*.off", "bad/*.ply", "bad/*.obj", "holes*.off")
BAD_OPTIONS = {"exponent_zero": ("exponent=0", "Exponent"), "exponent_above_one": ("exponent=1.5", "Exponent"),
               "max_passes": ("maxPasses=-1", "Max passes"), "boundary": ("boundaryShape=3", "Boundary shape")}


def pytest_generate_tests(metafunc):
    """The meshes of each test, with ids that make the ctest names (CMakeLists.txt)."""
    config = metafunc.config
    cgal = config.getoption("cgal_meshes")
    if "disk_case" in metafunc.fixturenames:
        cases = {}
        for boundary in BOUNDARY_INDEX:
            cases.update({f"{boundary}_{m}": (boundary, None, m) for m in GENERATED_DISKS})
            cases.update({f"{boundary}_cgal_{m}": (boundary, os.path.join(cgal, m + ".off"), None) for m in CGAL_DISKS})
        cases.update({f"square_shared_{m}": ("square", p, None) for m, p in pytest_options.shared(config, *SHARED_DISKS)})
        metafunc.parametrize("disk_case", list(cases.values()), ids=list(cases))
    if "bad_case" in metafunc.fixturenames:
        cases = {m: (None, m) for m in GENERATED_BAD}
        cases.update({f"shared_{m}": (p, None) for m, p in pytest_options.shared(config, *SHARED_BAD)})
        metafunc.parametrize("bad_case", list(cases.values()), ids=list(cases))
    if "bad_option" in metafunc.fixturenames:
        metafunc.parametrize("bad_option", list(BAD_OPTIONS.values()), ids=list(BAD_OPTIONS))


@pytest.fixture
def args(request, tmp_path):
    """What the helpers of e2e.py read; the work folder is this test's tmp_path."""
    config = request.config
    return types.SimpleNamespace(work=str(tmp_path), runner=pytest_options.required(config, "ml2025_runner"),
                                 plugin=pytest_options.required(config, "ml2025_plugin"), tool=config.getoption("tool"),
                                 mesh=None, generate=None, set=[], expect=None)


def core_message(message):
    """The core's message without the adapter's own hint (the filter names its parameter, the
    tool its option, after the core's words): what the filter and the tool share."""
    return message.split(" (set \"Non-disk input\"")[0]


def run_runner(args, input_path, before, after, settings, log_name="runner.log"):
    """The runner in the work folder (the texture is saved there, next to after)."""
    command = [args.runner, args.plugin, input_path, before, after] + settings
    proc = subprocess.run(command, cwd=args.work, capture_output=True, text=True, errors="replace", timeout=900)
    with open(os.path.join(args.work, log_name), "w") as f:
        f.write("$ " + " ".join(command) + f"\nexit code {proc.returncode}\n--- stdout ---\n{proc.stdout}"
                f"\n--- stderr ---\n{proc.stderr}")
    print(f"runner {' '.join(settings) or '(defaults)'} on {os.path.basename(input_path)}: exit code "
          f"{proc.returncode}, log in {os.path.join(args.work, log_name)}")
    return proc


def fields(proc):
    return dict(line.split(": ", 1) for line in proc.stdout.splitlines() if ": " in line)


def check_plugin_line(proc):
    plugin = fields(proc).get("plugin", "")
    assert plugin == f"{e2e.FILTER} | {PYTHON_NAME} | {TEXTURE_CLASS}", \
        f"PluginManager loads the plugin: '{plugin}' (display name | pymeshlab name | class Texture)"


def check_outputs(proc):
    """applyFilter's output values are the kept pass's metrics as the log gives them."""
    outputs = {m[1]: (m[2], m[3]) for m in OUTPUT_RE.finditer(proc.stdout)}
    expected = {"l2_stretch": "double", "linf_stretch": "double", "edge_distortion": "double",
                "angle_distortion": "double", "area_distortion": "double", "flipped": "int", "degenerate": "int",
                "kept_pass": "int", "passes": "int", "initial_l2_stretch": "double", "seconds": "double",
                "charts": "int", "seam_length": "double", "coverage": "double", "efficiency": "double",
                "max_chart_stretch": "double", "least_gutter": "double", "subtexel_triangles": "int",
                "float_collapsed": "int"}
    assert {k: t for k, (v, t) in outputs.items()} == expected, \
        f"applyFilter returns the output values {sorted(expected)} with their types"
    passes, kept = e2e.parse_log(proc.stdout)
    assert passes and kept is not None, "the log has the passes and the kept pass"
    chosen = [p for p in passes if p["pass"] == int(kept.group(1))][0]
    value = {k: float(v) for k, (v, _) in outputs.items()}
    stored = e2e.STORED_RE.search(proc.stdout)
    assert stored is not None, "the log has the metrics of the texture coordinates as stored"
    # The output values describe the stored (float) map: the log's "as stored" line; the kept
    # pass, computed in double, is within the rounding of it, unless the filter's last step had to
    # map it again (the note of e2e.REPAIRED_RE).
    repaired = e2e.REPAIRED_RE.search(proc.stdout) is not None
    same = (e2e.rel_diff(value["l2_stretch"], float(stored.group(1))) <= 1e-5
            and e2e.rel_diff(value["linf_stretch"], float(stored.group(2))) <= 1e-5
            and value["flipped"] == int(stored.group(3)) and value["degenerate"] == int(stored.group(4))
            and e2e.rel_diff(value["coverage"], float(stored.group(5))) <= 1e-4
            and value["subtexel_triangles"] == int(stored.group(6))
            and (repaired or e2e.rel_diff(value["l2_stretch"], chosen["l2"]) <= 1e-3))
    assert (same and value["kept_pass"] == chosen["pass"] and value["passes"] == len(passes)
            and e2e.rel_diff(value["initial_l2_stretch"], passes[0]["l2"]) <= 1e-5), (
        f"the output values are the logged metrics of the stored map (kept pass {int(value['kept_pass'])} of "
        f"{int(value['passes'])}, L2 stretch {value['l2_stretch']:.6g}, kept pass's {chosen['l2']:.6g}; "
        f"outputs {value}, as stored {stored.groups()})")


def test_disk(args, disk_case, monkeypatch):
    boundary, args.mesh, args.generate = disk_case
    assert not args.mesh or os.path.isfile(args.mesh), f"input mesh {args.mesh} exists"
    input_path, name = e2e.prepare(args, generate.DISKS)
    before, out = os.path.join(args.work, "before.ply"), os.path.join(args.work, "out.ply")
    # As the 2020.09 scripts: circle and natural disk only, square the default (charts of a non-disk).
    disk_only = ["nonDisk=0"] if boundary != "square" else []
    proc = run_runner(args, input_path, before, out, [f"boundaryShape={BOUNDARY_INDEX[boundary]}"] + disk_only)
    check_plugin_line(proc)
    monkeypatch.chdir(args.work)  # the PLY names its texture relative to itself
    print("info:   the checks below come from tests/e2e/e2e.py: its 'meshlabserver' is the runner here")
    e2e.check_result(args, name, boundary, proc, out)
    check_outputs(proc)


def run_bad(args):
    assert not args.mesh or os.path.isfile(args.mesh), f"input mesh {args.mesh} exists"
    input_path, name = e2e.prepare(args, {**generate.BAD, **generate.DISKS})
    before, after = os.path.join(args.work, "before.ply"), os.path.join(args.work, "after.ply")
    if not any(s.startswith("nonDisk=") for s in args.set):  # disk only, unless the test sets it
        args.set = ["nonDisk=0"] + args.set
    proc = run_runner(args, input_path, before, after, args.set)
    lines = fields(proc)
    assert proc.returncode == 1 and lines.get("result") == "failed", \
        f"applyFilter throws (exit code {proc.returncode}, result {lines.get('result')})"
    message = lines.get("message", "")
    assert bool(message) and not message.startswith("internal error"), f"the MLException holds a message: '{message}'"
    failure = e2e.FAIL_RE.search(proc.stdout)
    assert failure is not None and failure.group(1).strip() == message, "the log holds the same message"
    expected = args.expect or e2e.EXPECTED.get(name)
    if expected:
        assert expected in message, f"the message names the problem ('{expected}'): '{message}'"
    assert not OUTPUT_RE.search(proc.stdout), "no output values"
    if args.tool and args.set == ["nonDisk=0"]:
        tool_out = os.path.join(args.work, "tool.ply")
        tool = e2e.run_tool(args.tool, args.work, before, tool_out, "square", disk_only=True)
        assert (tool.returncode != 0 and message and core_message(message) in tool.stderr
                and not os.path.exists(tool_out)), (
            f"the lowstretch tool rejects the same mesh with the same message (exit code {tool.returncode}: "
            f"{tool.stderr.strip()[:300]}; the filter's: '{message}')")
    assert lines.get("dataMask before") == lines.get("dataMask after"), \
        f"the data masks are unchanged ({lines.get('dataMask before')} -> {lines.get('dataMask after')})"
    with open(before, "rb") as f1, open(after, "rb") as f2:
        assert f1.read() == f2.read(), "the mesh saved after the failing filter is byte-identical to the one before"
    saved = meshio.read_ply(after)
    assert (not saved.elements["face"].has("texcoord") and not saved.elements["vertex"].has("texture_u")
            and not saved.texture_files()), "it has no texcoords and no texture"


def test_bad(args, bad_case):
    args.mesh, args.generate = bad_case
    run_bad(args)


def test_bad_option(args, bad_option):
    setting, args.expect = bad_option
    args.generate, args.set = "wavy_grid", [setting]
    run_bad(args)


def test_deleted_elements(args, monkeypatch):
    """Deleted (not compacted) elements, interleaved with live ones, as MeshLab's selection and
    delete filters leave them: the result must be exactly that of the mesh without them."""
    vertices, faces, quality = generate.disk_with_flap(16)
    with_flap = os.path.join(args.work, "with_flap.ply")
    meshio.write_ply(with_flap, vertices, faces, quality)
    grid_v, grid_f = generate.wavy_grid(16)
    plain = os.path.join(args.work, "plain.ply")
    meshio.write_ply(plain, grid_v, grid_f, [0.0] * len(grid_v))
    monkeypatch.chdir(args.work)  # the PLY names its texture relative to itself

    out_plain = os.path.join(args.work, "plain_out.ply")
    proc = run_runner(args, plain, os.path.join(args.work, "plain_before.ply"), out_plain, [], "plain.log")
    reference = e2e.check_result(args, "plain.ply", "square", proc, out_plain)

    out_flap = os.path.join(args.work, "with_flap_out.ply")
    proc = run_runner(args, with_flap, os.path.join(args.work, "with_flap_before.ply"), out_flap,
                      ["deleteQualityAbove=0.5"], "with_flap.log")
    deleted = sum(1 for q in quality if q > 0.5)
    assert f"deleted 10 faces, {deleted} vertices" in proc.stdout, \
        f"the runner deleted the flap's 10 faces and {deleted} vertices before the filter ran"
    header = e2e.HEADER_RE.search(proc.stdout)
    assert header is not None and header.groups() == (str(len(grid_v)), str(len(grid_f))), \
        f"the filter saw only the live elements: {header and header.groups()}"
    assert proc.returncode == 0 and os.path.isfile(out_flap), "the filter succeeds after the deletion"
    result = meshio.read_ply(out_flap)
    assert result.vertices() == reference.vertices() and result.faces() == reference.faces(), \
        "same vertices and faces as the mesh without the flap"
    e2e.check_same_output(result, reference, "as the mesh without the flap")
