#!/usr/bin/env python3
"""What is wrong with a mesh, in the counts that describe real range scans:
vertices, faces, unreferenced vertices, parts (faces joined by a shared vertex index), faces of
exactly zero area and under 1e-3 of the median area, vertices at a position an earlier vertex
already has, non-manifold edges (three or more faces) and vertices (more than one fan of faces, or
on a non-manifold edge), boundary loops, and the Euler characteristic and genus of the largest part,
as it is and with its vertices welded by position (faces made degenerate by the welding dropped).

usage: mesh_defects.py MESH... (OFF, OBJ or PLY; polygons are fanned into triangles; needs numpy)
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "e2e"))
import meshio  # noqa: E402


def read(path):
    fast = read_triangle_off(path) if path.endswith(".off") else None
    if fast:
        return fast
    reader = {".obj": meshio.read_obj, ".off": meshio.read_off}.get(os.path.splitext(path)[1])
    if reader:
        vertices, faces = reader(path)
    else:
        ply = meshio.read_ply(path)
        vertices, faces = ply.vertices(), ply.faces()
    V = np.array(vertices, float).reshape(-1, 3)
    F = np.array([(f[0], f[k], f[k + 1]) for f in faces for k in range(1, len(f) - 1)], np.int64)
    return V, F.reshape(-1, 3)


def read_triangle_off(path):
    """Plain triangle OFF files (what the generators write) read fast; None for any other OFF."""
    words = open(path).read().split()
    if words[0] != "OFF" or "#" in words:
        return None
    nv, nf = int(words[1]), int(words[2])
    rest = words[4 + 3 * nv:]
    if len(rest) != 4 * nf or any(w != "3" for w in rest[::4]):
        return None
    V = np.array(words[4:4 + 3 * nv], float).reshape(-1, 3)
    return V, np.array(rest, np.int64).reshape(-1, 4)[:, 1:]


def components(n, pairs):
    """Label of each of n nodes, joined by the given pairs (union-find by hooking and shortcutting)."""
    label = np.arange(n)
    a, b = pairs[:, 0], pairs[:, 1]
    while True:
        la, lb = label[a], label[b]
        differ = la != lb
        if not differ.any():
            return label
        np.minimum.at(label, np.maximum(la, lb)[differ], np.minimum(la, lb)[differ])
        while True:
            up = label[label]
            if (up == label).all():
                break
            label = up


def edges_of(F):
    """Per corner edge (face k, edge from corner j to j+1), sorted pairs and their unique ids."""
    E = np.stack([F, np.roll(F, -1, axis=1)], axis=2).reshape(-1, 2)
    key = np.sort(E, axis=1)
    unique, inverse, counts = np.unique(key, axis=0, return_inverse=True, return_counts=True)
    return E, unique, inverse.ravel(), counts


def topology(F, nv):
    """Non-manifold edges and vertices, boundary loops, Euler characteristic of the faces F."""
    E, unique, inverse, counts = edges_of(F)
    proper = unique[:, 0] != unique[:, 1]  # an edge from a vertex to itself is no edge
    nonmanifold_edges = int((proper & (counts > 2)).sum())
    # Corners (face, vertex) around one vertex are one fan when joined across edges of two faces.
    corner = np.arange(3 * len(F)).reshape(-1, 3)
    order = np.argsort(inverse, kind="stable")
    first = np.searchsorted(inverse[order], np.arange(len(unique)))
    two = np.flatnonzero(proper & (counts == 2))
    h0, h1 = order[first[two]], order[first[two] + 1]  # the two half-edges of each such edge
    f0, j0, f1, j1 = h0 // 3, h0 % 3, h1 // 3, h1 % 3
    start0, end0 = corner[f0, j0], corner[f0, (j0 + 1) % 3]
    start1, end1 = corner[f1, j1], corner[f1, (j1 + 1) % 3]
    same = E[h0, 0] == E[h1, 0]  # both faces run the edge the same way (misoriented neighbours)
    pairs = np.concatenate([np.stack([start0, np.where(same, start1, end1)], 1),
                            np.stack([end0, np.where(same, end1, start1)], 1)])
    fan = components(3 * len(F), pairs) if len(F) else np.zeros(0, np.int64)
    fans = np.zeros(nv, np.int64)  # distinct fans at each vertex
    np.add.at(fans, F.ravel()[np.unique(fan, return_index=True)[1]], 1)
    bad = fans > 1
    bad[unique[proper & (counts > 2)].ravel()] = True
    # Boundary loops: boundary edges chained through the fans at their ends.
    one = np.flatnonzero(proper & (counts == 1))
    h = order[first[one]]
    ends = np.stack([fan[corner[h // 3, h % 3]], fan[corner[h // 3, (h % 3 + 1) % 3]]], 1)
    loops = 0
    if len(ends):
        nodes, index = np.unique(ends, return_inverse=True)
        loops = len(np.unique(components(len(nodes), index.reshape(-1, 2))))
    used = len(np.unique(F))
    euler = used - int(proper.sum()) + len(F)
    return nonmanifold_edges, int(bad.sum()), loops, euler


def report(path):
    V, F = read(path)
    print(path)
    print(f"  vertices {len(V)}, faces {len(F)}, unreferenced vertices {len(V) - len(np.unique(F))}")
    if not len(F):
        return
    label = components(len(V), np.concatenate([F[:, [0, 1]], F[:, [1, 2]]]))[F[:, 0]]
    part, size = np.unique(label, return_counts=True)
    print(f"  parts {len(part)} (largest {size.max()} faces, {int((size <= 10).sum())} of at most 10 faces)")
    area = np.linalg.norm(np.cross(V[F[:, 1]] - V[F[:, 0]], V[F[:, 2]] - V[F[:, 0]]), axis=1) / 2
    print(f"  zero-area faces {int((area == 0).sum())}, under 1e-3 of median area "
          f"{int((area < 1e-3 * np.median(area)).sum())}")
    positions, weld = np.unique(V, axis=0, return_inverse=True)
    weld = weld.ravel()
    print(f"  duplicate vertex positions {len(V) - len(positions)} "
          f"({len(np.unique(weld[np.unique(F)]))} distinct of {len(np.unique(F))} used vertices)")
    nme, nmv, loops, euler = topology(F, len(V))
    print(f"  non-manifold edges {nme}, non-manifold vertices {nmv}, boundary loops {loops}")
    largest = F[label == part[size.argmax()]]
    print(genus("largest part", largest, len(V)))
    welded = weld[largest]
    welded = welded[(welded[:, 0] != welded[:, 1]) & (welded[:, 1] != welded[:, 2]) & (welded[:, 2] != welded[:, 0])]
    print(genus("largest part welded by position", welded, len(positions)))


def genus(what, F, nv):
    nme, nmv, loops, euler = topology(F, nv)
    note = "" if nme == nmv == 0 else f" (not a manifold: {nme} non-manifold edges, {nmv} vertices)"
    return (f"  {what}: {len(F)} faces, Euler characteristic {euler}, boundary loops {loops}, "
            f"genus {(2 - euler - loops) / 2:g}{note}")

if __name__ == "__main__":
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    for p in sys.argv[1:]:
        report(p)
