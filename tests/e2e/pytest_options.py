"""Command-line options and mesh lists shared by the pytest tests of tests/e2e and
tests/meshlab2025 (each folder's conftest.py adds them; CMake passes them as it passed the
scripts' arguments before). An option already added by the other folder's conftest, when both
folders run in one pytest session, is not added twice."""
import glob
import os


def add(parser, name, **kwargs):
    try:
        parser.getgroup("lowstretch").addoption(name, **kwargs)
    except ValueError:  # already added by the other folder's conftest.py
        pass


def add_shared(parser):
    add(parser, "--tool", default="", help="the lowstretch executable, to compare with (optional)")
    add(parser, "--cgal-meshes", default=os.path.expanduser("~/.cache/filter_lowstretch/cgal-data/data/meshes"),
        help="folder of Debian's libcgal-demo meshes (mannequin-devil.off, ...)")
    add(parser, "--shared-meshes", default="", help="the optional ../shared/meshes folder (skipped when absent)")


def shared(config, *patterns):
    """(name without extension, path) of the files of --shared-meshes matching the patterns, sorted
    by path and without repeats, as CMake's file(GLOB) and NAME_WE give them."""
    folder = config.getoption("shared_meshes")
    if not folder or not os.path.isdir(folder):
        return []
    paths = sorted({p for pattern in patterns for p in glob.glob(os.path.join(folder, pattern))})
    return [(os.path.basename(p).split(".")[0], p) for p in paths]


def required(config, name):
    """The value of an option a test cannot run without."""
    value = config.getoption(name)
    assert value, f"give --{name.replace('_', '-')}"
    return value
