#!/usr/bin/env python3
"""The efficiency-against-seam trade-off of our atlas and its peers, drawn as an SVG: one panel per
mesh, texture efficiency (coverage / L2^2, higher is better) on x, seam length over sqrt(area)
(lower is better) on y, both computed by atlas_table.atlas_metrics. Points:
- ours: `lowstretch MESH --atlas` (the default), `--atlas --fewer-seams`, and a line through
  `--atlas --min-efficiency E` for E in MIN_EFFICIENCY, the knob under both;
- xatlas 0.0.11 with its default packer and with its brute-force packer;
- a line through UVAtlas (Open3D 0.20's compute_uvatlas, size 1024) for max_stretch in MAX_STRETCH,
  its default 1/6 ringed.
Also prints a markdown table of every point (charts, efficiency, seam, out/in vertices).

usage: tradeoff.py --tool build/lowstretch [--venv ~/.cache/filter_lowstretch/atlas-venv]
                   --out FILE.svg MESH...

Re-runs itself under atlas_table.py's venv; each peer runs in a child process, so that a native
crash is reported. Exit status 1 when a run failed (its point is left out), else 0.
"""
import argparse
import math
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import atlas_table as at  # noqa: E402

MIN_EFFICIENCY = [1, 0.7, 0.65, 0.6, 0.55, 0.5, 0.45, 0.4]
MAX_STRETCH = [0.05, 0.1, 1 / 6, 0.25, 0.35, 0.5]
# series: legend text, colour, marker, whether a line joins its points
SERIES = {"ours-sweep": ("ours --atlas --min-efficiency E", "#7fa8e0", "circle", True),  # lines first
          "uvatlas": ("UVAtlas, max_stretch S", "#2a9a3a", "circle", True),
          "ours": ("ours --atlas (default)", "#1f5fbf", "diamond", False),
          "ours-fewer": ("ours --atlas --fewer-seams", "#1f5fbf", "square", False),
          "xatlas": ("xatlas, default packer", "#e07b00", "triangle", False),
          "xatlas-bf": ("xatlas, brute-force packer", "#a03000", "tridown", False)}
PW, PH, ML, MR, MT, MB, LEGEND = 380, 330, 55, 30, 30, 42, 250  # panel size, margins, legend width


def uvatlas_worker(stretch, mesh_path, out):
    """Child process: UVAtlas with the given max_stretch, saved like atlas_table.worker's."""
    import numpy as np
    import open3d as o3d
    V, F = at.read_mesh(mesh_path)
    mesh = o3d.t.geometry.TriangleMesh()
    mesh.vertex.positions = o3d.core.Tensor(V.astype(np.float32))
    mesh.triangle.indices = o3d.core.Tensor(F.astype(np.int32))
    mesh.compute_uvatlas(size=1024, max_stretch=float(stretch))
    np.savez(out, faces=F, uv=mesh.triangle.texture_uvs.numpy())


def run_uvatlas(stretch, mesh, V, tmp):
    out = os.path.join(tmp, "uvatlas.npz")
    proc = subprocess.run([sys.executable, os.path.abspath(__file__), "--worker-uvatlas", repr(stretch), mesh, out],
                          capture_output=True, text=True)
    if proc.returncode != 0:
        raise at.ToolFailed(at.status(proc) + (proc.stderr.strip().splitlines() or [""])[-1], failed=True)
    data = at.np.load(out)
    return V, data["faces"], data["uv"]


def runs(tool, mesh, V, tmp):
    """(series, setting, label of the point or "", function giving V, F, corner UV) of every point."""
    ours = lambda *extra: lambda: at.run_ours(tool, mesh, ["--atlas", *extra], tmp)[:3]  # noqa: E731
    yield "ours", "--atlas", "", ours()
    yield "ours-fewer", "--atlas --fewer-seams", "", ours("--fewer-seams")
    for e in MIN_EFFICIENCY:
        yield "ours-sweep", f"--atlas --min-efficiency {e}", f"{e}", ours("--min-efficiency", str(e))
    for name, setting in (("xatlas", "default packer"), ("xatlas-bf", "brute-force packer")):
        yield name, setting, "", (lambda name=name: at.run_peer(name, mesh, V, tmp, None)[:3])
    for s in MAX_STRETCH:
        label = "1/6" if s == 1 / 6 else f"{s:g}"
        yield "uvatlas", f"max_stretch {label}" + (" (default)" if s == 1 / 6 else ""), label, \
            (lambda s=s: run_uvatlas(s, mesh, V, tmp))


