#!/usr/bin/env python3
"""Scan defects on a clean closed mesh (CGAL's armadillo in tests/bench/README.md), one OFF file
each, to see how the atlas takes them:
  holes200     200 one-face holes, none touching another (dropouts)
  dropouts     200 faces removed at random (holes that may touch: non-manifold vertices)
  collapsed    300 edges collapsed (one end moved onto the other: zero-area faces)
  debris3000   3000 loose triangles around the mesh (scan debris)
  debris30000  30000 of them
  soup         every face with vertices of its own (an unwelded STL export)
  fins         20 edges, none sharing a vertex, given one or two more faces (10 edges of three
               faces, 10 of four: non-manifold edges)
  slivers      300 edges split at their exact midpoint on one side, the crack closed by a
               triangle of exactly zero area (a T-junction: manifold, closed, 300 zero-area faces)
  duplicates   500 vertices each copied to the identical position, one of its faces moved to the
               copy (an unwelded seam: duplicate positions and small cracks)
  dust         2000 tiny parts near the surface: 1000 closed tetrahedra and 1000 open fans of
               three triangles (scan dust: many parts)
  all          holes200, fins, slivers, duplicates and dust on one mesh
Usage: make_defects.py MESH.off OUT_FOLDER (standard library only; seeded, so the same files)."""
import os
import random
import sys
from fractions import Fraction


def read_off(path):
    words = open(path).read().split()
    assert words[0] == "OFF"
    nv, nf = int(words[1]), int(words[2])
    at = 4
    vertices = [[float(w) for w in words[at + 3 * i:at + 3 * i + 3]] for i in range(nv)]
    at += 3 * nv
    faces = []
    for _ in range(nf):
        n = int(words[at])
        faces.append([int(w) for w in words[at + 1:at + 1 + n]])
        at += 1 + n
    return vertices, faces


def write_off(path, vertices, faces):
    with open(path, "w") as f:
        f.write("OFF\n%d %d 0\n" % (len(vertices), len(faces)))
        for v in vertices:
            f.write("%r %r %r\n" % tuple(v))
        for t in faces:
            f.write("3 %d %d %d\n" % tuple(t))


def holes_apart(vertices, faces, count, seed):
    """count faces removed, no two within one ring of each other: each hole its own loop."""
    rng = random.Random(seed)
    ring = {}
    for t in faces:
        for v in t:
            ring.setdefault(v, set()).update(t)
    order = list(range(len(faces)))
    rng.shuffle(order)
    touched, removed = set(), set()
    for i in order:
        if len(removed) >= count:
            break
        near = set().union(*(ring[v] for v in faces[i]))
        if near & touched:
            continue
        removed.add(i)
        touched |= near
    return vertices, [t for i, t in enumerate(faces) if i not in removed]


def dropouts(vertices, faces, count, seed):
    removed = set(random.Random(seed).sample(range(len(faces)), count))
    return vertices, [t for i, t in enumerate(faces) if i not in removed]


def collapsed(vertices, faces, count, seed):
    moved = [v[:] for v in vertices]
    for t in random.Random(seed).sample(faces, count):
        moved[t[0]] = moved[t[1]][:]
    return moved, faces


def debris(vertices, faces, count, seed):
    rng = random.Random(seed)
    lo = [min(v[k] for v in vertices) for k in range(3)]
    hi = [max(v[k] for v in vertices) for k in range(3)]
    size = 0.003 * max(h - l for h, l in zip(hi, lo))
    out, out_faces = [v[:] for v in vertices], [t[:] for t in faces]
    for _ in range(count):
        c = [rng.uniform(l, h) for l, h in zip(lo, hi)]
        b = len(out)
        out += [c, [c[0] + size, c[1], c[2]], [c[0], c[1] + size, c[2] + size / 6]]
        out_faces.append([b, b + 1, b + 2])
    return out, out_faces


def soup(vertices, faces):
    return [vertices[i][:] for t in faces for i in t], [[3 * k, 3 * k + 1, 3 * k + 2] for k in range(len(faces))]


def fins(vertices, faces, count, seed):
    """count edges apart from each other, each given a fin (a face off the surface) on one side
    or, every other edge, on both: three or four faces on the edge."""
    rng = random.Random(seed)
    out, out_faces = [v[:] for v in vertices], [t[:] for t in faces]
    used = set()
    for t in rng.sample(faces, len(faces)):
        if len(used) >= 2 * count:
            break
        a, b, c = t
        if a in used or b in used:
            continue
        used |= {a, b}
        A, B, C = vertices[a], vertices[b], vertices[c]
        n = cross([B[k] - A[k] for k in range(3)], [C[k] - A[k] for k in range(3)])
        scale = 0.5 * dot([B[k] - A[k] for k in range(3)], [B[k] - A[k] for k in range(3)]) ** 0.5
        scale /= dot(n, n) ** 0.5
        for side in ((1,) if len(used) % 4 == 2 else (1, -1)):
            out.append([(A[k] + B[k]) / 2 + side * scale * n[k] for k in range(3)])
            out_faces.append([b, a, len(out) - 1])
    return out, out_faces


