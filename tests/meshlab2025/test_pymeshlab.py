"""pymeshlab 2025.7 loads the filter. A virtual environment gets pymeshlab==2025.7.post1 from PyPI;
this file, run by that environment's Python (`test_pymeshlab.py --inside ... --output JSON`, no
pytest there), applies the filter and writes what it measured; the pytest tests below assert:
  - the MeshLab 2025.07 (float) build is refused by pymeshlab, whose MeshLab uses double scalars
    (this is why there is a pymeshlab build of the plugin);
  - pymeshlab.load_plugin(<pymeshlab build>) adds compute_texcoord_parametrization_low_stretch;
  - on a real disk (Debian's mannequin head), apply_filter returns the dict of output values (kept
    pass, L2/Linf stretch, distortions, flips, time), the mesh gets per-wedge texcoords 2 texels
    inside [0,1]^2 with no flipped triangle, the L2 stretch recomputed from those texcoords and the
    positions equals the returned one, per-face quality equals the recomputed face stretch, the
    Circle boundary works too, and refinestretch=True lowers the stretch without a flip;
  - on a mesh that is not a disk (head.off) it raises PyMeshLabException with the core's message
    in disk-only mode, and the mesh is unchanged; by default it gets charts; the atlas mode cuts;
    repackonly=True packs that atlas again at another size and gutter, its charts kept, and
    raises on a mesh without texcoords;
  - with --readme: the README's Python snippet (the ```python block that calls
    pymeshlab.load_plugin), run as written from a folder whose build/ is this build tree.

  python3 -B -m pytest -p no:cacheprovider tests/meshlab2025/test_pymeshlab.py --pymeshlab-plugin SO \
      --ml2025-plugin SO --venv DIR [--cgal-meshes DIR] [--readme README.md --build-dir DIR]

venv_python() is also used by tests/e2e/bake.py.
"""
import argparse
import json
import math
import os
import re
import subprocess
import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "e2e"))
from stretch_formula import map_stretch  # noqa: E402
from uv_charts import uv_charts  # noqa: E402

PYMESHLAB = "pymeshlab==2025.7.post1"
NAME = "compute_texcoord_parametrization_low_stretch"
GUTTER = 2 / 1024  # the default gutter (texels) over the default texture size: where UV stays
KEYS = {"l2_stretch": float, "linf_stretch": float, "edge_distortion": float, "angle_distortion": float,
        "area_distortion": float, "flipped": int, "degenerate": int, "kept_pass": int, "passes": int,
        "initial_l2_stretch": float, "seconds": float, "charts": int, "seam_length": float, "coverage": float,
        "efficiency": float, "max_chart_stretch": float, "least_gutter": float, "subtexel_triangles": int,
        "float_collapsed": int}
DISK, BAD, EXPECT = "mannequin-devil.off", "head.off", "3 boundary loops"  # in --cgal-meshes
# How the atlas of BAD is saved: name, file, binary (None: OBJ).
SAVED = [("ascii_ply", "atlas_ascii.ply", False), ("binary_ply", "atlas_binary.ply", True), ("obj", "atlas.obj", None)]


def venv_python(venv):
    """The environment's Python, which must have pymeshlab 2025.7.post1: .ci/setup-meshlab2025
    installs it (~/.cache/filter_lowstretch/scan-venv); a test only uses it, never installs."""
    python = os.path.join(venv, "bin", "python")
    have = subprocess.run([python, "-m", "pip", "show", "pymeshlab"], capture_output=True,
                          text=True).stdout if os.path.isfile(python) else ""
    if "Version: 2025.7.post1" not in have:
        raise RuntimeError(f"{venv} has no {PYMESHLAB}: run `bash .ci/setup-meshlab2025`, which installs it")
    return python


# ---------------------------------------------------------------------------------------------
# Inside the virtual environment (numpy and pymeshlab, no pytest): measure, write JSON.

def stretch(np, V, F, wedge_uv):
    """stretch_formula.map_stretch (the Python tests' one stretch) over numpy arrays, as arrays."""
    area_u, sigma, l2, area = map_stretch(V.tolist(), F.tolist(), wedge_uv.tolist())
    return np.array(area_u), np.array(sigma), l2, np.array(area)


