#!/usr/bin/env python3
"""Our atlas against xatlas and UVAtlas side by side, every column computed by one function
(atlas_metrics) from each tool's UV, with the definitions of the reference side-by-side
measurement of xatlas and UVAtlas (listed below).

usage: atlas_table.py --tool build/lowstretch --venv ~/.cache/filter_lowstretch/atlas-venv
                      [--tool-args "--atlas"] [--markdown] [--skip-uvatlas] [--xatlas-brute-force]
                      [--gutter G] [--peer-runs N] [--repeat N] MESH...

xatlas runs with its defaults; --xatlas-brute-force adds a row of xatlas with its brute-force
packer (PackOptions.bruteForce), the slower and tighter one. --repeat N runs our tool N times per
mesh and stops with exit status 1, naming the mesh and mode, if its OBJ files differ (issue 51:
no output depends on time or threads). --peer-runs N runs each peer N times
and gives each of its columns' median: UVAtlas's atlas changes from run to run. Each tool keeps
its own gutter between charts (ours 2 texels of 1024, UVAtlas 1, xatlas none) unless --gutter G
gives all three the same: ours --gutter G, xatlas PackOptions.padding G (whole texels of its about
1024), UVAtlas gutter G.

Re-runs itself under the venv's python (made if missing, with PACKAGES; Open3D also needs Debian's
libusb-1.0-0); each peer runs in a child process, so that a native crash is reported. Columns:
- charts: faces joined through shared UV corners (both ends of a shared 3D edge have equal UV).
- L2, Linf: Sander et al. 2001 stretch, 3D-area weighted, scaled so an isometry up to scale is 1.
- coverage: fraction of a 1024^2 raster of the layout's bounding square covered by UV triangles.
- efficiency: coverage / L2^2 (1 would use every texel with no stretch).
- seam: 3D length of edges whose two faces have different UVs, over sqrt(3D area); boundary
  edges are not seams.
- flips/zero-area: faces against their chart's majority orientation / faces with 3D area whose
  |UV area| <= 1e-12 of the layout square's area (a face of zero 3D area may map to zero area).
The summary line also says whether every input face came back with texture coordinates.
- out/in vertices: distinct (vertex, UV) pairs over the input's used vertices: what the seams cost
  a GPU, which duplicates every vertex on a seam.
- seconds: wall clock (ours: the whole process; peers: the parametrizing call only).
- overlap px: raster pixels whose centre is inside two or more UV triangles.
Exit status 1 when a tool failed (a crash, or an error exit other than our tool's 3, mesh not
usable, which is a rejection), else 0.
"""
import argparse
import os
import shlex
import subprocess
import sys
import tempfile
import time

try:
    import numpy as np
except ImportError:  # the system python: main() re-runs the script under the venv's python
    np = None

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "e2e"))
from meshio import read_obj, read_obj_with_texcoords, read_off, read_ply  # noqa: E402

PACKAGES = ["numpy", "pillow", "xatlas==0.0.11", "open3d-cpu==0.20.0"]
RES = 1024        # raster side, texels
SUB = 256         # UVs snap to 1/256 texel so that the inside tests below are exact integers
CHUNK = 1 << 20   # candidate pixels per vectorized batch (bounds memory)
ZERO_AREA = 1e-12


class ToolFailed(Exception):
    """A tool gave no map: it failed (crash, error), or ours rejected the mesh (failed False)."""
    def __init__(self, message, failed):
        super().__init__(message)
        self.failed = failed


def ensure_venv(venv, need_usb):
    python = os.path.join(venv, "bin", "python")
    if not os.path.exists(python):
        print(f"creating {venv} ({' '.join(PACKAGES)})", file=sys.stderr)
        subprocess.run([sys.executable, "-m", "venv", venv], check=True)
        subprocess.run([python, "-m", "pip", "install", "-q", *PACKAGES], check=True)
    if need_usb and subprocess.run(["dpkg", "-s", "libusb-1.0-0"], capture_output=True).returncode != 0:
        print("libusb-1.0-0 is missing (import open3d needs it): apt-get install -y libusb-1.0-0", file=sys.stderr)
        subprocess.run(["apt-get", "install", "-y", "libusb-1.0-0"], check=True)
    return python


def read_mesh(path):
    """Vertices and triangles of an OFF, OBJ or PLY file; polygons become fans."""
    ext = os.path.splitext(path)[1].lower()
    if ext == ".ply":
        ply = read_ply(path)
        vertices, faces = ply.vertices(), ply.faces()
    else:
        vertices, faces = read_obj(path) if ext == ".obj" else read_off(path)
    tris = [(f[0], f[i], f[i + 1]) for f in faces for i in range(1, len(f) - 1)]
    return np.array(vertices, float), np.array(tris, np.int64).reshape(-1, 3)


