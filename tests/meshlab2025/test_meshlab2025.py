#!/usr/bin/env python3
"""End-to-end tests of the "Low-stretch parameterization" filter for MeshLab 2025.07's FilterPlugin
API, headless, through lowstretch_meshlab2025_runner (runner.cpp: MeshLab's PluginManager loads the
plugin as pymeshlab does, vcglib reads the mesh, applyFilter, the mesh is saved before and after).
The checks are those of the MeshLab 2020.09 end-to-end tests (tests/e2e/e2e.py, whose check
functions are used here as they are), plus the output values that applyFilter returns.

  test_meshlab2025.py disk    --runner EXE --plugin SO --work DIR --boundary B (--mesh FILE | --generate NAME) [--tool=EXE]
  test_meshlab2025.py bad     --runner EXE --plugin SO --work DIR (--mesh FILE | --generate NAME)
                              [--set NAME=VALUE --expect WORDS] [--tool=EXE]
  test_meshlab2025.py deleted --runner EXE --plugin SO --work DIR [--tool=EXE]

disk: the filter succeeds; the saved PLY has per-wedge texcoords in [0,1]^2 equal to the per-vertex
ones, no flipped or zero-area triangle for Square and Circle, per-vertex and per-face quality equal
to the stretch recomputed from the saved file (and, with --tool, to the lowstretch tool's), the
checkerboard saved next to it; the log holds every pass and the kept pass; the output values are
the kept pass's logged metrics. bad: applyFilter throws MLException with the core's message (also
logged), and the mesh and its data masks are left exactly as they were. deleted: vertices and
faces deleted (not compacted) before the filter give exactly the result of the mesh without them.
"""
import argparse
import math
import os
import re
import subprocess
import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "e2e"))
import e2e  # noqa: E402
import generate  # noqa: E402
import meshio  # noqa: E402

BOUNDARY_INDEX = {"square": 0, "circle": 1, "natural": 2}
PYTHON_NAME = "compute_texcoord_parametrization_low_stretch"
TEXTURE_CLASS = 0x02000  # FilterPlugin::Texture
OUTPUT_RE = re.compile(r"^output: (\w+)=(\S+) \((\w+)\)$", re.M)


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


def check_plugin_line(check, proc):
    plugin = fields(proc).get("plugin", "")
    check(plugin == f"{e2e.FILTER} | {PYTHON_NAME} | {TEXTURE_CLASS}",
          f"PluginManager loads the plugin: '{plugin}' (display name | pymeshlab name | class Texture)")


def check_outputs(check, proc):
    """applyFilter's output values are the kept pass's metrics as the log gives them."""
    outputs = {m[1]: (m[2], m[3]) for m in OUTPUT_RE.finditer(proc.stdout)}
    expected = {"l2_stretch": "double", "linf_stretch": "double", "edge_distortion": "double",
                "angle_distortion": "double", "area_distortion": "double", "flipped": "int", "degenerate": "int",
                "kept_pass": "int", "passes": "int", "initial_l2_stretch": "double", "seconds": "double",
                "charts": "int", "seam_length": "double", "coverage": "double", "efficiency": "double",
                "max_chart_stretch": "double", "subtexel_triangles": "int"}
    if not check({k: t for k, (v, t) in outputs.items()} == expected,
                 f"applyFilter returns the output values {sorted(expected)} with their types"):
        return
    passes, kept = e2e.parse_log(proc.stdout)
    if not passes or kept is None:
        return
    chosen = [p for p in passes if p["pass"] == int(kept.group(1))][0]
    value = {k: float(v) for k, (v, _) in outputs.items()}
    stored = e2e.STORED_RE.search(proc.stdout)
    if not check(stored is not None, "the log has the metrics of the texture coordinates as stored"):
        return
    # The output values describe the stored (float) map: the log's "as stored" line; the kept
    # pass, computed in double, is within the rounding of it.
    same = (e2e.rel_diff(value["l2_stretch"], float(stored.group(1))) <= 1e-5
            and e2e.rel_diff(value["linf_stretch"], float(stored.group(2))) <= 1e-5
            and value["flipped"] == int(stored.group(3)) and value["degenerate"] == int(stored.group(4))
            and e2e.rel_diff(value["coverage"], float(stored.group(5))) <= 1e-4
            and value["subtexel_triangles"] == int(stored.group(6))
            and e2e.rel_diff(value["l2_stretch"], chosen["l2"]) <= 1e-3)
    check(same and value["kept_pass"] == chosen["pass"] and value["passes"] == len(passes)
          and e2e.rel_diff(value["initial_l2_stretch"], passes[0]["l2"]) <= 1e-5,
          f"the output values are the logged metrics of the stored map (kept pass {int(value['kept_pass'])} of "
          f"{int(value['passes'])}, L2 stretch {value['l2_stretch']:.6g}, kept pass's {chosen['l2']:.6g})")