def cross(u, v):
    return [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]


def dot(u, v):
    return sum(x * y for x, y in zip(u, v))


def slivers(vertices, faces, count, seed):
    """count edges a-b split at a midpoint m on the side of face (a, b, c) only, the crack
    closed by the face (a, b, m). Only edges whose computed midpoint lies exactly on the edge
    (checked in exact fractions and in the floating-point cross product) are taken, so that
    (a, b, m) has exactly zero area."""
    rng = random.Random(seed)
    out, out_faces = [v[:] for v in vertices], [t[:] for t in faces]
    split = set()  # edges split, so that no edge is split from both sides
    for i in rng.sample(range(len(faces)), len(faces)):
        if len(split) >= count:
            break
        a, b, c = faces[i]
        A, B = vertices[a], vertices[b]
        m = [(x + y) / 2 for x, y in zip(A, B)]
        exact = all(Fraction(m[k]) - Fraction(A[k]) == (Fraction(B[k]) - Fraction(A[k])) / 2 for k in range(3))
        if (min(a, b), max(a, b)) in split or not exact or any(
                cross([m[k] - A[k] for k in range(3)], [B[k] - A[k] for k in range(3)])):
            continue
        split.add((min(a, b), max(a, b)))
        out.append(m)
        k = len(out) - 1
        out_faces[i] = [a, k, c]
        out_faces += [[k, b, c], [a, b, k]]
    return out, out_faces


def duplicates(vertices, faces, count, seed):
    """count vertices copied to their identical position, one face around each moved onto the copy."""
    rng = random.Random(seed)
    around = {}
    for i, t in enumerate(faces):
        for v in t:
            around.setdefault(v, []).append(i)
    out, out_faces = [v[:] for v in vertices], [t[:] for t in faces]
    for v in rng.sample([v for v in sorted(around) if len(around[v]) > 2], count):  # not a fin's tip
        i = rng.choice(around[v])
        out.append(vertices[v][:])
        out_faces[i] = [len(out) - 1 if w == v else w for w in out_faces[i]]
    return out, out_faces


def dust(vertices, faces, count, seed):
    """count tiny parts, each near a random vertex: closed tetrahedra and open fans of three
    triangles, in turn, about 0.002 of the mesh's size."""
    rng = random.Random(seed)
    size = 0.002 * max(max(v[k] for v in vertices) - min(v[k] for v in vertices) for k in range(3))
    out, out_faces = [v[:] for v in vertices], [t[:] for t in faces]
    for n in range(count):
        near = rng.choice(vertices)
        c = [x + rng.uniform(-5, 5) * size for x in near]
        b = len(out)
        out += [[x + rng.uniform(-size, size) for x in c] for _ in range(4)]
        if n % 2 == 0:
            out_faces += [[b, b + 1, b + 2], [b, b + 3, b + 1], [b + 1, b + 3, b + 2], [b, b + 2, b + 3]]
        else:
            out.append([x + rng.uniform(-size, size) for x in c])
            out_faces += [[b, b + 1, b + 2], [b, b + 2, b + 3], [b, b + 3, b + 4]]
    return out, out_faces


def everything(vertices, faces):
    v, f = holes_apart(vertices, faces, 200, 2)
    v, f = slivers(v, f, 300, 1)
    v, f = fins(v, f, 20, 1)
    v, f = duplicates(v, f, 500, 1)
    return dust(v, f, 2000, 1)


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    vertices, faces = read_off(sys.argv[1])
    assert all(len(t) == 3 for t in faces), "triangles only"
    os.makedirs(sys.argv[2], exist_ok=True)
    made = {
        "holes200": holes_apart(vertices, faces, 200, 2),
        "dropouts": dropouts(vertices, faces, 200, 1),
        "collapsed": collapsed(vertices, faces, 300, 1),
        "debris3000": debris(vertices, faces, 3000, 1),
        "debris30000": debris(vertices, faces, 30000, 1),
        "soup": soup(vertices, faces),
        "fins": fins(vertices, faces, 20, 1),
        "slivers": slivers(vertices, faces, 300, 1),
        "duplicates": duplicates(vertices, faces, 500, 1),
        "dust": dust(vertices, faces, 2000, 1),
        "all": everything(vertices, faces),
    }
    for name, (v, f) in made.items():
        path = os.path.join(sys.argv[2], name + ".off")
        write_off(path, v, f)
        print(path, len(v), "vertices", len(f), "faces")


if __name__ == "__main__":
    main()
