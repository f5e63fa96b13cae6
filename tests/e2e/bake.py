#!/usr/bin/env python3
"""The texturing workflow as MeshLab users run it: parameterize a mesh that has vertex colours,
then bake the colours into a texture with MeshLab's own filter, and check the texture.

  bake.py meshlab2020 --prefix DIR --resources DIR --mesh OFF|--generate NAME --work DIR
      meshlabserver 2020.09: resources/lowstretch_bake.mlx (Low-stretch parameterization, then
      Transfer: Vertex Color to Texture) in one run; MeshLab's Voronoi atlas and trivial
      per-triangle parameterizations baked the same way, for comparison.
  bake.py pymeshlab --plugin SO --venv DIR --mesh OFF|--generate NAME --work DIR
      pymeshlab 2025.7: the same three, with compute_texmap_from_color.
  --atlas: our filter makes an atlas (Non-disk input: Atlas for any mesh), cut where the map
      stretches more than Max chart stretch, instead of the disk's single chart.
  bake.py colour --mesh OFF --output PLY
      only gives the mesh the colour pattern (a stand-in for a scan's colours; the README uses it).
meshlab2020 and pymeshlab print the table, then check ours (exit code 1 when a check fails); the
ctest tests run the same through pytest (test_bake.py).

For every method the baked texture is sampled at four points of every face (its centroid and
halfway from it to each corner), at the texel that the wedge texcoords address, and compared
with the vertex colours interpolated there: the colour error is the RMS over the surface (3D
area) of the per-channel difference, in 0-255 units. Checks for ours: no "out of range" pixel
warning, no flipped UV triangle, colour error below a bound and no worse than the Voronoi atlas's.
"""
import argparse
import math
import os
import re
import subprocess
import sys
import xml.etree.ElementTree as ET

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import e2e  # noqa: E402
import generate  # noqa: E402
import meshio  # noqa: E402
from stretch_formula import map_stretch  # noqa: E402

SIZE = 1024                 # texture side, as the .mlx and the filter's Texture size say
ERROR_BOUND = 3.0           # colour error (RMS, 0-255) our bake must stay under
OUT_OF_RANGE = re.compile(r"QImage::(setPixel|pixel): coordinate")
PERIODS = 3                 # of the colour pattern across the mesh's bounding box
PYMESHLAB_FILTERS = {       # the methods compared; pymeshlab name and parameters of each
    "low-stretch": ("compute_texcoord_parametrization_low_stretch", {"nondisk": "Make charts"}),
    "Voronoi atlas": ("generate_voronoi_atlas_parametrization", {}),
    "trivial per-triangle": ("compute_texcoord_parametrization_triangle_trivial_per_wedge", {"textdim": SIZE}),
}


def colour_pattern(vertices):
    """Smooth RGB waves over the bounding box: detail that only a texture of enough texels per
    unit of surface keeps."""
    low = [min(v[c] for v in vertices) for c in range(3)]
    side = max(max(v[c] for v in vertices) - low[c] for c in range(3)) or 1.0
    colours = []
    for v in vertices:
        x, y, z = ((v[c] - low[c]) / side for c in range(3))
        wave = [math.sin(2 * math.pi * PERIODS * x), math.sin(2 * math.pi * PERIODS * y + 1),
                math.sin(2 * math.pi * PERIODS * z + 2)]
        colours.append(tuple(int(round(127.5 + 127.5 * w)) for w in wave))
    return colours


def write_coloured_ply(path, vertices, faces, colours):
    with open(path, "w") as f:
        f.write(f"ply\nformat ascii 1.0\nelement vertex {len(vertices)}\nproperty float x\nproperty float y\n"
                "property float z\nproperty uchar red\nproperty uchar green\nproperty uchar blue\n"
                f"element face {len(faces)}\nproperty list uchar int vertex_indices\nend_header\n")
        for v, c in zip(vertices, colours):
            f.write("%.9g %.9g %.9g %d %d %d\n" % (*v, *c))
        for face in faces:
            f.write("3 %d %d %d\n" % tuple(face))


def coloured_input(args):
    """The input mesh with the colour pattern, as an ASCII PLY in the work folder."""
    if args.mesh:
        vertices, faces = meshio.read_off(args.mesh)
        name = os.path.splitext(os.path.basename(args.mesh))[0]
    else:
        vertices, faces = generate.DISKS[args.generate]()
        name = args.generate
    path = os.path.join(args.work, name + "_coloured.ply")
    write_coloured_ply(path, vertices, faces, colour_pattern(vertices))
    return path, name


