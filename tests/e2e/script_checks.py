"""The check collector of the scripts that are not pytest tests yet: bake.py (also a tool, run
from README.md) and tool_files.py and scan_atlas.py, whose ctest registration is in
tests/unit/CMakeLists.txt, which passes them script arguments. The end-to-end tests (test_e2e.py, tests/meshlab2025) are pytest tests."""


class Checks:
    """Collects failed checks instead of stopping at the first one."""

    def __init__(self):
        self.failed = []

    def __call__(self, ok, what):
        print(("ok:     " if ok else "FAILED: ") + what)
        if not ok:
            self.failed.append(what)
        return ok
