#!/usr/bin/env python3
"""Runs a shell example of the README as a user would paste it: the ```sh block right after
`<!-- example: NAME -->`, from a folder laid out like the repository (build/, resources/ and
tests/ are links to the real ones), with the MeshLab prefix under test first on PATH so that
`meshlabserver` loads this build of the plugin. Checks the exit code and the files it must write.

  readme_examples.py --readme README.md --name NAME --build-dir DIR --repo DIR --work DIR
                     [--prefix DIR] [--expect PATH ...]
"""
import argparse
import os
import re
import shutil
import subprocess
import sys


def example(readme, name):
    with open(readme) as f:
        text = f.read()
    found = re.search(rf"<!-- example: {re.escape(name)} -->\s*```sh\n(.*?)```", text, re.S)
    return found.group(1) if found else None


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--readme", required=True)
    parser.add_argument("--name", required=True)
    parser.add_argument("--build-dir", required=True)
    parser.add_argument("--repo", required=True)
    parser.add_argument("--work", required=True)
    parser.add_argument("--prefix", help="a MeshLab prefix whose bin/ goes first on PATH")
    parser.add_argument("--expect", action="append", default=[], help="a file the example writes (relative)")
    args = parser.parse_args()

    script = example(args.readme, args.name)
    if script is None:
        print(f"FAILED: {args.readme} has no ```sh block after <!-- example: {args.name} -->")
        return 1
    shutil.rmtree(args.work, ignore_errors=True)
    os.makedirs(args.work)
    os.symlink(os.path.abspath(args.build_dir), os.path.join(args.work, "build"))
    for folder in ("resources", "tests"):
        os.symlink(os.path.join(os.path.abspath(args.repo), folder), os.path.join(args.work, folder))
    for path in args.expect:
        if os.path.exists(os.path.join(args.work, path)):
            os.remove(os.path.join(args.work, path))  # a file left by an earlier run proves nothing
    env = dict(os.environ)
    if args.prefix:
        env["PATH"] = os.path.join(os.path.abspath(args.prefix), "bin") + os.pathsep + env["PATH"]
    print("$ " + script.replace("\n", "\n$ ").rstrip("$ "))
    proc = subprocess.run(["bash", "-euo", "pipefail", "-c", script], cwd=args.work, env=env,
                          capture_output=True, text=True, errors="replace", timeout=900)
    print(f"exit code {proc.returncode}\n--- stdout ---\n{proc.stdout[-3000:]}\n--- stderr ---\n{proc.stderr[-3000:]}")
    failed = proc.returncode != 0
    for path in args.expect:
        full = os.path.join(args.work, path)
        ok = os.path.isfile(full) and os.path.getsize(full) > 0
        print(("ok:     " if ok else "FAILED: ") + f"the example writes {path}")
        failed |= not ok
    print("FAILED" if failed else "all checks passed")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