def texcoord_facts(np, m):
    """Wedge texcoords of the current mesh: shape, range, flipped/zero/non-positive UV triangles,
    L2 stretch recomputed from them; and the face stretch (for the quality)."""
    if not m.has_wedge_tex_coord():
        return {"has": False}, None
    V, F = m.vertex_matrix(), m.face_matrix()
    wtc = m.wedge_tex_coord_matrix().astype(np.float64)
    area_u, sigma, l2, area = stretch(np, V, F, wtc)
    return {"has": True, "shape": list(wtc.shape), "faces": len(F), "min": float(wtc.min()), "max": float(wtc.max()),
            "flipped": int((area_u < 0).sum()), "zero": int((area_u == 0).sum()),
            "non_positive": int((area_u <= 0).sum()), "l2": l2}, (sigma, area)


def inside(args):
    import numpy as np
    import pymeshlab

    facts = {"pymeshlab": pymeshlab.__file__}
    try:
        pymeshlab.load_plugin(args.float_plugin)
        facts["float_refused"] = None
    except pymeshlab.PyMeshLabException as e:
        facts["float_refused"] = str(e)

    pymeshlab.load_plugin(args.plugin)
    facts["listed"] = NAME in pymeshlab.filter_list()

    ms = pymeshlab.MeshSet()
    ms.load_new_mesh(args.disk)
    out = ms.apply_filter(NAME)
    facts["out_is_dict"] = isinstance(out, dict)
    facts["out"] = out
    facts["out_types"] = {k: type(v).__name__ for k, v in out.items()}
    m = ms.current_mesh()
    facts["square"], face = texcoord_facts(np, m)
    facts["has_face_scalar"] = m.has_face_scalar()
    if face is not None and m.has_face_scalar():
        # The quality, the dict and the texcoords all describe the stored map.
        sigma, area = face
        q = m.face_scalar_array()
        facts["quality_rel_max"] = float((np.abs(q - sigma) / np.maximum(sigma, 1e-30)).max())
        facts["quality_l2"] = float(np.sqrt((area * q ** 2).sum() / area.sum()))
    facts["has_vertex_scalar"] = m.has_vertex_scalar()
    facts["texture_number"] = m.texture_number()
    facts["textures"] = str(m.textures()) if hasattr(m, "textures") else ""

    ms.load_new_mesh(args.disk)
    facts["circle"] = ms.apply_filter(NAME, boundaryshape="Circle", maxpasses=3)

    ms.load_new_mesh(args.disk)
    facts["refined"] = ms.apply_filter(NAME, refinestretch=True)
    facts["refined_uv"] = texcoord_facts(np, ms.current_mesh())[0]

    ms.load_new_mesh(args.bad)
    m = ms.current_mesh()
    before = (m.vertex_matrix().copy(), m.face_matrix().copy())
    try:
        ms.apply_filter(NAME, nondisk="Reject")
        facts["bad_raised"] = None
    except pymeshlab.PyMeshLabException as e:
        facts["bad_raised"] = str(e)
    m = ms.current_mesh()
    facts["bad_unchanged"] = bool((m.vertex_matrix() == before[0]).all() and (m.face_matrix() == before[1]).all())
    facts["bad_has_wedge"] = m.has_wedge_tex_coord()

    facts["charts"] = ms.apply_filter(NAME)
    facts["charts_uv"] = texcoord_facts(np, ms.current_mesh())[0]
    # The atlas saved as users save it: ASCII and binary PLY, OBJ (read back by the tests).
    facts["saved"] = {}
    for name, file_name, binary in SAVED:
        path = os.path.join(os.path.dirname(os.path.abspath(args.output)), file_name)
        if binary is None:
            ms.save_current_mesh(path)
        else:
            ms.save_current_mesh(path, binary=binary)
        facts["saved"][name] = path

    # The atlas of the disk, cut where it stretches more than 1.1, at another texture size.
    ms.load_new_mesh(args.disk)
    facts["atlas"] = ms.apply_filter(NAME, nondisk="Atlas for any mesh", maxstretch=1.1, texturesize=512, gutter=3)
    facts["atlas_uv"] = texcoord_facts(np, ms.current_mesh())[0]
    # The pack stage alone: that atlas packed again for 2048 texels and an 8-texel gutter.
    F = ms.current_mesh().face_matrix().tolist()

    def triangles(m):
        wedges = m.wedge_tex_coord_matrix().tolist()
        return [wedges[3 * f:3 * f + 3] for f in range(len(F))]

    atlas_charts = uv_charts(F, triangles(ms.current_mesh()))
    facts["repacked"] = ms.apply_filter(NAME, repackonly=True, texturesize=2048, gutter=8)
    facts["repacked_uv"] = texcoord_facts(np, ms.current_mesh())[0]
    facts["repacked_same_charts"] = uv_charts(F, triangles(ms.current_mesh())) == atlas_charts
    ms.load_new_mesh(args.disk)  # no texcoords: nothing to pack again
    try:
        ms.apply_filter(NAME, repackonly=True)
        facts["repack_raised"] = None
    except pymeshlab.PyMeshLabException as e:
        facts["repack_raised"] = str(e)
    facts["repack_refused_has_wedge"] = ms.current_mesh().has_wedge_tex_coord()
    with open(args.output, "w") as f:
        json.dump(facts, f, indent=1)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--inside", action="store_true", required=True, help="measure (in the pymeshlab venv)")
    parser.add_argument("--plugin", required=True, help="the pymeshlab (double) build of libfilter_lowstretch.so")
    parser.add_argument("--float-plugin", required=True, help="the MeshLab 2025.07 (float) build")
    parser.add_argument("--disk", required=True, help="a disk mesh (OFF)")
    parser.add_argument("--bad", required=True, help="a mesh that is not a disk (OFF)")
    parser.add_argument("--output", required=True, help="the JSON file of what was measured")
    inside(parser.parse_args())
    return 0


