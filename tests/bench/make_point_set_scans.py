#!/usr/bin/env python3
"""Surfaces of real scanner point sets, reconstructed the way MeshLab users do it, and written as
they come out (no cleaning), one OFF file per point set and method: NAME_ball_pivoting,
NAME_poisson and NAME_vcg. The point sets are CGAL's (its data/points_3 folder):
  hippo1, hippo2, oni (PLY with normals), kitten (XYZ with normals), radar (XYZ, no normals),
  building (PLY with normals, 100,000 points), b9_training (PLY, no normals, a labelled city scan).
Normals missing from the file are estimated by MeshLab (10 neighbours). The methods:
  ball_pivoting  MeshLab's ball pivoting, automatic radius
  poisson        MeshLab's screened Poisson, depth 8, one thread (two give a different mesh each run)
  vcg            MeshLab's VCG volumetric merge of the ball-pivoted mesh as one range map (voxel
                 0.5% of the box diagonal); skipped, with a message, where MeshLab refuses it
Nothing random, so the same files every run. Needs numpy 2.4.6 and pymeshlab 2025.7.post1 (the
Python of tests/bench/make_reconstructions.py). The VCG merge writes scratch files in the working
folder, so everything runs in a temporary one.

usage: make_point_set_scans.py POINTS_FOLDER OUT_FOLDER [POINT_SET...]
  POINT_SET: file names of POINT_SETS to reconstruct (default: all of them)
"""
import os
import sys
import tempfile
import time

import numpy as np
import pymeshlab

POINT_SETS = ["hippo1.ply", "hippo2.ply", "oni.ply", "kitten.xyz", "radar.xyz", "building.ply", "b9_training.ply"]


def write_off(path, V, F):
    with open(path, "w") as f:
        f.write(f"OFF\n{len(V)} {len(F)} 0\n")
        np.savetxt(f, V, fmt="%.17g")
        np.savetxt(f, np.column_stack([np.full(len(F), 3), F]), fmt="%d")


def load_points(path):
    """A MeshSet holding the point set, with its normals (estimated where the file has none)."""
    ms = pymeshlab.MeshSet()
    if path.endswith(".xyz"):
        data = np.loadtxt(path, ndmin=2)
        if data.shape[1] >= 6:
            ms.add_mesh(pymeshlab.Mesh(vertex_matrix=data[:, :3], v_normals_matrix=data[:, 3:6]))
        else:
            ms.add_mesh(pymeshlab.Mesh(vertex_matrix=data[:, :3]))
    else:
        ms.load_new_mesh(path)
    if not np.abs(ms.current_mesh().vertex_normal_matrix()).sum(1).all():
        ms.compute_normal_for_point_clouds(k=10)
    return ms


def quietly(call):
    """call() with stdout and stderr closed (the VCG merge prints its progress on both)."""
    sys.stdout.flush()
    saved = os.dup(1), os.dup(2)
    quiet = os.open(os.devnull, os.O_WRONLY)
    os.dup2(quiet, 1)
    os.dup2(quiet, 2)
    try:
        return call()
    finally:
        os.dup2(saved[0], 1)
        os.dup2(saved[1], 2)
        for fd in (quiet, *saved):
            os.close(fd)


def reconstructions(path):
    ms = load_points(path)
    ms.generate_surface_reconstruction_ball_pivoting()
    yield "ball_pivoting", ms.current_mesh()
    bpa = ms.current_mesh_id()
    ms.set_current_mesh(0)
    ms.generate_surface_reconstruction_screened_poisson(depth=8, threads=1)
    yield "poisson", ms.current_mesh()
    merge = pymeshlab.MeshSet()
    merge.add_mesh(ms.mesh(bpa))
    try:
        quietly(lambda: merge.generate_surface_reconstruction_vcg(voxsize=pymeshlab.PercentageValue(0.5)))
    except pymeshlab.PyMeshLabException as e:
        print(f"  vcg refused: {e}")
        return
    yield "vcg", merge.current_mesh()


def main():
    if len(sys.argv) < 3 or not set(sys.argv[3:]) <= set(POINT_SETS):
        sys.exit(__doc__)
    points, out = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
    chosen = sys.argv[3:] or POINT_SETS
    os.makedirs(out, exist_ok=True)
    here = os.getcwd()
    with tempfile.TemporaryDirectory() as scratch:
        os.chdir(scratch)
        for point_set in chosen:
            path = os.path.join(points, point_set)
            if not os.path.exists(path):
                print(f"{point_set}: missing, skipped")
                continue
            start = time.time()
            for method, mesh in reconstructions(path):
                name = f"{os.path.splitext(point_set)[0]}_{method}"
                V, F = mesh.vertex_matrix(), mesh.face_matrix()
                write_off(os.path.join(out, name + ".off"), V, F)
                print(f"{name}: {len(V)} vertices, {len(F)} faces, {time.time() - start:.1f} s")
                start = time.time()
        os.chdir(here)


if __name__ == "__main__":
    main()