def cmd_disk(args):
    check = e2e.Checks()
    input_path, name = e2e.prepare(args, generate.DISKS)
    before, out = os.path.join(args.work, "before.ply"), os.path.join(args.work, "out.ply")
    # As the 2020.09 scripts: circle and natural disk only, square the default (charts of a non-disk).
    disk_only = ["nonDisk=0"] if args.boundary != "square" else []
    proc = run_runner(args, input_path, before, out, [f"boundaryShape={BOUNDARY_INDEX[args.boundary]}"] + disk_only)
    check_plugin_line(check, proc)
    os.chdir(args.work)  # the PLY names its texture relative to itself
    print("info:   the checks below come from tests/e2e/e2e.py: its 'meshlabserver' is the runner here")
    e2e.check_result(check, args, name, args.boundary, proc, out)
    check_outputs(check, proc)
    return check


def cmd_bad(args):
    check = e2e.Checks()
    input_path, name = e2e.prepare(args, {**generate.BAD, **generate.DISKS})
    before, after = os.path.join(args.work, "before.ply"), os.path.join(args.work, "after.ply")
    if not any(s.startswith("nonDisk=") for s in args.set):  # disk only, unless the test sets it
        args.set = ["nonDisk=0"] + args.set
    proc = run_runner(args, input_path, before, after, args.set)
    lines = fields(proc)
    if not check(proc.returncode == 1 and lines.get("result") == "failed",
                 f"applyFilter throws (exit code {proc.returncode}, result {lines.get('result')})"):
        return check
    message = lines.get("message", "")
    check(bool(message) and not message.startswith("internal error"), f"the MLException holds a message: '{message}'")
    failure = e2e.FAIL_RE.search(proc.stdout)
    check(failure is not None and failure.group(1).strip() == message, "the log holds the same message")
    expected = args.expect or e2e.EXPECTED.get(name)
    if expected:
        check(expected in message, f"the message names the problem ('{expected}')")
    check(not OUTPUT_RE.search(proc.stdout), "no output values")
    if args.tool and args.set == ["nonDisk=0"]:
        tool_out = os.path.join(args.work, "tool.ply")
        tool = e2e.run_tool(args.tool, args.work, before, tool_out, "square", disk_only=True)
        check(tool.returncode != 0 and message and core_message(message) in tool.stderr and not os.path.exists(tool_out),
              f"the lowstretch tool rejects the same mesh with the same message (exit code {tool.returncode}: "
              f"{tool.stderr.strip()[:300]})")
    check(lines.get("dataMask before") == lines.get("dataMask after"),
          f"the data masks are unchanged ({lines.get('dataMask before')} -> {lines.get('dataMask after')})")
    with open(before, "rb") as f1, open(after, "rb") as f2:
        check(f1.read() == f2.read(), "the mesh saved after the failing filter is byte-identical to the one before")
    saved = meshio.read_ply(after)
    check(not saved.elements["face"].has("texcoord") and not saved.elements["vertex"].has("texture_u")
          and not saved.texture_files(), "it has no texcoords and no texture")
    return check


