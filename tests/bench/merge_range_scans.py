#!/usr/bin/env python3
"""Real range scans merged into one surface by MeshLab's VCG volumetric merge, as a scanning
pipeline does, and written as they come out (no cleaning): OUT_FOLDER/NAME_vcg_VOXEL.off.

The scans are a folder in the Stanford 3D Scanning Repository's layout: PLY range maps and a
.conf file whose `bmesh FILE tx ty tz qx qy qz qw` lines place each one (the bunny's
bunny/data folder: bun000.ply ... bun315.ply, chin.ply, ear_back.ply, top2.ply, top3.ply and
bun.conf, from http://graphics.stanford.edu/data/3Dscanrep/). Keep them and the merges in the
cache (~/.cache/filter_lowstretch/real-scans), never in the repository.

VOXEL is the merge's voxel size in percent of the box diagonal: 1 gives the bunny 12,678 faces,
0.5 42,369, 0.25 160,239, 0.15 431,795, 0.1 960,979 (with the pinned pymeshlab). Nothing random,
so the same files every run. Needs numpy and pymeshlab 2025.7.post1 (the Python of
tests/bench/make_reconstructions.py); the merge writes scratch files in the working folder, so
it runs in a temporary one.

usage: merge_range_scans.py SCANS_FOLDER CONF_FILE OUT_FOLDER VOXEL...
"""
import os
import sys
import tempfile

import numpy as np
import pymeshlab

from make_point_set_scans import quietly, write_off


def rotation(x, y, z, w):
    """The rotation of the unit quaternion (x, y, z, w), as the .conf files store it."""
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
                     [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
                     [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]])


def placed_scans(folder, conf):
    """Each range map of the .conf file, its vertices moved where the file places them."""
    scans = []
    for line in open(conf):
        words = line.split()
        if not words or words[0] != "bmesh":
            continue
        translation, quaternion = np.array(words[2:5], float), [float(t) for t in words[5:9]]
        ms = pymeshlab.MeshSet()
        ms.load_new_mesh(os.path.join(folder, words[1]))
        mesh = ms.current_mesh()
        scans.append((words[1], mesh.vertex_matrix() @ rotation(*quaternion) + translation, mesh.face_matrix()))
    return scans


def main():
    if len(sys.argv) < 5:
        sys.exit(__doc__)
    folder, conf, out = (os.path.abspath(a) for a in sys.argv[1:4])
    voxels = [float(v) for v in sys.argv[4:]]
    scans = placed_scans(folder, conf)
    if not scans:
        sys.exit(f"{conf}: no bmesh line")
    name = os.path.splitext(os.path.basename(conf))[0]
    os.makedirs(out, exist_ok=True)
    here = os.getcwd()
    with tempfile.TemporaryDirectory() as scratch:
        os.chdir(scratch)
        for voxel in voxels:
            ms = pymeshlab.MeshSet()
            for scan, V, F in scans:
                ms.add_mesh(pymeshlab.Mesh(vertex_matrix=V, face_matrix=F), scan)
            quietly(lambda: ms.generate_surface_reconstruction_vcg(voxsize=pymeshlab.PercentageValue(voxel)))
            merged = ms.current_mesh()
            path = os.path.join(out, f"{name}_vcg_{voxel:g}.off")
            write_off(path, merged.vertex_matrix(), merged.face_matrix())
            print(f"{os.path.basename(path)}: {merged.vertex_number()} vertices, {merged.face_number()} faces")
        os.chdir(here)


if __name__ == "__main__":
    main()
