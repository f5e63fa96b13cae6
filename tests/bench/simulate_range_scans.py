#!/usr/bin/env python3
"""A scanning session of a mesh simulated and merged by MeshLab's VCG volumetric merge, as
merge_range_scans.py merges real range scans, and written as it comes out (no cleaning):
OUT_FOLDER/NAME_sim_VOXEL.off. Real merges have defects that generated meshes miss: caps and
needles by the thousand, vertices close but not equal, loose sheets and tiny handles at fine
voxels; this makes them from any mesh (e.g. Debian's CGAL demo armadillo.off), at any size.

The scanner: VIEWS range maps (all but two on a ring around the y axis, at seeded heights and
turns, then the top and the bottom), each an orthographic PIXELS x PIXELS depth grid across the
mesh's box diagonal (the bunny's scans sample at about 0.2% of it). Each pixel's depth is the
nearest surface point on its ray (triangles rasterized exactly), plus noise along the ray; pixels
seen at a grazing angle are dropped, and so are grid triangles across a depth step. Each range
map is a PLY mesh in its scanner's frame, placed by a `bmesh FILE tx ty tz qx qy qz qw` line of
NAME.conf (the Stanford layout, read by merge_range_scans.placed_scans; the placement slightly
off, as a registration leaves it), kept in OUT_FOLDER/NAME_scans.

VOXEL is the merge's voxel size in percent of the mesh's box diagonal: armadillo.off gives 52,932
faces at 0.66 and 802,500 at 0.17 (4 s and 21 s on 2 cores); bun_zipper.ply 52,991 at 0.75.
Nothing random: seeded, the same files every run. Needs numpy and pymeshlab 2025.7.post1 (the
Python of tests/bench/make_reconstructions.py, ~/.cache/filter_lowstretch/scan-venv); the merge
writes scratch files in the working folder, so it runs in a temporary one.

usage: simulate_range_scans.py MESH OUT_FOLDER VOXEL... [--views N] [--pixels P] [--seed S]
  N: range maps (default 12), P: pixels a side (default 450), S: seed (default 1)
"""
import argparse
import os

import numpy as np
import pymeshlab

from merge_range_scans import placed_scans, rotation, write_merges

# Fitted to the bunny's scans (roughness, long triangles, holes) and merges (parts, handles):
NOISE = 0.12  # depth noise, standard deviation in grid steps
STEP = 45  # largest depth difference in a kept grid triangle, in grid steps (Stanford's keep ~50x long edges)
GRAZING = 89  # pixels whose surface turns further from the ray (degrees) are dropped
MISALIGN = 0.3  # registration error of each placement, in grid steps


def quaternion(R):
    """The unit quaternion (x, y, z, w) whose rotation() is the rotation matrix R."""
    (a, b, c), (d, e, f), (g, h, i) = R
    K = np.array([[a - e - i, d + b, g + c, h - f], [d + b, e - a - i, h + f, c - g],
                  [g + c, h + f, i - a - e, d - b], [h - f, c - g, d - b, a + e + i]]) / 3
    q = np.linalg.eigh(K)[1][:, -1]
    return q if q[3] >= 0 else -q


def views(count, rng):
    """Rotations taking the world to each scanner's frame (its z axis toward the scanner)."""
    ring = count - 2
    out = []
    for k in range(count):
        if k < ring:
            azimuth = 2 * np.pi * (k + rng.uniform(-0.3, 0.3)) / ring
            elevation = rng.uniform(-0.4, 0.4)
        else:
            azimuth = rng.uniform(0, 2 * np.pi)
            elevation = (1 if k == ring else -1) * rng.uniform(1.2, 1.4)
        z = np.array([np.cos(elevation) * np.sin(azimuth), np.sin(elevation), np.cos(elevation) * np.cos(azimuth)])
        x = np.cross([0, 1, 0], z) if abs(z[1]) < 0.9 else np.cross([0, 0, 1], z)
        x /= np.linalg.norm(x)
        roll = rng.uniform(-0.3, 0.3)
        y = np.cross(z, x)
        x, y = np.cos(roll) * x + np.sin(roll) * y, np.cos(roll) * y - np.sin(roll) * x
        out.append(np.array([x, y, z]))
    return out


