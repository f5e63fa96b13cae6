"""The tool's files say what its JSON says: `lowstretch MESH -o out.obj --json` and `-o out.ply`,
then the L2 and Linf stretch and the flipped and zero-area triangles recomputed from each file's
texture coordinates (and the PLY's per-face quality) against the JSON's `layout`, the metrics of
the texture coordinates as stored. They agree within 1e-6 relative (the promise is 1e-3): the core
rounds the coordinates to float before measuring, and both files keep every digit of a float.

  python3 -B -m pytest -p no:cacheprovider tests/e2e/test_tool_files.py --tool build/lowstretch \
      [--cgal-meshes DIR] [--shared-meshes DIR] [--basetemp DIR]

test_tool_files[CASE-EXT] (EXT: obj, ply): the CGAL mannequin head, CGAL's head with
`--non-disk charts --boundary natural` (a natural-boundary chart that float rounding flips) and,
when --shared-meshes has them, the shared 180k disk and the closed Max Planck head in charts.
"""
import json
import math
import os
import subprocess
import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import meshio  # noqa: E402
import pytest_options  # noqa: E402
from e2e import rel_diff  # noqa: E402
from stretch_formula import map_linf, map_stretch  # noqa: E402

CHARTS_NATURAL = ["--non-disk", "charts", "--boundary", "natural"]
# case id (the ctest name without tool_files_): (folder option, file, extra tool arguments)
CASES = {
    "cgal_mannequin-devil": ("cgal_meshes", "mannequin-devil.off", []),
    "cgal_head_charts_natural": ("cgal_meshes", "head.off", CHARTS_NATURAL),
    "shared_disk_maxplanck_179730v_loop1": ("shared_meshes", "disk_maxplanck_179730v_loop1.off", []),
    "shared_bad_closed_maxplanck_charts_natural": ("shared_meshes", "bad/bad_closed_maxplanck_5272v.obj", CHARTS_NATURAL),
}


def pytest_generate_tests(metafunc):
    """The cases whose mesh exists (the shared ones are optional), with ids that make the ctest
    names (tests/unit/CMakeLists.txt)."""
    if "case" in metafunc.fixturenames:
        config = metafunc.config
        cases = {}
        for name, (folder, file, extra) in CASES.items():
            root = config.getoption(folder)
            if root and os.path.isfile(os.path.join(root, file)):
                cases[name] = (os.path.join(root, file), extra)
        metafunc.parametrize("case", list(cases.values()), ids=list(cases))
        metafunc.parametrize("ext", ["obj", "ply"])


def test_tool_files(request, tmp_path, case, ext):
    tool = pytest_options.required(request.config, "tool")
    mesh, extra = case
    out = str(tmp_path / ("out." + ext))
    proc = subprocess.run([tool, mesh, "-o", out, "--json"] + extra, capture_output=True, text=True, timeout=900)
    assert proc.returncode == 0, f"{ext}: the tool runs (exit code {proc.returncode}) {proc.stderr[-300:]}"
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
    assert rel_diff(l2, json_l2) <= 1e-6, f"{ext}: L2 stretch of the file {l2:.9g} = the JSON's {json_l2:.9g}"
    if layout["flipped"] + layout["degenerate"] == 0:
        linf = map_linf(vertices, faces, corner_uv)
        assert rel_diff(linf, layout["linf_stretch"]) <= 1e-6, \
            f"{ext}: Linf stretch of the file {linf:.9g} = the JSON's {layout['linf_stretch']:.9g}"
    assert (flipped, zero) == (layout["flipped"], layout["degenerate"]), (
        f"{ext}: flipped and zero-area triangles of the file {(flipped, zero)} = the JSON's "
        f"{(layout['flipped'], layout['degenerate'])}")
    if quality is not None:
        worst = max((rel_diff(q, s) for q, s in zip(quality, sigma) if math.isfinite(s)), default=0.0)
        assert worst <= 1e-6, \
            f"{ext}: per-face quality = face stretch of the file (largest relative difference {worst:.1e})"