def ticks(lo, hi):
    """Round values between lo and hi, 3 to 6 of them."""
    step = 10 ** math.floor(math.log10((hi - lo) / 5))
    step *= next(m for m in (1, 2, 5, 10) if (hi - lo) / (step * m) <= 5)
    return [round(k * step, 10) for k in range(math.ceil(lo / step), math.floor(hi / step) + 1)]


def marker(shape, x, y, colour, r=4.5):
    style = f'fill="{colour}" stroke="black" stroke-width="0.6"'
    if shape == "circle":
        return f'<circle cx="{x:.1f}" cy="{y:.1f}" r="{r * 0.85:.1f}" {style}/>'
    corners = {"square": [(-1, -1), (1, -1), (1, 1), (-1, 1)], "diamond": [(0, -1.4), (1.4, 0), (0, 1.4), (-1.4, 0)],
               "triangle": [(0, -1.3), (1.2, 0.9), (-1.2, 0.9)], "tridown": [(0, 1.3), (1.2, -0.9), (-1.2, -0.9)]}
    points = " ".join(f"{x + r * dx:.1f},{y + r * dy:.1f}" for dx, dy in corners[shape])
    return f'<polygon points="{points}" {style}/>'


def panel(name, points, left):
    """SVG of one mesh's panel, its top left corner at (left, 0)."""
    xs, ys = [p["efficiency"] for p in points], [p["seam"] for p in points]
    (x0, x1), (y0, y1) = [(min(v) - 0.08 * (max(v) - min(v) or 1), max(v) + 0.08 * (max(v) - min(v) or 1))
                          for v in (xs, ys)]
    X = lambda x: left + ML + (x - x0) / (x1 - x0) * (PW - ML - MR)  # noqa: E731
    Y = lambda y: PH - MB - (y - y0) / (y1 - y0) * (PH - MT - MB)  # noqa: E731
    out = [f'<text x="{left + (PW + ML - MR) / 2}" y="18" text-anchor="middle" font-weight="bold">{name}</text>',
           f'<rect x="{left + ML}" y="{MT}" width="{PW - ML - MR}" height="{PH - MT - MB}" fill="none" stroke="black"/>']
    for t in ticks(x0, x1):
        out.append(f'<line x1="{X(t):.1f}" y1="{MT}" x2="{X(t):.1f}" y2="{PH - MB + 4}" stroke="#ddd"/>'
                   f'<text x="{X(t):.1f}" y="{PH - MB + 15}" text-anchor="middle" font-size="10">{t:g}</text>')
    for t in ticks(y0, y1):
        out.append(f'<line x1="{left + ML - 4}" y1="{Y(t):.1f}" x2="{left + PW - MR}" y2="{Y(t):.1f}" stroke="#ddd"/>'
                   f'<text x="{left + ML - 6}" y="{Y(t) + 3:.1f}" text-anchor="end" font-size="10">{t:g}</text>')
    out.append(f'<text x="{left + (PW + ML - MR) / 2}" y="{PH - 8}" text-anchor="middle" font-size="11">'
               'efficiency = coverage / L2² (higher is better)</text>'
               f'<text transform="translate({left + 14},{(PH + MT - MB) / 2}) rotate(-90)" text-anchor="middle" '
               'font-size="11">seam length / √area (lower is better)</text>')
    for key, (_, colour, shape, line) in SERIES.items():
        mine, labels = [p for p in points if p["series"] == key], {}
        if line and len(mine) > 1:
            path = " ".join(f"{X(p['efficiency']):.1f},{Y(p['seam']):.1f}" for p in mine)
            out.append(f'<polyline points="{path}" fill="none" stroke="{colour}" stroke-width="1.2"/>')
        for p in mine:
            x, y = X(p["efficiency"]), Y(p["seam"])
            if "default" in p["setting"] and key == "uvatlas":
                out.append(f'<circle cx="{x:.1f}" cy="{y:.1f}" r="8" fill="none" stroke="black" stroke-width="1.2"/>')
            out.append(marker(shape, x, y, colour))
            if p["label"]:  # points within 6 px share one label
                spot = next((k for k in labels if abs(k[0] - x) < 6 and abs(k[1] - y) < 6), (x, y))
                labels.setdefault(spot, []).append(p["label"])
        for (x, y), text in labels.items():
            dy = 13 if key == "uvatlas" else -5  # UVAtlas's below, ours above
            out.append(f'<text x="{x + 6:.1f}" y="{y + dy:.1f}" font-size="8" fill="#444">{", ".join(text)}</text>')
    return out


