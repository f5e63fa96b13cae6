"""Scans get a valid atlas with the tool's default options. TestDefects: tests/bench/make_defects.py
puts fins (non-manifold edges), zero-area slivers, duplicate vertices, dust, holes and collapsed
edges into a closed mesh; TestReconstructions: tests/bench/make_reconstructions.py makes MeshLab's
ball pivoting, VCG and screened Poisson reconstructions and marching cubes on a quantized signed
distance of it (run by --scan-python, a Python with numpy, pymeshlab and scikit-image). For each
file (test_atlas[NAME]; test_fewer_seams_atlas adds --fewer-seams on two defects and on ball
pivoting, on the slivers alone with --scan-size small) `lowstretch FILE -o out.obj --json` must
exit 0, write every input face with texture coordinates inside the gutter, keep charts a gutter
apart (the JSON's least_gutter), and leave no flipped UV triangle and no zero-area one on a face
with 3D area (a face of zero 3D area may have zero UV area, never a negative one), as read back from
the OBJ and as MeshLab's ASCII PLY writer would print it (each coordinate, a float, with 6
decimals); TestPointSets: the same on CGAL's real scanner point sets reconstructed by MeshLab
(tests/bench/make_point_set_scans.py); TestSimulatedMerges: the same on range scans of the closed
mesh simulated and merged by MeshLab's VCG merge (tests/bench/simulate_range_scans.py); the
triangle soup of make_defects.py is refused with the weld message (TestDefects::test_soup_refused).
The closed mesh is CGAL's armadillo (--cgal-meshes), or with --scan-size small its Chinese dragon
(under half the size) and smaller reconstructions of it (make_reconstructions.py --small), for the
sanitizer build.

  python3 -B -m pytest -p no:cacheprovider tests/e2e/test_scan_atlas.py::TestDefects --tool build/lowstretch
  python3 -B -m pytest -p no:cacheprovider tests/e2e/test_scan_atlas.py::TestReconstructions \
      --tool build/lowstretch --scan-python ~/.cache/filter_lowstretch/scan-venv/bin/python
"""
import json
import os
import struct
import subprocess
import sys

import pytest

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import meshio  # noqa: E402
import pytest_options  # noqa: E402

GUTTER = 2 / 1024  # the default gutter over the default texture size
ZERO_AREA = 1e-12  # of the layout's square, as tests/bench/atlas_table.py counts zero-area triangles
# The closed mesh (in --cgal-meshes) and the points sampled on it for the reconstructions, by
# --scan-size: small puts the same defects into a mesh under half the size, for the sanitizer build.
SCAN_SIZES = {"full": ("armadillo.off", []), "small": ("ChineseDragon-10kv.off", ["--small"])}
# CGAL's real scanner point sets (its data/points_3, beside --cgal-meshes) reconstructed by
# tests/bench/make_point_set_scans.py, by --scan-size: the larger ones are for the bench.
POINT_SETS = {"full": ["hippo1.ply", "hippo2.ply", "oni.ply", "kitten.xyz"], "small": ["hippo2.ply"]}
DEFECTS = ["fins", "slivers", "duplicates", "dust", "collapsed", "dropouts", "holes200", "all"]
RECONSTRUCTIONS = ["ball_pivoting", "vcg", "poisson", "sdf_mc"]
# A scanning session of the closed mesh simulated and merged by MeshLab's VCG merge
# (tests/bench/simulate_range_scans.py), by --scan-size: voxel sizes in % of the diagonal, the
# finer with loose sheets and handles as real merges have.
SIMULATED_VOXELS = {"full": ["0.66", "0.3"], "small": ["1"]}
# The scans also mapped with --fewer-seams, by --scan-size: under the sanitizers (small) one run
# covers its code, and each takes minutes there.
FEWER_SEAMS = {"full": ["slivers", "collapsed", "ball_pivoting"], "small": ["slivers"]}