def read_rgb(path):
    """The image's pixels as rows of (r, g, b), read through ImageMagick."""
    size = subprocess.run(["identify", "-format", "%w %h", path], capture_output=True, text=True, check=True).stdout
    width, height = map(int, size.split())
    raw = subprocess.run(["convert", path, "-depth", "8", "rgb:-"], capture_output=True, check=True).stdout
    return width, height, raw


def measure(mesh_path, texture_path, flip_v=False):
    """Coverage, L2 stretch, flips and colour error of a baked mesh (a PLY with vertex colours and
    wedge texcoords) and its texture."""
    ply = meshio.read_ply(mesh_path)
    vertices, faces = ply.vertices(), ply.faces()
    vd = ply.elements["vertex"].data
    colours = list(zip(vd["red"], vd["green"], vd["blue"]))
    tc = ply.elements["face"].data["texcoord"]
    corner_uv = [(t[2 * k], t[2 * k + 1]) for t in tc for k in range(3)]
    area_u, _, l2, area = map_stretch(vertices, faces, corner_uv)
    width, height, raw = read_rgb(texture_path)
    squared, weight = 0.0, 0.0
    for f, face in enumerate(faces):
        for w in ((1 / 3, 1 / 3, 1 / 3), (2 / 3, 1 / 6, 1 / 6), (1 / 6, 2 / 3, 1 / 6), (1 / 6, 1 / 6, 2 / 3)):
            u = sum(w[k] * corner_uv[3 * f + k][0] for k in range(3))
            v = sum(w[k] * corner_uv[3 * f + k][1] for k in range(3))
            v = 1 - v if flip_v else v
            x = min(width - 1, max(0, int(u * width)))
            y = height - 1 - min(height - 1, max(0, int(v * height)))  # row 0 is the top (v = 1)
            texel = raw[3 * (y * width + x):3 * (y * width + x) + 3]
            expected = [sum(w[k] * colours[face[k]][c] for k in range(3)) for c in range(3)]
            squared += area[f] / 4 * sum((texel[c] - expected[c]) ** 2 for c in range(3)) / 3
        weight += area[f]
    return {"coverage": sum(abs(a) for a in area_u), "l2": l2, "flipped": sum(1 for a in area_u if a <= 0),
            "colour_error": math.sqrt(squared / weight), "faces": len(faces),
            "uv_range": (min(min(t) for t in tc), max(max(t) for t in tc)), "mesh": mesh_path, "texture": texture_path}


def filter_xml(name, params):
    """A <filter> element of a MeshLab 2020.09 script: params are (name, type, value) or, for an
    enum, (name, "RichEnum", index, [entries])."""
    element = ET.Element("filter", name=name)
    for pname, ptype, value, *entries in params:
        param = ET.SubElement(element, "Param", name=pname, type=ptype, value=str(value), description=pname)
        if entries:
            param.set("enum_cardinality", str(len(entries[0])))
            for i, entry in enumerate(entries[0]):
                param.set(f"enum_val{i}", entry)
    return element


def write_script(path, filters):
    root = ET.Element("FilterScript")
    root.extend(filters)
    with open(path, "w") as f:
        f.write("<!DOCTYPE FilterScript>\n" + ET.tostring(root, encoding="unicode") + "\n")
    return path


def bake_filter(args):
    """Transfer: Vertex Color to Texture exactly as resources/lowstretch_bake.mlx has it."""
    return ET.parse(os.path.join(args.resources, "lowstretch_bake.mlx")).getroot().findall("filter")[1]