if __name__ == "__main__":
    sys.exit(main())


# ---------------------------------------------------------------------------------------------
# The pytest tests (outside the environment).

try:
    import pytest
except ImportError:  # the environment's Python runs this file with --inside only
    pytest = None

if pytest is not None:
    import pytest_options

    @pytest.fixture(scope="module")
    def python(request):
        venv = pytest_options.required(request.config, "venv")
        return venv_python(venv)

    @pytest.fixture(scope="module")
    def facts(request, python, tmp_path_factory):
        config = request.config
        cgal = config.getoption("cgal_meshes")
        work = tmp_path_factory.mktemp("inside")
        output = work / "facts.json"
        proc = subprocess.run([python, os.path.abspath(__file__), "--inside",
                               "--plugin", pytest_options.required(config, "pymeshlab_plugin"),
                               "--float-plugin", pytest_options.required(config, "ml2025_plugin"),
                               "--disk", os.path.join(cgal, DISK), "--bad", os.path.join(cgal, BAD),
                               "--output", str(output)], cwd=work, capture_output=True, text=True, timeout=900)
        print(proc.stdout + proc.stderr)
        assert proc.returncode == 0 and output.is_file(), \
            f"the measures in the pymeshlab environment run (exit code {proc.returncode}): {proc.stderr[-1500:]}"
        result = json.loads(output.read_text())
        print(f"        {json.dumps(result['out'])}")
        return result


def test_float_build_is_refused(facts):
    assert facts["float_refused"] is not None, "pymeshlab refuses the float (MeshLab 2025.07) build"
    assert "different floating point precision" in facts["float_refused"], \
        f"pymeshlab refuses the float (MeshLab 2025.07) build: '{facts['float_refused']}'"


def test_load_plugin_adds_the_filter(facts):
    assert facts["listed"], f"load_plugin adds {NAME} to pymeshlab.filter_list()"


def test_output_values(facts):
    out = facts["out"]
    assert facts["out_is_dict"] and set(out) == set(KEYS) and all(
        facts["out_types"][k] == t.__name__ for k, t in KEYS.items()), \
        f"apply_filter returns a dict of {len(KEYS)} output values with their types: {facts['out_types']}"
    assert out["flipped"] == 0 and out["degenerate"] == 0, "no flipped or degenerate triangle (square)"
    assert 1 <= out["l2_stretch"] < out["initial_l2_stretch"] and 0 <= out["kept_pass"] < out["passes"], (
        f"L2 stretch {out['l2_stretch']:.6g} < initial {out['initial_l2_stretch']:.6g}, kept pass "
        f"{out['kept_pass']} of {out['passes']}")


def test_wedge_texcoords(facts):
    uv = facts["square"]
    assert uv["has"], "the mesh has per-wedge texcoords"
    assert uv["shape"] == [3 * uv["faces"], 2] and uv["min"] >= GUTTER - 1e-6 and uv["max"] <= 1 - GUTTER + 1e-6, \
        f"wedge texcoords: shape {uv['shape']} (3 x {uv['faces']} faces), range [{uv['min']:.6g}, {uv['max']:.6g}]"
    assert uv["non_positive"] == 0, \
        f"no flipped or zero-area triangle in the texcoords ({uv['flipped']} flipped, {uv['zero']} zero)"
    out = facts["out"]
    assert abs(uv["l2"] - out["l2_stretch"]) <= 1e-9 * out["l2_stretch"], \
        f"L2 stretch recomputed from the wedge texcoords {uv['l2']:.6g} = returned {out['l2_stretch']:.6g}"