def depth_grid(P, F, pixels):
    """Per pixel (centres at integer x, y of the scanner frame P), the largest z of the surface
    there and the facing (|z| of the unit normal) of its triangle; -inf where nothing is."""
    T = P[F]
    lo, hi = np.ceil(T[:, :, :2].min(1)).astype(int), np.floor(T[:, :, :2].max(1)).astype(int)
    lo, hi = np.maximum(lo, 0), np.minimum(hi, pixels - 1)
    n = np.cross(T[:, 1] - T[:, 0], T[:, 2] - T[:, 0])
    size = np.where(n[:, 2:] != 0, np.maximum(hi - lo + 1, 0), 0)  # edge-on triangles cover nothing
    count = size[:, 0] * size[:, 1]
    t = np.repeat(np.arange(len(F)), count)
    local = np.arange(len(t)) - np.repeat(np.cumsum(count) - count, count)
    x, y = lo[t, 0] + local % size[t, 0], lo[t, 1] + local // size[t, 0]
    a, b, c, area = T[t, 0], T[t, 1], T[t, 2], n[t, 2]
    wb = ((x - a[:, 0]) * (c[:, 1] - a[:, 1]) - (y - a[:, 1]) * (c[:, 0] - a[:, 0])) / area
    wc = ((b[:, 0] - a[:, 0]) * (y - a[:, 1]) - (b[:, 1] - a[:, 1]) * (x - a[:, 0])) / area
    inside = (wb >= 0) & (wc >= 0) & (wb + wc <= 1)
    z = (a[:, 2] + wb * (b[:, 2] - a[:, 2]) + wc * (c[:, 2] - a[:, 2]))[inside]
    pixel, t = (y * pixels + x)[inside], t[inside]
    depth = np.full(pixels * pixels, -np.inf)
    np.maximum.at(depth, pixel, z)
    facing = np.zeros(pixels * pixels)
    top = z == depth[pixel]
    facing[pixel[top]] = np.abs(n[t[top], 2]) / np.linalg.norm(n[t[top]], axis=1)
    return depth.reshape(pixels, pixels), facing.reshape(pixels, pixels)


def range_map(P, F, pixels, rng):
    """The scanner's mesh of the surface P (scanner frame, in grid steps): vertices (x, y, depth)
    of the pixels it sees, two triangles per grid square whose corners it all sees at close depth."""
    depth, facing = depth_grid(P, F, pixels)
    seen = np.isfinite(depth) & (facing > np.cos(np.radians(GRAZING)))
    depth = np.where(seen, depth + rng.normal(0, NOISE, depth.shape), 0)
    index = np.cumsum(seen).reshape(seen.shape) - 1
    y, x = np.nonzero(seen)
    V = np.column_stack([x, y, depth[y, x]]).astype(float)
    corners = [(0, 0), (1, 0), (0, 1), (1, 0), (1, 1), (0, 1)]
    faces = []
    for k in (0, 3):
        cy, cx = zip(*[(slice(dy, pixels - 1 + dy), slice(dx, pixels - 1 + dx))
                       for dx, dy in corners[k:k + 3]])
        s = [seen[cy[j], cx[j]] for j in range(3)]
        d = [depth[cy[j], cx[j]] for j in range(3)]
        keep = s[0] & s[1] & s[2] & (np.maximum.reduce(d) - np.minimum.reduce(d) < STEP)
        faces.append(np.column_stack([index[cy[j], cx[j]][keep] for j in range(3)]))
    return V, np.concatenate(faces)


def scan(V, F, folder, name, count, pixels, seed):
    """Writes the session's PLY range maps and FOLDER/NAME.conf placing them; the .conf's path."""
    rng = np.random.default_rng(seed)
    centre = (V.min(0) + V.max(0)) / 2
    step = np.linalg.norm(V.max(0) - V.min(0)) / pixels
    conf = os.path.join(folder, name + ".conf")
    with open(conf, "w") as f:
        for k, R in enumerate(views(count, rng)):
            P = (V - centre) @ R.T / step + [pixels / 2, pixels / 2, 0]
            G, T = range_map(P, F, pixels, rng)
            ms = pymeshlab.MeshSet()
            ms.add_mesh(pymeshlab.Mesh(vertex_matrix=(G - [pixels / 2, pixels / 2, 0]) * step, face_matrix=T))
            ms.meshing_remove_unreferenced_vertices()
            ply = f"{name}_{k:02d}.ply"
            ms.save_current_mesh(os.path.join(folder, ply))
            # placed_scans() places vertex rows as V @ rotation(q) + t: q is R's own quaternion.
            axis, angle = rng.normal(size=3), rng.normal(0, MISALIGN) / pixels  # MISALIGN steps at a diagonal
            turn = np.append(np.sin(angle / 2) * axis / np.linalg.norm(axis), np.cos(angle / 2))
            q = quaternion(rotation(*turn) @ R)
            t = centre + rng.normal(0, MISALIGN * step, 3)
            f.write(f"bmesh {ply} {' '.join(f'{v:.9g}' for v in t)} {' '.join(f'{v:.9g}' for v in q)}\n")
    return conf


def main():
    parser = argparse.ArgumentParser(usage=__doc__.split("usage: ")[1])
    parser.add_argument("mesh")
    parser.add_argument("out")
    parser.add_argument("voxels", nargs="+", type=float)
    parser.add_argument("--views", type=int, default=12)
    parser.add_argument("--pixels", type=int, default=450)
    parser.add_argument("--seed", type=int, default=1)
    args = parser.parse_args()
    out = os.path.abspath(args.out)
    name = os.path.splitext(os.path.basename(args.mesh))[0]
    ms = pymeshlab.MeshSet()
    ms.load_new_mesh(os.path.abspath(args.mesh))
    folder = os.path.join(out, name + "_scans")
    os.makedirs(folder, exist_ok=True)
    conf = scan(ms.current_mesh().vertex_matrix(), ms.current_mesh().face_matrix(), folder, name,
                args.views, args.pixels, args.seed)
    scans = placed_scans(folder, conf)
    diagonal = np.linalg.norm(np.ptp(ms.current_mesh().vertex_matrix(), axis=0))
    write_merges(scans, args.voxels, diagonal, out, f"{name}_sim")


if __name__ == "__main__":
    main()