def run_2020(args, method, coloured):
    """One method through meshlabserver in its own folder; returns (baked mesh, texture, log)."""
    work = os.path.join(args.work, method.replace(" ", "_"))
    os.makedirs(work, exist_ok=True)
    source = os.path.join(work, "input.ply")
    with open(coloured, "rb") as a, open(source, "wb") as b:
        b.write(a.read())  # the texture is written beside the mesh meshlabserver loaded
    out = os.path.join(work, "baked.ply")
    mask = ["-m", "vc", "wt"]
    if method == "low-stretch":
        script = ET.parse(os.path.join(args.resources, "lowstretch_bake.mlx"))
        if args.atlas:  # "Atlas for any mesh"
            [p.set("value", "2") for p in script.getroot().iter("Param") if p.get("name") == "nonDisk"]
        script.write(os.path.join(work, "lowstretch_bake.mlx"))
        proc = e2e.meshlabserver(args.prefix, work, "bake.log", ["-i", source, "-o", out] + mask +
                                 ["-s", os.path.join(work, "lowstretch_bake.mlx")])
        return out, os.path.join(work, "texture.png"), proc.stdout + proc.stderr
    if method == "trivial per-triangle":
        script = write_script(os.path.join(work, "script.mlx"), [
            filter_xml("Parametrization: Trivial Per-Triangle", [("sidedim", "RichInt", 0), ("textdim", "RichInt", SIZE),
                       ("border", "RichInt", 2), ("method", "RichEnum", 1, ["Basic", "Space-optimizing"])]), bake_filter(args)])
        proc = e2e.meshlabserver(args.prefix, work, "bake.log", ["-i", source, "-o", out] + mask + ["-s", script])
        return out, os.path.join(work, "texture.png"), proc.stdout + proc.stderr
    # The Voronoi atlas is a new layer without a file: save it, then bake it (MeshLab 2020.09
    # bakes beside the mesh's file).
    atlas = os.path.join(work, "atlas.ply")
    script = write_script(os.path.join(work, "atlas.mlx"), [
        filter_xml("Parametrization: Voronoi Atlas", [("regionNum", "RichInt", 10), ("overlapFlag", "RichBool", "false")]),
        filter_xml("Change the current layer", [("layer", "RichMesh", 1)])])
    first = e2e.meshlabserver(args.prefix, work, "atlas.log", ["-i", source, "-o", atlas] + mask + ["-s", script])
    script = write_script(os.path.join(work, "bake.mlx"), [bake_filter(args)])
    proc = e2e.meshlabserver(args.prefix, work, "bake.log", ["-i", atlas, "-o", out] + mask + ["-s", script])
    return out, os.path.join(work, "texture.png"), first.stdout + first.stderr + proc.stdout + proc.stderr


def run_pymeshlab_inside(args):
    """In the pymeshlab environment: one method, baked and saved with its texture into the
    method's folder (baked.ply, texture.png)."""
    import pymeshlab
    pymeshlab.load_plugin(os.path.abspath(args.plugin))
    name, params = PYMESHLAB_FILTERS[args.method]
    if args.atlas and args.method == "low-stretch":
        params = {"nondisk": "Atlas for any mesh"}
    ms = pymeshlab.MeshSet()
    ms.load_new_mesh(args.input)
    ms.apply_filter(name, **params)
    if args.method == "Voronoi atlas":  # a new layer, not the current one, and without colours
        atlas = ms.mesh_number() - 1
        ms.transfer_attributes_per_vertex(sourcemesh=0, targetmesh=atlas)  # the colour at the same points
        ms.set_current_mesh(atlas)
    ms.compute_texmap_from_color(textname="texture.png", textw=SIZE, texth=SIZE, overwrite=False, pullpush=True)
    ms.save_current_mesh(os.path.join(args.work, "baked.ply"), save_vertex_color=True, save_wedge_texcoord=True,
                         save_textures=True)
    return 0


def run_pymeshlab(args, method, coloured):
    """One method in its own pymeshlab process (its log is its own); returns (mesh, texture, log)."""
    sys.path.insert(0, os.path.join(HERE, "..", "meshlab2025"))
    from test_pymeshlab import venv_python
    python = venv_python(args.venv)
    work = os.path.join(args.work, method.replace(" ", "_"))
    os.makedirs(work, exist_ok=True)
    proc = subprocess.run([python, os.path.abspath(__file__), "pymeshlab", "--inside", "--method", method,
                           "--plugin", args.plugin, "--input", coloured, "--work", work] + (["--atlas"] if args.atlas else []),
                          capture_output=True, text=True, errors="replace", timeout=1200)
    with open(os.path.join(work, "pymeshlab.log"), "w") as f:
        f.write(f"exit code {proc.returncode}\n--- stdout ---\n{proc.stdout}\n--- stderr ---\n{proc.stderr}")
    print(f"pymeshlab, {method}: exit code {proc.returncode}, log in {work}/pymeshlab.log")
    return os.path.join(work, "baked.ply"), os.path.join(work, "texture.png"), proc.stdout + proc.stderr


