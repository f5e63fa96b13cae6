#!/usr/bin/env python3
"""Real range scans merged into one surface by MeshLab's VCG volumetric merge, as a scanning
pipeline does, and written as they come out (no cleaning): OUT_FOLDER/NAME_vcg_VOXEL.off.

The scans are a folder in the Stanford 3D Scanning Repository's layout: PLY range maps and a
.conf file whose `bmesh FILE tx ty tz qx qy qz qw` lines place each one (the bunny's
bunny/data folder: bun000.ply ... bun315.ply, chin.ply, ear_back.ply, top2.ply, top3.ply and
bun.conf, from http://graphics.stanford.edu/data/3Dscanrep/). Keep them and the merges in the
cache (~/.cache/filter_lowstretch/real-scans), never in the repository.

VOXEL is the merge's voxel size in percent of the diagonal of all placed scans: the bunny's ten
scans give 27,623 faces at 1, 104,295 at 0.5, 433,016 at 0.25, 771,931 at 0.19 and 859,652 at 0.18
(with the pinned pymeshlab). Nothing random, so the same files every run. Needs numpy and
pymeshlab 2025.7.post1 (the Python of tests/bench/make_reconstructions.py); the merge writes
scratch files in the working folder, so it runs in a temporary one.

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


def vcg_merge(scans, voxel):
    """MeshLab's VCG merge of the placed scans (name, V, F) at the voxel size (absolute), run in the
    working folder. The merge saves each layer to a scratch file named after the file it was read
    from, so each scan is read from a file of its own: layers made from arrays would all share one
    name, and only the last would be merged (as many times as there are scans)."""
    ms = pymeshlab.MeshSet()
    for name, V, F in scans:
        scan = pymeshlab.MeshSet()
        scan.add_mesh(pymeshlab.Mesh(vertex_matrix=V, face_matrix=F))
        path = os.path.abspath("placed_" + os.path.splitext(name)[0] + ".ply")
        scan.save_current_mesh(path)
        ms.load_new_mesh(path)
    quietly(lambda: ms.generate_surface_reconstruction_vcg(voxsize=pymeshlab.PureValue(voxel)))
    return ms.current_mesh().vertex_matrix(), ms.current_mesh().face_matrix()


def diagonal(scans):
    """The diagonal of the box of all placed scans."""
    V = np.vstack([V for _, V, _ in scans])
    return float(np.linalg.norm(V.max(0) - V.min(0)))


def write_merges(scans, voxels, diagonal, out, stem):
    """OUT/STEM_VOXEL.off for each voxel size (in % of `diagonal`): the scans merged, in a scratch
    folder (the merge writes files in the working folder)."""
    here = os.getcwd()
    with tempfile.TemporaryDirectory() as scratch:
        os.chdir(scratch)
        for voxel in voxels:
            V, F = vcg_merge(scans, voxel / 100 * diagonal)
            path = os.path.join(out, f"{stem}_{voxel:g}.off")
            write_off(path, V, F)
            print(f"{os.path.basename(path)}: {len(V)} vertices, {len(F)} faces")
        os.chdir(here)


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
    write_merges(scans, voxels, diagonal(scans), out, f"{name}_vcg")


if __name__ == "__main__":
    main()
