#!/usr/bin/env python3
"""No include runs from a lower layer of filter_lowstretch/ to a higher one.

Layers, lowest first: core, then the atlas stages (base, cut, chart_map, bound, pack, measure,
prepare, search, then atlas/charts.*), then what the tool and both filters share (plugin_common, vcg_arrays), then
the tool and the two MeshLab adapters. Usage: include_layers.py REPOSITORY_ROOT
"""
import pathlib
import re
import sys

LAYERS = ["core", "atlas/base", "atlas/cut", "atlas/chart_map", "atlas/bound", "atlas/pack", "atlas/measure",
          "atlas/prepare", "atlas/search", "atlas", "vcg_arrays", "plugin_common", "tool", "meshlab2020", "meshlab2025"]
# The adapters and the tool sit side by side: none includes another.
SIDE_BY_SIDE = {"tool", "meshlab2020", "meshlab2025"}


def layer_of(path: str) -> str:
    folder = path.rsplit("/", 1)[0] if "/" in path else ""
    return max((l for l in LAYERS if folder == l or folder.startswith(l + "/")), key=len, default="")


def main() -> int:
    source = pathlib.Path(sys.argv[1]) / "filter_lowstretch"
    wrong = []
    files = sorted(p for p in source.rglob("*") if p.suffix in (".h", ".cpp"))
    for path in files:
        own = layer_of(str(path.relative_to(source)))
        for line in path.read_text().splitlines():
            m = re.match(r'\s*#include "([^"]+)"', line)
            if not m or not (source / m.group(1)).exists():
                continue
            theirs = layer_of(m.group(1))
            higher = LAYERS.index(theirs) > LAYERS.index(own)
            beside = own != theirs and own in SIDE_BY_SIDE and theirs in SIDE_BY_SIDE
            if higher or beside:
                wrong.append(f"{path.relative_to(source)} ({own}) includes {m.group(1)} ({theirs})")
    print(f"{len(files)} files checked")
    for w in wrong:
        print("FAIL", w)
    return 1 if wrong else 0


if __name__ == "__main__":
    sys.exit(main())