def print_table(name, args, results, logs):
    print(f"mesh {name}, texture {SIZE} x {SIZE}, MeshLab {'2020.09' if args.mode == 'meshlab2020' else '2025.7 (pymeshlab)'}"
          f"{', ours as an atlas' if args.atlas else ''}")
    print("| method | faces | coverage | L2 stretch | flipped | colour error (RMS, 0-255) | out-of-range warnings |")
    print("|---|---|---|---|---|---|---|")
    for method, r in results.items():
        print(f"| {method} | {r['faces']} | {r['coverage']:.3f} | {r['l2']:.3f} | {r['flipped']} | "
              f"{r['colour_error']:.2f} | {len(OUT_OF_RANGE.findall(logs[method]))} |")


def bake(args):
    """The three methods baked in args.work (args.mode: meshlab2020 or pymeshlab), measured, the
    table printed; returns (results, logs, the methods whose mesh or texture is missing)."""
    os.makedirs(args.work, exist_ok=True)
    coloured, name = coloured_input(args)
    results, logs, missing = {}, {}, []
    run = run_2020 if args.mode == "meshlab2020" else run_pymeshlab
    for method in PYMESHLAB_FILTERS:
        mesh, texture, logs[method] = run(args, method, coloured)
        if os.path.isfile(mesh) and os.path.isfile(texture):
            results[method] = measure(mesh, texture)
        else:
            missing.append(method)
    print_table(name, args, results, logs)
    return results, logs, missing


def check_bake(results, logs, missing):
    """The checks of ours, as assertions (test_bake.py runs them under pytest)."""
    assert not missing, f"baked mesh and texture written by every method (missing: {', '.join(missing)})"
    ours, voronoi = results["low-stretch"], results["Voronoi atlas"]
    assert len(OUT_OF_RANGE.findall(logs["low-stretch"])) == 0, "baking our map writes no pixel out of range"
    low, high = ours["uv_range"]
    assert low > 0 and high < 1, f"our texcoords are strictly inside (0,1): [{low:.6g}, {high:.6g}]"
    assert ours["flipped"] == 0, f"no flipped or zero-area UV triangle in our map ({ours['flipped']})"
    # The measure sees a wrong texture: read upside down, ours is far off.
    upside_down = measure(ours["mesh"], ours["texture"], flip_v=True)["colour_error"]
    assert upside_down > 5 * ours["colour_error"], \
        f"the colour error sees a wrong texture: {upside_down:.2f} when read upside down"
    assert ours["colour_error"] <= ERROR_BOUND, f"colour error of our bake {ours['colour_error']:.2f} <= {ERROR_BOUND}"
    assert ours["colour_error"] <= voronoi["colour_error"], (
        f"colour error of our bake {ours['colour_error']:.2f} <= the Voronoi atlas's {voronoi['colour_error']:.2f}")


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("mode", choices=["meshlab2020", "pymeshlab", "colour"])
    parser.add_argument("--output", help="colour: the PLY to write")
    parser.add_argument("--prefix", help="meshlab2020: the private MeshLab prefix with our plugin (e2e.py prefix)")
    parser.add_argument("--resources", help="meshlab2020: the repository's resources/ folder")
    parser.add_argument("--plugin", help="pymeshlab: the pymeshlab build of the plugin")
    parser.add_argument("--venv", help="pymeshlab: the virtual environment with pymeshlab")
    group = parser.add_mutually_exclusive_group()
    group.add_argument("--mesh", help="a disk mesh (OFF)")
    group.add_argument("--generate", choices=sorted(generate.DISKS), help="a generated disk")
    parser.add_argument("--work", help="work folder (meshlab2020, pymeshlab)")
    parser.add_argument("--atlas", action="store_true", help="our filter makes an atlas (Atlas for any mesh)")
    parser.add_argument("--inside", action="store_true", help=argparse.SUPPRESS)
    parser.add_argument("--input", help=argparse.SUPPRESS)
    parser.add_argument("--method", help=argparse.SUPPRESS)
    args = parser.parse_args()
    if args.inside:
        return run_pymeshlab_inside(args)
    if args.mode == "colour":
        if not args.mesh or not args.output:
            parser.error("colour needs --mesh and --output")
        vertices, faces = meshio.read_off(args.mesh)
        write_coloured_ply(args.output, vertices, faces, colour_pattern(vertices))
        return 0
    if not args.work:
        parser.error(f"{args.mode} needs --work")
    for name in ("prefix", "resources", "plugin", "venv", "mesh", "work"):
        if getattr(args, name):
            setattr(args, name, os.path.abspath(getattr(args, name)))

    try:
        check_bake(*bake(args))
    except AssertionError as failure:
        print(f"FAILED: {failure}")
        return 1
    print("all checks passed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
