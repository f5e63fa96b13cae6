"""pytest options of the MeshLab 2020.09 end-to-end tests (test_e2e.py); see pytest_options.py."""
import os
import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import pytest  # noqa: E402

pytest.register_assert_rewrite("e2e")
import pytest_options  # noqa: E402


def pytest_addoption(parser):
    pytest_options.add_shared(parser)
    pytest_options.add(parser, "--prefix", help="the private MeshLab 2020.09 prefix made by `e2e.py prefix`")
    pytest_options.add(parser, "--resources", help="the repository's resources/ folder (the .mlx scripts)")
    pytest_options.add(parser, "--runner", help="lowstretch_plugin_runner executable")
    pytest_options.add(parser, "--plugin", help="the MeshLab 2020.09 libfilter_lowstretch.so under test")