def cmd_deleted(args):
    """Deleted (not compacted) elements, interleaved with live ones, as MeshLab's selection and
    delete filters leave them: the result must be exactly that of the mesh without them."""
    check = e2e.Checks()
    os.makedirs(args.work, exist_ok=True)
    for entry in os.listdir(args.work):
        os.remove(os.path.join(args.work, entry))
    vertices, faces, quality = generate.disk_with_flap(16)
    with_flap = os.path.join(args.work, "with_flap.ply")
    meshio.write_ply(with_flap, vertices, faces, quality)
    grid_v, grid_f = generate.wavy_grid(16)
    plain = os.path.join(args.work, "plain.ply")
    meshio.write_ply(plain, grid_v, grid_f, [0.0] * len(grid_v))
    os.chdir(args.work)

    out_plain = os.path.join(args.work, "plain_out.ply")
    proc = run_runner(args, plain, os.path.join(args.work, "plain_before.ply"), out_plain, [], "plain.log")
    reference = e2e.check_result(check, args, "plain.ply", "square", proc, out_plain)

    out_flap = os.path.join(args.work, "with_flap_out.ply")
    proc = run_runner(args, with_flap, os.path.join(args.work, "with_flap_before.ply"), out_flap,
                      ["deleteQualityAbove=0.5"], "with_flap.log")
    deleted = sum(1 for q in quality if q > 0.5)
    check(f"deleted 10 faces, {deleted} vertices" in proc.stdout,
          f"the runner deleted the flap's 10 faces and {deleted} vertices before the filter ran")
    header = e2e.HEADER_RE.search(proc.stdout)
    check(header is not None and header.groups() == (str(len(grid_v)), str(len(grid_f))),
          f"the filter saw only the live elements: {header and header.groups()}")
    if not check(proc.returncode == 0 and os.path.isfile(out_flap), "the filter succeeds after the deletion"):
        return check
    if reference is None:
        return check
    result = meshio.read_ply(out_flap)
    check(result.vertices() == reference.vertices() and result.faces() == reference.faces(),
          "same vertices and faces as the mesh without the flap")
    for element, props in (("vertex", ("texture_u", "texture_v", "quality")), ("face", ("texcoord", "quality"))):
        for prop in props:
            check(result.elements[element].data.get(prop) == reference.elements[element].data.get(prop),
                  f"same {element} {prop} as the mesh without the flap")
    return check


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("command", choices=("disk", "bad", "deleted"))
    parser.add_argument("--runner", required=True, help="lowstretch_meshlab2025_runner executable")
    parser.add_argument("--plugin", required=True, help="the MeshLab 2025.07 libfilter_lowstretch.so under test")
    parser.add_argument("--work", required=True, help="work folder of this test (emptied first)")
    parser.add_argument("--mesh", help="input mesh file")
    parser.add_argument("--generate", help="name of a generated input mesh")
    parser.add_argument("--boundary", choices=sorted(BOUNDARY_INDEX), default="square")
    parser.add_argument("--tool", default="", help="the lowstretch executable, to compare with (optional)")
    parser.add_argument("--set", action="append", default=[], metavar="NAME=VALUE",
                        help="bad: run the filter with this parameter value (an invalid one)")
    parser.add_argument("--expect", help="bad: words the filter's message must contain")
    args = parser.parse_args()
    args.work = os.path.abspath(args.work)
    if args.mesh and not os.path.isfile(args.mesh):
        print(f"FAILED: input mesh {args.mesh} does not exist")
        return 1
    check = {"disk": cmd_disk, "bad": cmd_bad, "deleted": cmd_deleted}[args.command](args)
    print(f"{len(check.failed)} check(s) failed" if check.failed else "all checks passed")
    return 1 if check.failed else 0


if __name__ == "__main__":
    sys.exit(main())
