"""pytest options of the MeshLab 2025.07 tests (test_meshlab2025.py, test_pymeshlab.py); the
shared ones are in tests/e2e/pytest_options.py."""
import os
import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "e2e"))
import pytest  # noqa: E402

pytest.register_assert_rewrite("e2e")
import pytest_options  # noqa: E402


def pytest_addoption(parser):
    pytest_options.add_shared(parser)
    add = pytest_options.add
    add(parser, "--ml2025-runner", help="lowstretch_meshlab2025_runner executable")
    add(parser, "--ml2025-plugin", help="the MeshLab 2025.07 (float) libfilter_lowstretch.so under test")
    add(parser, "--pymeshlab-plugin", help="the pymeshlab (double) build of libfilter_lowstretch.so")
    add(parser, "--venv", help="virtual environment with pymeshlab 2025.7.post1 (.ci/setup-meshlab2025 makes it)")
    add(parser, "--readme", help="README.md whose pymeshlab snippet is run (optional)")
    add(parser, "--build-dir", help="the build tree the snippet's build/ paths refer to (with --readme)")
