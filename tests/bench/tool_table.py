"""The command line and loop shared by the table scripts: run `lowstretch MESH FLAGS --json` on
every mesh and print one Markdown row each.

usage of a table script: SCRIPT LOWSTRETCH MESH... [-- EXTRA lowstretch ARGUMENTS]
"""
import json
import os
import subprocess
import sys


def l2(value):
    """A stretch value as the tables print it (JSON null is an infinite stretch)."""
    return "inf" if value is None else f"{value:.4f}"


def print_table(columns, flags, row, rejected_text=lambda stderr: stderr, empty_cells=None):
    """columns: header cells; flags: lowstretch arguments before --json; row(name, json) -> the
    cells of one mesh; a mesh the tool refuses gets rejected_text(stderr) and empty cells."""
    args = sys.argv[1:]
    extra = []
    if "--" in args:
        extra = args[args.index("--") + 1:]
        args = args[:args.index("--")]
    tool, meshes = args[0], args[1:]
    print("| " + " | ".join(columns) + " |")
    print("|" + "---|" * len(columns))
    empty = len(columns) - 2 if empty_cells is None else empty_cells
    for mesh in meshes:
        run = subprocess.run([tool, mesh] + flags + ["--json"] + extra, capture_output=True, text=True)
        name = os.path.basename(mesh)
        if run.returncode != 0:
            print(f"| {name} | rejected: {rejected_text(run.stderr.strip())} |" + "|" * empty)
            continue
        print("| " + " | ".join([name] + row(json.loads(run.stdout))) + " |")