def worker(name, mesh_path, out, gutter="none"):
    """Runs one peer on a mesh and saves the input faces it mapped and their per-corner UV; gutter:
    texels between charts, or "none" for the peer's own."""
    V, F = read_mesh(mesh_path)
    if name in ("xatlas", "xatlas-bf"):
        import xatlas
        start = time.perf_counter()
        atlas = xatlas.Atlas()
        atlas.add_mesh(V, F)
        pack = xatlas.PackOptions()
        pack.bruteForce = name == "xatlas-bf"
        if gutter != "none":
            pack.padding = round(float(gutter))
        atlas.generate(pack_options=pack)
        vmapping, indices, uvs = atlas[0]
        seconds = time.perf_counter() - start
        faces, corner_uv = vmapping[indices], uvs[indices]  # xatlas keeps the faces' order and count
    else:
        import open3d as o3d
        mesh = o3d.t.geometry.TriangleMesh()
        mesh.vertex.positions = o3d.core.Tensor(V.astype(np.float32))
        mesh.triangle.indices = o3d.core.Tensor(F.astype(np.int32))
        start = time.perf_counter()
        own = {} if gutter == "none" else {"gutter": float(gutter)}
        mesh.compute_uvatlas(size=1024, **own)  # defaults: gutter 1, max_stretch 1/6
        seconds = time.perf_counter() - start
        faces, corner_uv = F, mesh.triangle.texture_uvs.numpy()
    np.savez(out, faces=faces, uv=corner_uv, seconds=seconds)


def status(proc):
    code = proc.returncode
    return f"(signal {-code}) " if code < 0 else f"(exit {code}) "


def run_peer(name, mesh, V, tmp, gutter):
    out = os.path.join(tmp, name + ".npz")
    proc = subprocess.run([sys.executable, os.path.abspath(__file__), "--worker", name, mesh, out,
                           "none" if gutter is None else str(gutter)],
                          capture_output=True, text=True)
    if proc.returncode != 0:  # the last line of a Python traceback names the error
        raise ToolFailed(status(proc) + (proc.stderr.strip().splitlines() or [""])[-1], failed=True)
    data = np.load(out)
    return V, data["faces"], data["uv"], float(data["seconds"])


class NotRepeatable(Exception):
    """Two runs of our tool on one mesh and mode wrote different files (--repeat)."""


def run_ours(tool, mesh, tool_args, tmp, repeat=1):
    """Our tool's map of the mesh, timed by its first run; with repeat above 1 it runs that many
    times and every run's OBJ must be the first's byte for byte (NotRepeatable otherwise)."""
    out = os.path.join(tmp, "ours.obj")
    first = None
    for run in range(repeat):
        start = time.perf_counter()
        proc = subprocess.run([tool, mesh, "-o", out, "--json", *tool_args], capture_output=True, text=True)
        seconds = time.perf_counter() - start if run == 0 else seconds
        if proc.returncode != 0:  # its first line says why (a usage text may follow); exit 3: mesh not usable
            message = (proc.stderr.strip().splitlines() or [""])[0].split(": ", 2)[-1]
            raise ToolFailed((status(proc) if proc.returncode != 3 else "") + message, failed=proc.returncode != 3)
        with open(out, "rb") as f:
            data = f.read()
        if first is not None and data != first:
            raise NotRepeatable(f"{os.path.basename(mesh)} with {shlex.join(tool_args) or 'the defaults'}: run {run + 1} "
                                "of our tool wrote another OBJ than run 1")
        first = data
    vertices, faces, corner_uv = read_obj_with_texcoords(out)
    return np.array(vertices), np.array(faces).reshape(-1, 3), np.array(corner_uv, float).reshape(-1, 3, 2), seconds