def area3(p, q, r):
    u = [q[k] - p[k] for k in range(3)]
    v = [r[k] - p[k] for k in range(3)]
    c = (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])
    return 0.5 * (c[0] ** 2 + c[1] ** 2 + c[2] ** 2) ** 0.5


def area_uv(a, b, c):
    return 0.5 * ((b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1]))


def as_ascii_ply(uv):
    """A texture coordinate as MeshLab's ASCII PLY writer prints it: the float, with printf's %f."""
    return tuple(float("%f" % struct.unpack("f", struct.pack("f", t))[0]) for t in uv)


def make_scans(python, script, mesh, work, *options):
    """The scans of mesh, written into work by tests/bench/SCRIPT run by python."""
    made = subprocess.run([python, os.path.join(HERE, "..", "bench", script), mesh, str(work), *options],
                          capture_output=True, text=True)
    assert made.returncode == 0, f"{script} writes the meshes ({made.stderr.strip()[-300:]})"
    return work


@pytest.fixture(scope="session")
def tool(request):
    return pytest_options.required(request.config, "tool")


@pytest.fixture(scope="session")
def scan_size(request):
    return SCAN_SIZES[request.config.getoption("scan_size")]


@pytest.fixture(scope="session")
def closed_mesh(request, scan_size):
    return os.path.join(pytest_options.required(request.config, "cgal_meshes"), scan_size[0])


def check_atlas(tool, path, work, options=()):
    name = os.path.basename(path)
    out = os.path.join(work, name[:-4] + "".join(options) + ".obj")
    proc = subprocess.run([tool, path, "-o", out, "--json", *options], capture_output=True, text=True, timeout=900)
    assert proc.returncode == 0, f"{name}: exit 0 ({proc.returncode}: {proc.stderr.strip()[:200]})"
    result = json.loads(proc.stdout)
    layout = result["layout"]
    assert layout["flipped"] == 0 and layout["degenerate"] == 0, \
        f"{name}: the JSON counts no flipped or zero-area triangle ({layout['flipped']}, {layout['degenerate']})"
    assert result["least_gutter"] >= result["gutter"] * (1 - 1e-4), \
        f"{name}: charts a gutter ({result['gutter']} texels) apart and from the border ({result['least_gutter']:.4g})"
    in_vertices, in_faces = meshio.read_off(path)
    _, faces, corners = meshio.read_obj_with_texcoords(out)
    corner_uv = [corners[3 * f:3 * f + 3] for f in range(len(faces))]
    assert [list(f) for f in faces] == [list(f) for f in in_faces], \
        f"{name}: every input face written, as it was ({len(faces)} of {len(in_faces)})"
    assert all(c is not None and GUTTER - 1e-7 <= t <= 1 - GUTTER + 1e-7 for c in corners for t in (c or (0, 0))), \
        f"{name}: every texture coordinate inside the gutter"
    flipped = zero = flat_negative = ascii_invalid = 0
    for f, uv in zip(faces, corner_uv):
        a = area_uv(*uv)
        if area3(*(in_vertices[v] for v in f)) > 0:  # in the input's own coordinates
            flipped += a < 0
            zero += abs(a) <= ZERO_AREA
            ascii_invalid += not area_uv(*(as_ascii_ply(t) for t in uv)) > 0
        else:
            flat_negative += a < 0
    assert flipped == 0 and zero == 0 and flat_negative == 0, (
        f"{name}: no flipped UV triangle ({flipped}), no zero-area one on a face with area ({zero}), no flat face "
        f"flipped ({flat_negative})")
    assert ascii_invalid == 0, \
        f"{name}: no UV triangle on a face with area flipped or collapsed with 6 decimals, as in ASCII PLY ({ascii_invalid})"


def fewer_seams_only_where_listed(request, name):
    size = request.config.getoption("scan_size")
    if name not in FEWER_SEAMS[size]:
        pytest.skip(f"--fewer-seams runs on {', '.join(FEWER_SEAMS[size])} alone with --scan-size {size}")


