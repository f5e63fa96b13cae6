"""The texturing workflow of bake.py as pytest tests: a mesh with the vertex colour pattern,
parameterized by our filter and baked with MeshLab's own filter, against MeshLab's Voronoi atlas
and trivial per-triangle maps baked the same way (bake.py prints the table; bake.check_bake
asserts: every method baked, no out-of-range pixel line for ours, texcoords strictly inside
(0,1), no flipped triangle, colour error at most 3 and no worse than the Voronoi atlas's, and the
texture read upside down far off).

  python3 -B -m pytest -p no:cacheprovider tests/e2e/test_bake.py -k meshlab2020 \
      --prefix build/tests/e2e/prefix --resources resources [--cgal-meshes DIR]
  python3 -B -m pytest -p no:cacheprovider tests/e2e/test_bake.py -k pymeshlab \
      --pymeshlab-plugin build/.../libfilter_lowstretch.so --venv DIR

test_meshlab2020[CASE] (meshlabserver 2020.09, resources/lowstretch_bake.mlx) and
test_pymeshlab[CASE] (pymeshlab 2025.7 in --venv): CASE is hemisphere (generated),
mannequin-devil (CGAL's) or atlas_mannequin-devil (ours as an atlas: Atlas for any mesh).
Each works in its tmp_path.
"""
import argparse
import os
import sys

import pytest

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import bake  # noqa: E402
import pytest_options  # noqa: E402

# case id: (generated disk or None, CGAL mesh or None, --atlas)
CASES = {
    "hemisphere": ("hemisphere", None, False),
    "mannequin-devil": (None, "mannequin-devil.off", False),
    "atlas_mannequin-devil": (None, "mannequin-devil.off", True),
}


@pytest.fixture(params=list(CASES.values()), ids=list(CASES))
def case(request):
    return request.param


def bake_args(config, mode, case, work, **paths):
    generate, mesh, atlas = case
    if mesh:
        mesh = os.path.abspath(os.path.join(pytest_options.required(config, "cgal_meshes"), mesh))
    return argparse.Namespace(mode=mode, generate=generate, mesh=mesh, atlas=atlas, work=str(work), prefix=None,
                              resources=None, plugin=None, venv=None, **paths)


def test_meshlab2020(request, tmp_path, case):
    config = request.config
    args = bake_args(config, "meshlab2020", case, tmp_path)
    args.prefix = os.path.abspath(pytest_options.required(config, "prefix"))
    args.resources = os.path.abspath(pytest_options.required(config, "resources"))
    bake.check_bake(*bake.bake(args))


def test_pymeshlab(request, tmp_path, case):
    config = request.config
    args = bake_args(config, "pymeshlab", case, tmp_path)
    args.plugin = os.path.abspath(pytest_options.required(config, "pymeshlab_plugin"))
    args.venv = os.path.abspath(pytest_options.required(config, "venv"))
    bake.check_bake(*bake.bake(args))