def test_quality(facts):
    assert facts["square"]["has"], "the mesh has per-wedge texcoords"
    assert facts["has_face_scalar"], "the mesh has per-face quality"
    assert facts["quality_rel_max"] <= 1e-6, (f"per-face quality = face stretch recomputed from the texcoords "
                                              f"(largest relative difference {facts['quality_rel_max']:.1e})")
    l2 = facts["out"]["l2_stretch"]
    assert abs(facts["quality_l2"] - l2) <= 1e-9 * l2, \
        f"sqrt(sum A q^2 / sum A) over the per-face quality {facts['quality_l2']:.10g} = returned L2 stretch {l2:.10g}"
    assert facts["has_vertex_scalar"], "the mesh has per-vertex quality"


def saved_triangles(path):
    """Vertices, faces and each face's UV triangle, as the file holds them (PLY wedges or OBJ vt)."""
    import meshio
    if path.endswith(".obj"):
        vertices, faces, corners = meshio.read_obj_with_texcoords(path)
        return vertices, faces, [tuple(corners[3 * f:3 * f + 3]) for f in range(len(faces))]
    ply = meshio.read_ply(path)
    texcoords = ply.elements["face"].data["texcoord"]
    return ply.vertices(), ply.faces(), [((t[0], t[1]), (t[2], t[3]), (t[4], t[5])) for t in texcoords]


@pytest.mark.parametrize("saved", [s[0] for s in SAVED])
def test_saved_atlas(facts, saved):
    """The atlas of a mesh with holes (seams), saved by pymeshlab as ASCII PLY, binary PLY and OBJ:
    in every file, every face of positive 3D area has a counter-clockwise UV triangle of positive
    area (MeshLab's ASCII PLY writer takes per-vertex texcoords for the wedges when a mesh has
    them: the filter leaves none on an atlas)."""
    assert facts["charts"]["seam_length"] > 0, "the mesh is cut into charts (seams)"
    vertices, faces, triangles = saved_triangles(facts["saved"][saved])
    assert len(faces) == facts["charts_uv"]["faces"] and all(None not in t for t in triangles), \
        "every face is saved with its wedge texcoords"
    area3 = [math.dist((0, 0, 0), cross(vertices[f[0]], vertices[f[1]], vertices[f[2]])) for f in faces]
    area_uv = [(b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1]) for a, b, c in triangles]
    bad = sum(1 for a3, au in zip(area3, area_uv) if a3 > 0 and not au > 0)
    assert bad == 0, f"no flipped or zero-area UV triangle in the {saved} file ({bad} of {len(faces)})"


def cross(p, q, r):
    u, v = [q[k] - p[k] for k in range(3)], [r[k] - p[k] for k in range(3)]
    return (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])


def test_texture(facts):
    assert facts["square"]["has"], "the mesh has per-wedge texcoords"
    assert facts["texture_number"] == 1, f"one texture (the checkerboard): {facts['textures']}"


def test_circle(facts):
    circle = facts["circle"]
    assert circle["flipped"] == 0 and circle["passes"] <= 4, (
        f"boundaryshape='Circle', maxpasses=3: L2 stretch {circle['l2_stretch']:.6g}, {circle['passes']} passes, "
        f"no flip")


def test_refine_stretch(facts):
    refined, uv, out = facts["refined"], facts["refined_uv"], facts["out"]
    assert uv["has"], "the refined mesh has per-wedge texcoords"
    l2 = uv["l2"]
    assert (refined["l2_stretch"] < 0.99 * out["l2_stretch"] and refined["flipped"] + refined["degenerate"] == 0
            and uv["non_positive"] == 0 and abs(l2 - refined["l2_stretch"]) <= 1e-9 * l2), (
        f"refinestretch=True lowers the L2 stretch from {out['l2_stretch']:.6g} to {refined['l2_stretch']:.6g} "
        f"(recomputed from the texcoords {l2:.6g}), no flip")


def test_non_disk_is_rejected_unchanged(facts):
    raised = facts["bad_raised"]
    assert raised is not None, "a mesh that is not a disk raises PyMeshLabException in disk-only mode"
    assert EXPECT in raised, (f"a mesh that is not a disk raises PyMeshLabException naming the problem "
                              f"('{EXPECT}'): '{' / '.join(raised.splitlines())}'")
    assert facts["bad_unchanged"] and not facts["bad_has_wedge"], "that mesh is unchanged and has no texcoords"


