#!/usr/bin/env python3
"""Writes small seed corpora for the fuzz targets, one folder per target, into OUT:
meshes the project can make (wavy grids as OFF, OBJ, ASCII and binary PLY, with the variants the
readers support) and, when present, the shared parse-error files.

usage: make_seeds.py OUT [SHARED_MESHES_DIR]
"""
import math
import os
import shutil
import struct
import sys


def grid(n, wavy=True):
    """An n x n grid over [0,1]^2 (counter-clockwise triangles), z a small wave: a disk."""
    V = [(i / n, j / n, 0.2 * math.sin(3 * i / n) * math.cos(2 * j / n) if wavy else 0.0)
         for j in range(n + 1) for i in range(n + 1)]
    F = []
    for j in range(n):
        for i in range(n):
            a, b, c, d = j * (n + 1) + i, j * (n + 1) + i + 1, (j + 1) * (n + 1) + i + 1, (j + 1) * (n + 1) + i
            F += [(a, b, c), (a, c, d)] if (i + j) % 2 == 0 else [(a, b, d), (b, c, d)]
    return V, F


def quads(n):
    V, _ = grid(n)
    Q = [(j * (n + 1) + i, j * (n + 1) + i + 1, (j + 1) * (n + 1) + i + 1, (j + 1) * (n + 1) + i)
         for j in range(n) for i in range(n)]
    return V, Q


def fmt(x):
    return ("%.6g" % x)


def off(V, F, header="OFF", comment=False, same_line=False, colors=False):
    out = [header + (" %d %d 0" % (len(V), len(F)) if same_line else "")]
    if comment:
        out.insert(0, "# made by make_seeds.py")
    if not same_line:
        out.append("%d %d 0" % (len(V), len(F)))
    for k, v in enumerate(V):
        out.append(" ".join(fmt(x) for x in v) + (" 200 100 %d" % (k % 256) if colors else ""))
    for k, f in enumerate(F):
        out.append("%d " % len(f) + " ".join(str(i) for i in f) + (" 1 0.5 0.25" if colors and k % 2 else ""))
    return ("\n".join(out) + "\n").encode()


def obj(V, F, style="plain"):
    out = ["# made by make_seeds.py", "o grid"]
    out += ["v " + " ".join(fmt(x) for x in v) for v in V]
    if style != "plain":
        out += ["vt %s %s" % (fmt(v[0]), fmt(v[1])) for v in V]
        out += ["vn 0 0 1"]
    for f in F:
        if style == "plain":
            out.append("f " + " ".join(str(i + 1) for i in f))
        elif style == "slashes":
            out.append("f " + " ".join("%d/%d/1" % (i + 1, i + 1) for i in f))
        elif style == "normals":
            out.append("f " + " ".join("%d//1" % (i + 1) for i in f))
        else:  # negative (relative) indices
            out.append("f " + " ".join(str(i - len(V)) for i in f))
    return ("\n".join(out) + "\n").encode()


def ply_header(fmt_name, V, F, double=False, colors=False, quality=False, list_name="vertex_indices",
               count="uchar", index="int"):
    h = ["ply", "format %s 1.0" % fmt_name, "comment made by make_seeds.py", "element vertex %d" % len(V)]
    h += ["property %s %s" % ("double" if double else "float", a) for a in "xyz"]
    if colors:
        h += ["property uchar red", "property uchar green", "property uchar blue"]
    h += ["element face %d" % len(F), "property list %s %s %s" % (count, index, list_name)]
    if quality:
        h += ["property float quality"]
    h += ["end_header"]
    return ("\n".join(h) + "\n").encode()


def ply_ascii(V, F, **kw):
    body = []
    for k, v in enumerate(V):
        body.append(" ".join(fmt(x) for x in v) + (" 255 %d 0" % (k % 256) if kw.get("colors") else ""))
    for f in F:
        body.append("%d " % len(f) + " ".join(str(i) for i in f) + (" 0.5" if kw.get("quality") else ""))
    return ply_header("ascii", V, F, **kw) + ("\n".join(body) + "\n").encode()


