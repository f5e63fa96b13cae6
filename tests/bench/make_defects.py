#!/usr/bin/env python3
"""Scan defects on a clean closed mesh (CGAL's armadillo in tests/bench/README.md), one OFF file
each, to see how the atlas takes them:
  holes200     200 one-face holes, none touching another (dropouts)
  dropouts     200 faces removed at random (holes that may touch: non-manifold vertices)
  collapsed    300 edges collapsed (one end moved onto the other: zero-area faces)
  debris3000   3000 loose triangles around the mesh (scan debris)
  debris30000  30000 of them
  soup         every face with vertices of its own (an unwelded STL export)
Usage: make_defects.py MESH.off OUT_FOLDER (standard library only; seeded, so the same files)."""
import os
import random
import sys


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
    }
    for name, (v, f) in made.items():
        path = os.path.join(sys.argv[2], name + ".off")
        write_off(path, v, f)
        print(path, len(v), "vertices", len(f), "faces")


if __name__ == "__main__":
    main()