def test_non_disk_gets_charts_by_default(facts):
    charts, uv = facts["charts"], facts["charts_uv"]
    print(f"        default (nondisk='Make charts'): {json.dumps(charts)}")
    assert (set(charts) == set(KEYS) and charts["charts"] >= 1 and charts["flipped"] == 0
            and charts["degenerate"] == 0 and 0 < charts["coverage"] <= 1), (
        f"by default it is parameterized as charts: {charts['charts']} charts, coverage {charts['coverage']:.4g}, no flip")
    assert uv["has"], "it now has per-wedge texcoords"
    assert (uv["shape"] == [3 * uv["faces"], 2] and uv["min"] >= GUTTER - 1e-6 and uv["max"] <= 1 - GUTTER + 1e-6
            and uv["non_positive"] == 0), (
        f"wedge texcoords 2 texels of 1024 inside [0,1]^2, no flipped or zero-area triangle ({uv['non_positive']})")


def test_atlas(facts):
    """The atlas of the disk, cut where it stretches more than 1.1, at another texture size."""
    atlas, uv, out = facts["atlas"], facts["atlas_uv"], facts["out"]
    assert uv["has"], "the atlas has per-wedge texcoords"
    l2 = uv["l2"]
    assert (set(atlas) == set(KEYS) and atlas["charts"] > 1 and abs(l2 - atlas["l2_stretch"]) <= 1e-9 * l2
            and abs(atlas["efficiency"] - atlas["coverage"] / l2 ** 2) <= 1e-9 * atlas["efficiency"]
            and atlas["efficiency"] > out["coverage"] / out["l2_stretch"] ** 2), (
        f"nondisk='Atlas for any mesh', maxstretch=1.1: {atlas['charts']} charts, L2 stretch {atlas['l2_stretch']:.6g} "
        f"(recomputed {l2:.6g}), efficiency {atlas['efficiency']:.4g} = coverage / L2^2, above the single chart's "
        f"{out['coverage'] / out['l2_stretch'] ** 2:.4g}")
    assert uv["min"] >= 3 / 512 - 1e-6 and uv["max"] <= 1 - 3 / 512 + 1e-6 and uv["non_positive"] == 0, (
        f"the atlas stays 3 texels of 512 inside [0,1]^2 ({uv['min']:.6g}, {uv['max']:.6g}), no flipped or "
        f"zero-area triangle")


def test_repack(facts):
    """The pack stage alone (repackonly=True): the disk's atlas packed again for 2048 texels and an
    8-texel gutter keeps its charts, stays 8 texels inside, no flipped triangle; a mesh without
    texcoords raises with what to do and stays without."""
    atlas, repacked, uv = facts["atlas"], facts["repacked"], facts["repacked_uv"]
    assert repacked["charts"] == atlas["charts"] and facts["repacked_same_charts"], (
        f"the same charts: {repacked['charts']} of {atlas['charts']}, same faces in each: {facts['repacked_same_charts']}")
    assert uv["min"] >= 8 / 2048 - 1e-6 and uv["max"] <= 1 - 8 / 2048 + 1e-6 and uv["non_positive"] == 0, (
        f"8 texels of 2048 inside [0,1]^2 ({uv['min']:.6g}, {uv['max']:.6g}), no flipped or zero-area triangle")
    assert abs(uv["l2"] - repacked["l2_stretch"]) <= 1e-9 * uv["l2"], "the returned L2 stretch is the stored map's"
    raised = facts["repack_raised"]
    assert raised is not None and "no atlas to pack again" in raised and not facts["repack_refused_has_wedge"], (
        f"a mesh without texcoords raises and is unchanged: {raised}")


def test_readme_snippet(request, python, tmp_path):
    readme, build_dir = request.config.getoption("readme"), request.config.getoption("build_dir")
    if not (readme and build_dir):
        pytest.skip("no --readme and --build-dir")
    with open(readme) as f:
        blocks = re.findall(r"```python\n(.*?)```", f.read(), re.S)
    snippet = [b for b in blocks if "pymeshlab.load_plugin" in b]
    assert snippet, f"{readme} has a ```python block calling pymeshlab.load_plugin"
    folder = tmp_path / "readme"
    folder.mkdir()
    os.symlink(os.path.abspath(build_dir), folder / "build")
    (folder / "snippet.py").write_text(snippet[0])
    proc = subprocess.run([python, "snippet.py"], cwd=folder, capture_output=True, text=True, timeout=600)
    print("        README snippet output:\n" + "".join("        | " + line + "\n" for line in proc.stdout.splitlines()))
    assert proc.returncode == 0, f"the README's Python snippet runs (exit code {proc.returncode}) {proc.stderr[-500:]}"