def ply_binary_body(V, F, big=False, double=False, colors=False, quality=False, count="uchar", index="int"):
    e = ">" if big else "<"
    out = b""
    for k, v in enumerate(V):
        out += struct.pack(e + ("3d" if double else "3f"), *v)
        if colors:
            out += struct.pack("3B", 255, k % 256, 0)
    for f in F:
        out += struct.pack(e + ("B" if count == "uchar" else "i"), len(f))
        out += struct.pack(e + "%d%s" % (len(f), "i" if index == "int" else "I"), *f)
        if quality:
            out += struct.pack(e + "f", 0.5)
    return out


def ply_binary(V, F, big=False, **kw):
    return ply_header("binary_big_endian" if big else "binary_little_endian", V, F, **kw) + ply_binary_body(V, F, big, **kw)


def recipe(V, F, flags, extra=0):
    """An input of fuzz_read_ply_binary's header-recipe form (see fuzz_read_ply_binary.cpp)."""
    kw = dict(big=bool(flags & 1), double=bool(flags & 2), colors=bool(flags & 4), quality=bool(flags & 8),
              count="int" if flags & 16 else "uchar", index="uint" if flags & 32 else "int")
    body = b""
    if flags & 128:
        body += b"".join(struct.pack((">" if flags & 1 else "<") + "2i", k, k + 1) for k in range(extra & 0x7f))
    vb = ply_binary_body(V, [], **kw)
    fb = ply_binary_body([], F, **kw)
    body += fb + vb if flags & 64 else vb + fb
    return bytes([flags, len(V), len(F), extra]) + body


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    out = sys.argv[1]
    shared = sys.argv[2] if len(sys.argv) > 2 else None
    seeds = {t: {} for t in ("off", "obj", "ply_ascii", "ply_binary", "parameterize")}
    V2, F2 = grid(2)
    V4, F4 = grid(4)
    Vq, Q = quads(3)
    tri_V, tri_F = [(0, 0, 0), (1, 0, 0), (0, 1, 0)], [(0, 1, 2)]

    s = seeds["off"]
    s["grid2.off"] = off(V2, F2)
    s["grid4_comment.off"] = off(V4, F4, comment=True)
    s["grid2_sameline.off"] = off(V2, F2, same_line=True)
    s["quads3.off"] = off(Vq, Q)
    s["grid2_colors.off"] = off(V2, F2, header="COFF", colors=True)
    s["triangle.off"] = off(tri_V, tri_F)
    s["pentagon.off"] = off([(math.cos(a), math.sin(a), 0) for a in [2 * math.pi * k / 5 for k in range(5)]], [tuple(range(5))])

    s = seeds["obj"]
    s["grid2.obj"] = obj(V2, F2)
    s["grid4_slashes.obj"] = obj(V4, F4, "slashes")
    s["grid2_normals.obj"] = obj(V2, F2, "normals")
    s["grid2_negative.obj"] = obj(V2, F2, "negative")
    s["quads3.obj"] = obj(Vq, Q)
    s["triangle.obj"] = obj(tri_V, tri_F)

    s = seeds["ply_ascii"]
    s["grid2.ply"] = ply_ascii(V2, F2)
    s["grid4_colors_quality.ply"] = ply_ascii(V4, F4, colors=True, quality=True)
    s["grid2_vertex_index.ply"] = ply_ascii(V2, F2, list_name="vertex_index", double=True)
    s["quads3.ply"] = ply_ascii(Vq, Q)
    s["triangle.ply"] = ply_ascii(tri_V, tri_F)

    s = seeds["ply_binary"]
    s["grid2_le.ply"] = ply_binary(V2, F2)
    s["grid2_be_double.ply"] = ply_binary(V2, F2, big=True, double=True)
    s["grid4_colors_quality_int_uint.ply"] = ply_binary(V4, F4, colors=True, quality=True, count="int", index="uint")
    s["quads3_le.ply"] = ply_binary(Vq, Q)
    for flags in (0, 1, 2, 4 | 8, 16 | 32, 64, 128 | 1, 255):
        s["recipe_grid2_%02x" % flags] = recipe(V2, F2, flags, extra=3 if flags & 128 else 0)
    s["recipe_triangle"] = recipe(tri_V, tri_F, 0)
    s["recipe_quads3"] = recipe(Vq, Q, 0)

    # fuzz_parameterize: mode byte, parameter byte, then (grid) shape byte and edits or (raw)
    # counts, coordinates and indices; see fuzz_parameterize.cpp.
    s = seeds["parameterize"]
    for boundary in range(3):
        for weights in range(3):
            s["grid_b%d_w%d" % (boundary, weights)] = bytes([boundary | weights << 2, 0, 2 | 0x80])
    s["hemisphere"] = bytes([0, 0, 6])
    s["grid_exponent_half"] = bytes([16, 100, 3])
    s["grid_cancel"] = bytes([64, 3, 2])
    s["grid_all_passes_natural"] = bytes([128 | 2, 0, 4 | 0x80])
    s["grid_nan"] = bytes([0, 0, 2, 0, 4, 2, 0xf0])
    s["grid_duplicate_face"] = bytes([0, 0, 2, 2, 1, 0, 0])
    s["grid_hole"] = bytes([0, 0, 4, 3, 11, 0, 0])
    s["grid_flap"] = bytes([0, 0, 2, 5, 8, 9, 10])
    s["grid_fin"] = bytes([0, 0, 3, 5, 7, 8, 20])  # a flap on an interior edge: three faces on it
    s["grid_flipped_face"] = bytes([0, 0, 3, 4, 5, 0, 0])  # misoriented edges
    s["grid_collapsed_vertex"] = bytes([0, 0, 3, 6, 7, 8, 0])  # zero-area faces, a zero-length edge
    s["grid_tiny"] = bytes([0, 0, 2, 7, 0, 0, 0])
    s["grid_huge"] = bytes([0, 0, 2, 7, 255, 0, 0])
    # The disk the fuzzer found folded (harmonic weights, exponent 0.3): a hemisphere of 2 rings and
    # 5 sectors, its apex moved, a vertex moved onto another, all scaled by 10^-31.25.
    s["hemisphere_harmonic_folded"] = bytes([8 | 16, 60, 27, 0, 0, 0, 27, 6, 8, 7, 0, 7, 3, 0, 0])
    tri = [0, 0, 0, 8, 0, 0, 0, 8, 0]
    s["raw_triangle"] = bytes([32, 0, 3, 1] + tri + [0, 1, 2])
    s["raw_zero_faces"] = bytes([32, 0, 3, 0] + tri)
    s["raw_two_triangles"] = bytes([32, 0, 4, 2] + tri + [8, 8, 0] + [0, 1, 2, 1, 3, 2])
    s["raw_out_of_range"] = bytes([32, 0, 3, 1] + tri + [0, 1, 0xfe])

    if shared:
        errors = os.path.join(shared, "parse_errors")
        if os.path.isdir(errors):
            for name in sorted(os.listdir(errors)):
                ext = name.rsplit(".", 1)[-1].lower()
                target = {"off": "off", "obj": "obj", "ply": "ply_ascii"}.get(ext)
                if target:
                    with open(os.path.join(errors, name), "rb") as f:
                        seeds[target]["shared_" + name] = f.read()

    for target, files in seeds.items():
        folder = os.path.join(out, target)
        shutil.rmtree(folder, ignore_errors=True)
        os.makedirs(folder)
        for name, data in files.items():
            with open(os.path.join(folder, name), "wb") as f:
                f.write(data)
    print("make_seeds: %s" % ", ".join("%s %d" % (t, len(f)) for t, f in seeds.items()))


if __name__ == "__main__":
    main()