def svg(panels):
    width = PW * len(panels) + LEGEND
    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{PH}" font-family="sans-serif">',
           f'<rect width="{width}" height="{PH}" fill="white"/>']
    for k, (name, points) in enumerate(panels):
        out += panel(name, points, k * PW)
    for k, (text, colour, shape, line) in enumerate(SERIES.values()):
        x, y = PW * len(panels) + 20, MT + 20 + 22 * k
        if line:
            out.append(f'<line x1="{x - 10}" y1="{y}" x2="{x + 10}" y2="{y}" stroke="{colour}" stroke-width="1.2"/>')
        out.append(marker(shape, x, y, colour) + f'<text x="{x + 16}" y="{y + 4}" font-size="11">{text}</text>')
    x, y = PW * len(panels) + 20, MT + 20 + 22 * len(SERIES)
    out.append(f'<circle cx="{x}" cy="{y}" r="8" fill="none" stroke="black" stroke-width="1.2"/>'
               f'<text x="{x + 16}" y="{y + 4}" font-size="11">UVAtlas default (S = 1/6)</text>'
               f'<text x="{x - 12}" y="{y + 26}" font-size="9" fill="#444">small numbers: E or S</text>')
    return "\n".join(out + ["</svg>\n"])


def main():
    if len(sys.argv) > 1 and sys.argv[1] == "--worker-uvatlas":
        return uvatlas_worker(*sys.argv[2:5])
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--tool", required=True, help="the lowstretch binary")
    parser.add_argument("--venv", default="~/.cache/filter_lowstretch/atlas-venv")
    parser.add_argument("--out", required=True, help="the SVG to write")
    parser.add_argument("meshes", nargs="+", metavar="MESH")
    args = parser.parse_args()
    venv = os.path.expanduser(args.venv)
    if os.path.realpath(sys.prefix) != os.path.realpath(venv):  # numpy and the peers live in the venv
        python = at.ensure_venv(venv, True)
        os.execv(python, [python, os.path.abspath(__file__), *sys.argv[1:]])
    print("| mesh | method | setting | charts | efficiency | seam | out/in vertices |\n|---|---|---|---|---|---|---|",
          flush=True)
    panels, failed = [], []
    for mesh in args.meshes:
        name, (V, _) = os.path.basename(mesh), at.read_mesh(mesh)
        points = []
        with tempfile.TemporaryDirectory() as tmp:
            for series, setting, label, run in runs(os.path.abspath(args.tool), mesh, V, tmp):
                method = "ours" if series.startswith("ours") else series
                try:
                    m = at.atlas_metrics(*run())
                except at.ToolFailed as failure:
                    print(f"| {name} | {method} | {setting} | failed: {failure} | | | |", flush=True)
                    failed.append(f"{method} {setting} on {name}")
                    continue
                points.append(dict(m, series=series, setting=setting, label=label))
                print(f"| {name} | {method} | {setting} | {m['charts']} | {m['efficiency']:.3f} | {m['seam']:.2f} "
                      f"| {m['out_in']:.2f} |", flush=True)
        if points:
            panels.append((name, points))
    with open(args.out, "w") as f:
        f.write(svg(panels))
    print(f"\nwrote {args.out}", file=sys.stderr)
    if failed:
        print("failed: " + ", ".join(failed), file=sys.stderr)
        sys.exit(1)


if __name__ == "__main__":
    main()