class TestDefects:
    @pytest.fixture(scope="class")
    def scans(self, tmp_path_factory, closed_mesh):
        return make_scans(sys.executable, "make_defects.py", closed_mesh, tmp_path_factory.mktemp("defects"))

    @pytest.mark.parametrize("name", DEFECTS)
    def test_atlas(self, tool, scans, name):
        check_atlas(tool, str(scans / (name + ".off")), str(scans))

    # Fewer seams refines every chart's map, which must not shrink a sliver's UV triangle to nothing.
    @pytest.mark.parametrize("name", ["slivers", "collapsed"])
    def test_fewer_seams_atlas(self, request, tool, scans, name):
        fewer_seams_only_where_listed(request, name)
        check_atlas(tool, str(scans / (name + ".off")), str(scans), ["--fewer-seams"])

    def test_soup_refused(self, tool, scans):
        out = scans / "soup.obj"
        soup = subprocess.run([tool, str(scans / "soup.off"), "-o", str(out)], capture_output=True, text=True,
                              timeout=900)
        assert soup.returncode == 3 and "not welded" in soup.stderr and not out.exists(), \
            f"soup.off: refused with the weld message, nothing written ({soup.returncode}: {soup.stderr.strip()[:120]})"


class TestPointSets:
    """Real scanner data: CGAL's point sets, reconstructed as MeshLab users do (ball pivoting,
    screened Poisson, the VCG merge)."""

    @pytest.fixture(scope="class")
    def scans(self, request, tmp_path_factory):
        config = request.config
        python = pytest_options.required(config, "scan_python")
        points = os.path.join(os.path.dirname(os.path.abspath(pytest_options.required(config, "cgal_meshes"))), "points_3")
        work = tmp_path_factory.mktemp("point_sets")
        return make_scans(python, "make_point_set_scans.py", points, work, *POINT_SETS[config.getoption("scan_size")])

    def test_atlas(self, tool, scans):
        made = sorted(p for p in os.listdir(scans) if p.endswith(".off"))
        assert len(made) >= 2, f"the point sets are reconstructed ({made})"
        for name in made:
            check_atlas(tool, str(scans / name), str(scans))


class TestReconstructions:
    @pytest.fixture(scope="class")
    def scans(self, request, tmp_path_factory, closed_mesh, scan_size):
        python = pytest_options.required(request.config, "scan_python")
        return make_scans(python, "make_reconstructions.py", closed_mesh, tmp_path_factory.mktemp("reconstructions"),
                          *scan_size[1])

    @pytest.mark.parametrize("name", RECONSTRUCTIONS)
    def test_atlas(self, tool, scans, name):
        check_atlas(tool, str(scans / (name + ".off")), str(scans))

    def test_fewer_seams_atlas(self, request, tool, scans):
        # The largest reconstruction under Fewer seams' face bound (kTuning.most_free_union_faces):
        # its charts are refined and its unions freed at scan size.
        fewer_seams_only_where_listed(request, "ball_pivoting")
        check_atlas(tool, str(scans / "ball_pivoting.off"), str(scans), ["--fewer-seams"])


class TestSimulatedMerges:
    """Range scans of the closed mesh simulated (depth noise, step edges, grazing dropouts, a
    registration slightly off) and merged as real ones are: caps and needles by the thousand,
    vertices close but not equal, loose sheets and handles."""

    @pytest.fixture(scope="class")
    def scans(self, request, tmp_path_factory, closed_mesh):
        python = pytest_options.required(request.config, "scan_python")
        voxels = SIMULATED_VOXELS[request.config.getoption("scan_size")]
        return make_scans(python, "simulate_range_scans.py", closed_mesh, tmp_path_factory.mktemp("simulated"), *voxels)

    def test_atlas(self, request, tool, scans, closed_mesh):
        name = os.path.splitext(os.path.basename(closed_mesh))[0]
        for voxel in SIMULATED_VOXELS[request.config.getoption("scan_size")]:
            check_atlas(tool, str(scans / f"{name}_sim_{voxel}.off"), str(scans))
