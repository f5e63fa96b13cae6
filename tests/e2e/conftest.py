"""pytest options of the tests of this folder: the MeshLab 2020.09 end-to-end tests (test_e2e.py),
the tool's files and scans (test_tool_files.py, test_scan_atlas.py) and the bake (test_bake.py);
see pytest_options.py."""
import os
import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import pytest  # noqa: E402

pytest.register_assert_rewrite("e2e", "bake")
import pytest_options  # noqa: E402


def pytest_addoption(parser):
    pytest_options.add_shared(parser)
    pytest_options.add(parser, "--prefix", help="the private MeshLab 2020.09 prefix made by `e2e.py prefix`")
    pytest_options.add(parser, "--resources", help="the repository's resources/ folder (the .mlx scripts)")
    pytest_options.add(parser, "--runner", help="lowstretch_plugin_runner executable")
    pytest_options.add(parser, "--plugin", help="the MeshLab 2020.09 libfilter_lowstretch.so under test")
    pytest_options.add(parser, "--scan-python", help="test_scan_atlas.py TestReconstructions: a Python with numpy, "
                       "pymeshlab and scikit-image (~/.cache/filter_lowstretch/scan-venv/bin/python)")
    pytest_options.add(parser, "--scan-size", default="full", choices=["full", "small"],
                       help="test_scan_atlas.py: full (the armadillo) or small (the same defects and "
                       "reconstructions of a smaller mesh, for the sanitizer build)")
    # test_bake.py's pymeshlab tests (the same options as tests/meshlab2025/conftest.py's)
    pytest_options.add(parser, "--pymeshlab-plugin", help="the pymeshlab (double) build of libfilter_lowstretch.so")
    pytest_options.add(parser, "--venv", help="virtual environment with pymeshlab 2025.7.post1 (.ci/setup-meshlab2025 makes it)")
