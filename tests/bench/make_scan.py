#!/usr/bin/env python3
"""A range-scan-like mesh of about 830k faces, made from Debian's CGAL demo armadillo (52k faces):
subdivided twice (each triangle into four at its edge midpoints), then broken the way scans are:
gaps along a few planes (the scanner's missing strips: many parts) and round holes (occlusions),
with the faces at vertices left non-manifold removed, so that the mesh is manifold and oriented
but far from a disk. Seeded: the same mesh every run.

  python3 tests/bench/make_scan.py ~/.cache/filter_lowstretch/cgal-data/data/meshes/armadillo.off build/scan.off

Needs numpy (the atlas benchmark's venv has it).
"""
import sys

import numpy as np


def read_off(path):
    words = open(path).read().split()
    nv, nf = int(words[1]), int(words[2])
    stride = 7 if words[0] == "COFF" else 3
    at = 4
    V = np.array([words[at + i * stride: at + i * stride + 3] for i in range(nv)], float)
    at += nv * stride
    F = []
    for _ in range(nf):
        n = int(words[at])
        F.append([int(w) for w in words[at + 1: at + 1 + n]])
        at += 1 + n
    return V, np.array(F, np.int64)


def subdivide(V, F):
    """Each triangle into four at the midpoints of its edges (one new vertex per edge)."""
    edges = np.concatenate([F[:, [0, 1]], F[:, [1, 2]], F[:, [2, 0]]])
    key = np.sort(edges, axis=1)
    unique, index = np.unique(key, axis=0, return_inverse=True)
    mid = len(V) + index.reshape(3, -1).T  # per face: midpoints of edges 01, 12, 20
    V = np.concatenate([V, (V[unique[:, 0]] + V[unique[:, 1]]) / 2])
    a, b, c = F[:, 0], F[:, 1], F[:, 2]
    ab, bc, ca = mid[:, 0], mid[:, 1], mid[:, 2]
    F = np.concatenate([np.stack(t, 1) for t in ((a, ab, ca), (ab, b, bc), (ca, bc, c), (ab, bc, ca))])
    return V, F


def drop_nonmanifold_vertices(F, nv):
    """Removes, until none is left, the faces around vertices whose faces form more than one fan."""
    while True:
        # A vertex is manifold when its faces' edges opposite... simpler: count boundary edges at
        # the vertex: a manifold vertex has 0 (interior) or 2 (one fan on the boundary).
        edges = np.concatenate([F[:, [0, 1]], F[:, [1, 2]], F[:, [2, 0]]])
        key = np.sort(edges, axis=1)
        unique, counts = np.unique(key, axis=0, return_counts=True)
        boundary = unique[counts == 1]
        per_vertex = np.bincount(boundary.ravel(), minlength=nv)
        bad = per_vertex > 2
        if not bad.any():
            return F
        F = F[~bad[F].any(axis=1)]


def main():
    source, target = sys.argv[1], sys.argv[2]
    V, F = read_off(source)
    for _ in range(2):
        V, F = subdivide(V, F)
    rng = np.random.default_rng(2004)
    centroid = V[F].mean(axis=1)
    low, high = V.min(0), V.max(0)
    size = np.linalg.norm(high - low)
    keep = np.ones(len(F), bool)
    for _ in range(8):  # strips the scanner missed
        normal = rng.normal(size=3)
        normal /= np.linalg.norm(normal)
        offset = normal @ (low + rng.random(3) * (high - low))
        keep &= np.abs(centroid @ normal - offset) > 0.002 * size
    for _ in range(40):  # occlusions
        centre = V[rng.integers(len(V))]
        keep &= np.linalg.norm(centroid - centre, axis=1) > rng.uniform(0.005, 0.02) * size
    F = drop_nonmanifold_vertices(F[keep], len(V))
    with open(target, "w") as f:
        f.write(f"OFF\n{len(V)} {len(F)} 0\n")
        np.savetxt(f, V, fmt="%.9g")
        np.savetxt(f, np.column_stack([np.full(len(F), 3), F]), fmt="%d")
    print(f"{target}: {len(V)} vertices ({len(np.unique(F))} used), {len(F)} faces")


if __name__ == "__main__":
    main()