def face_charts(F, uv):
    """Chart label of every face, the pairs of faces sharing a 3D edge, whether each pair is joined
    (equal UV at both ends) and the edge's two vertices. An edge of more than two faces gives a pair
    for each two faces next to each other in sorted order."""
    a, b = F.ravel(), F[:, [1, 2, 0]].ravel()
    ua, ub = uv.reshape(-1, 2), uv[:, [1, 2, 0]].reshape(-1, 2)
    lo, hi = np.minimum(a, b), np.maximum(a, b)
    swap = (a > b)[:, None]
    ulo, uhi = np.where(swap, ub, ua), np.where(swap, ua, ub)
    order = np.lexsort((hi, lo))
    same = (lo[order][1:] == lo[order][:-1]) & (hi[order][1:] == hi[order][:-1])
    i, j = order[:-1][same], order[1:][same]
    joined = (ulo[i] == ulo[j]).all(1) & (uhi[i] == uhi[j]).all(1)
    parent = list(range(len(F)))

    def find(x):
        while parent[x] != x:
            parent[x] = parent[parent[x]]
            x = parent[x]
        return x
    for f, g in zip((i[joined] // 3).tolist(), (j[joined] // 3).tolist()):
        rf, rg = find(f), find(g)
        if rf != rg:
            parent[rf] = rg
    labels = np.unique([find(f) for f in range(len(F))], return_inverse=True)[1]
    return labels, joined, lo[i], hi[i]


def raster_counts(uv, lo, side):
    """How many UV triangles contain each pixel centre of the layout's bounding square. Vertices
    snap to a 1/SUB texel grid and each triangle is made counter-clockwise, so an edge test is an
    exact integer; a centre on an edge belongs to one side only (the edge's owner: going down, or
    going right when horizontal), so neighbours never count it twice."""
    p = np.rint((uv - lo) / side * RES * SUB).astype(np.int64)
    a, b, c = p[:, 0], p[:, 1].copy(), p[:, 2].copy()
    area = (b[:, 0] - a[:, 0]) * (c[:, 1] - a[:, 1]) - (b[:, 1] - a[:, 1]) * (c[:, 0] - a[:, 0])
    b[area < 0], c[area < 0] = p[area < 0, 2], p[area < 0, 1]
    a, b, c = a[area != 0], b[area != 0], c[area != 0]  # a flat triangle covers nothing
    pmin, pmax = np.minimum(np.minimum(a, b), c), np.maximum(np.maximum(a, b), c)
    first = np.clip(-((SUB // 2 - pmin) // SUB), 0, RES)  # the pixels whose centre is in the bounding box
    size = np.maximum(np.clip((pmax - SUB // 2) // SUB, -1, RES - 1) - first + 1, 0)
    count = size[:, 0] * size[:, 1]
    ends, counts, t0 = np.cumsum(count), np.zeros(RES * RES, np.int64), 0
    while t0 < len(count):
        t1 = max(int(np.searchsorted(ends, (ends[t0 - 1] if t0 else 0) + CHUNK, "right")), t0 + 1)
        n = count[t0:t1]
        tri = np.repeat(np.arange(t0, t1), n)
        k = np.arange(n.sum()) - np.repeat(np.cumsum(n) - n, n)
        ix = first[tri, 0] + k % size[tri, 0]
        iy = first[tri, 1] + k // size[tri, 0]
        px, py = ix * SUB + SUB // 2, iy * SUB + SUB // 2
        inside = np.ones(len(tri), bool)
        for s, e in ((a, b), (b, c), (c, a)):
            d = e[tri] - s[tri]
            edge = d[:, 0] * (py - s[tri, 1]) - d[:, 1] * (px - s[tri, 0])
            owner = (d[:, 1] < 0) | ((d[:, 1] == 0) & (d[:, 0] > 0))
            inside &= (edge > 0) | ((edge == 0) & owner)
        counts += np.bincount(iy[inside] * RES + ix[inside], minlength=RES * RES)
        t0 = t1
    return counts


def atlas_metrics(V, F, corner_uv):
    """Every column of the table for a map given per face corner (V: n x 3, F: m x 3 indices into
    V, corner_uv: m x 3 x 2)."""
    uv = np.asarray(corner_uv, float)
    p = V[F]
    e1, e2 = p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]
    area3 = 0.5 * np.linalg.norm(np.cross(e1, e2), axis=1)
    d1, d2 = uv[:, 1] - uv[:, 0], uv[:, 2] - uv[:, 0]
    area_uv = 0.5 * (d1[:, 0] * d2[:, 1] - d2[:, 0] * d1[:, 1])
    # stretch_formula.py's derivatives, vectorized (it loops in Python and calls any face with
    # A_U <= 0 infinite); here a mirrored face keeps its stretch (S_s and S_t only change sign),
    # since peers mirror whole charts: flips counts mirroring, only a zero area is infinite
    with np.errstate(divide="ignore", invalid="ignore"):
        ss = (e1 * d2[:, 1:] - e2 * d1[:, 1:]) / (2 * area_uv[:, None])
        st = (e2 * d1[:, :1] - e1 * d2[:, :1]) / (2 * area_uv[:, None])
        a, b, c = (ss * ss).sum(1), (ss * st).sum(1), (st * st).sum(1)
        big = np.sqrt(0.5 * (a + c + np.sqrt((a - c) ** 2 + 4 * b * b)))
    # a face with no 3D area (a scan's zero-area face) has nothing to stretch: it weighs nothing
    # in L2 and does not count in Linf, whatever its UV
    flat, no_area = area_uv == 0, area3 == 0
    mean_sq, big = np.where(flat, np.inf, 0.5 * (a + c)), np.where(flat, np.inf, big)
    mean_sq, big = np.where(no_area, 0, mean_sq), np.where(no_area, 0, big)
    scale = np.sqrt(np.abs(area_uv).sum() / area3.sum())
    l2 = scale * np.sqrt((area3 * mean_sq).sum() / area3.sum())
    linf = scale * big.max()

    labels, joined, v0, v1 = face_charts(F, uv)
    seam = np.linalg.norm(V[v0[~joined]] - V[v1[~joined]], axis=1).sum() / np.sqrt(area3.sum())
    lo = uv.reshape(-1, 2).min(0)
    side = (uv.reshape(-1, 2).max(0) - lo).max()
    # relative to the layout, so units do not matter; only on faces with 3D area, which need UV area
    zero = (np.abs(area_uv) <= ZERO_AREA * side * side) & (area3 > 0)
    pos = np.bincount(labels, ((area_uv > 0) & ~zero).astype(float))
    neg = np.bincount(labels, ((area_uv < 0) & ~zero).astype(float))
    counts = raster_counts(uv, lo, side)
    coverage = (counts > 0).mean()
    corners = np.column_stack([F.ravel(), uv.reshape(-1, 2)])
    out_vertices = len(np.unique(corners, axis=0)) / len(np.unique(F))
    return {"charts": int(labels.max()) + 1, "out_in": out_vertices, "l2": l2, "linf": linf, "coverage": coverage,
            "efficiency": coverage / l2 ** 2, "seam": seam, "flips": int(np.minimum(pos, neg).sum()),
            "zero": int(zero.sum()), "overlap": int((counts > 1).sum())}


def cells(m):
    return [str(m["charts"]), f"{m['l2']:.3f}", f"{m['linf']:.1f}", f"{m['coverage']:.3f}", f"{m['efficiency']:.3f}",
            f"{m['seam']:.2f}", f"{m['out_in']:.2f}", f"{m['flips']}/{m['zero']}", f"{m['seconds']:.2f}", str(m["overlap"])]


COLUMNS = ["mesh", "V", "method", "charts", "L2", "Linf", "coverage", "efficiency", "seam", "out/in vertices", "flips/zero-area",
           "seconds", "overlap px"]


def summary(name, results):
    """One line: does ours beat the peers' best efficiency, xatlas's seam and UVAtlas's seam, how
    much faster than UVAtlas is it, is it free of flips, zero-area triangles and overlap."""
    ours, uva = results.get("lowstretch"), results.get("uvatlas")
    if not isinstance(ours, dict):
        return f"{name}: lowstretch gave no map"
    yes = {True: "yes", False: "no"}
    best = max([m["efficiency"] for m in results.values() if isinstance(m, dict) and m is not ours] or [0])
    text = f"{name}: efficiency {ours['efficiency']:.3f} >= peers' best {best:.3f}: {yes[ours['efficiency'] >= best]}"
    for peer in ("xatlas", "uvatlas"):
        if isinstance(results.get(peer), dict):
            text += f"; seam {ours['seam']:.2f} <= {peer} {results[peer]['seam']:.2f}: {yes[ours['seam'] <= results[peer]['seam']]}"
    if isinstance(uva, dict):
        text += f"; uvatlas / ours seconds {uva['seconds'] / ours['seconds']:.1f}"
    text += f"; every face written: {yes[ours['missing'] == 0]}"
    return text + f"; flips, zero-area, overlap all zero: {yes[ours['flips'] == ours['zero'] == ours['overlap'] == 0]}"


def column_medians(runs):
    """Each column's median over a peer's runs (UVAtlas gives another atlas from run to run); of an
    even count, the lower middle value."""
    return {key: sorted(run[key] for run in runs)[(len(runs) - 1) // 2] for key in runs[0]}


def run_mesh(mesh, methods, args):
    """The table rows of one mesh, the metrics (or the failure text) of each method, the failures."""
    name, (V_in, F_in) = os.path.basename(mesh), read_mesh(mesh)
    rows, results, failed = [], {}, []
    with tempfile.TemporaryDirectory() as tmp:
        for method in methods:
            try:
                if method == "lowstretch":
                    tool_args = shlex.split(args.tool_args) + ([] if args.gutter is None else ["--gutter", str(args.gutter)])
                    V, F, uv, seconds = run_ours(os.path.abspath(args.tool), mesh, tool_args, tmp, args.repeat)
                    results[method] = dict(atlas_metrics(V, F, uv), seconds=seconds, missing=len(F_in) - len(F))
                else:
                    runs = []
                    for _ in range(args.peer_runs):
                        V, F, uv, seconds = run_peer(method, mesh, V_in, tmp, args.gutter)
                        runs.append(dict(atlas_metrics(V, F, uv), seconds=seconds, missing=len(F_in) - len(F)))
                    results[method] = column_medians(runs)
                row = cells(results[method])
            except ToolFailed as failure:
                results[method] = str(failure)
                row = [("failed " if failure.failed else "rejected: ") + str(failure)] + [""] * 9
                failed += [f"{method} on {name}"] if failure.failed else []
            rows.append(([name, str(len(V_in))] if not rows else ["", ""]) + [method] + row)
            if args.markdown:
                print("| " + " | ".join(rows[-1]) + " |", flush=True)
    return rows, summary(name, results), failed


def main():
    if len(sys.argv) > 1 and sys.argv[1] == "--worker":
        return worker(*sys.argv[2:6])
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--tool", required=True, help="the lowstretch binary")
    parser.add_argument("--venv", default="~/.cache/filter_lowstretch/atlas-venv")
    parser.add_argument("--tool-args", default="--non-disk charts", help="lowstretch arguments (one string)")
    parser.add_argument("--markdown", action="store_true")
    parser.add_argument("--skip-uvatlas", action="store_true", help="UVAtlas takes 1-40 s per mesh")
    parser.add_argument("--ours-only", action="store_true", help="no peers (tuning runs)")
    parser.add_argument("--xatlas-brute-force", action="store_true", help="also xatlas with its brute-force packer")
    parser.add_argument("--peer-runs", type=int, default=1, metavar="N",
                        help="run each peer N times and give each column's median (UVAtlas varies from run to run)")
    parser.add_argument("--gutter", type=float, help="texels between charts for all three tools (default: each its own)")
    parser.add_argument("--repeat", type=int, default=1, metavar="N",
                        help="run our tool N times per mesh and fail, naming the mesh and mode, if its files differ")
    parser.add_argument("meshes", nargs="+", metavar="MESH")
    argv = sys.argv[1:]
    if "--tool-args" in argv[:-1]:  # so that a value starting with "--" is taken as the value
        k = argv.index("--tool-args")
        argv[k:k + 2] = ["--tool-args=" + argv[k + 1]]
    args = parser.parse_args(argv)
    if args.peer_runs < 1 or args.repeat < 1:
        parser.error("--peer-runs and --repeat must be at least 1")
    venv = os.path.expanduser(args.venv)
    if os.path.realpath(sys.prefix) != os.path.realpath(venv):  # numpy and the peers live in the venv
        python = ensure_venv(venv, not args.skip_uvatlas)
        os.execv(python, [python, os.path.abspath(__file__), *sys.argv[1:]])
    peers = ["xatlas"] + (["xatlas-bf"] if args.xatlas_brute_force else []) + ([] if args.skip_uvatlas else ["uvatlas"])
    methods = ["lowstretch"] + ([] if args.ours_only else peers)
    failed, summaries = [], []
    if args.markdown:
        print("| " + " | ".join(COLUMNS) + " |\n|" + "---|" * len(COLUMNS), flush=True)
    for mesh in args.meshes:
        try:
            rows, text, failures = run_mesh(mesh, methods, args)
        except NotRepeatable as difference:
            print(f"not repeatable: {difference}", file=sys.stderr)
            sys.exit(1)
        failed += failures
        summaries.append(text)
        if not args.markdown:
            widths = [max(len(r[k]) for r in [COLUMNS] + rows if k < 3 or r[-1])  # a failure's text runs over
                      for k in range(len(COLUMNS))]
            for r in [COLUMNS] + rows:
                print("  ".join(cell.ljust(w) for cell, w in zip(r, widths)).rstrip())
            print(text + "\n", flush=True)
    if args.markdown:
        print("\n" + "\n".join(summaries))
    if failed:
        print("failed: " + ", ".join(failed), file=sys.stderr)
        sys.exit(1)


if __name__ == "__main__":
    main()
