#!/usr/bin/env python3
"""Scan reconstructions of a clean mesh, made the way scan pipelines make them, and written as
they come out (no cleaning: duplicate vertices, zero-area faces, unreferenced vertices and
non-manifold edges kept), one OFF file each:
  ball_pivoting  MeshLab's ball pivoting on noisy points sampled from MESH (holes, non-manifold
                 and unreferenced vertices)
  vcg            MeshLab's VCG volumetric merge (marching cubes) of three ball-pivoted range
                 maps, each the noisy points facing one direction (parts, holes, tiny faces)
  poisson        MeshLab's screened Poisson on the noisy points (closed, tiny faces)
  sdf_mc         scikit-image's marching cubes on MESH's signed distance (MeshLab's), noisy and
                 quantized: exact zeros at grid vertices give zero-area faces and duplicate
                 vertex positions, the voxel-scale noise tiny handles and bubbles (dust)
  --big adds sdf_mc_big, the same on a grid of 400 cells instead of 128 with less noise (about
                 880,000 faces, all those defects at once; half a minute, 3.8 GB).
Seeded, so the same files every run. Needs numpy 2.4.6, pymeshlab 2025.7.post1 and scikit-image
0.26.0 (python3 -m venv ~/.cache/filter_lowstretch/scan-venv, then pip install those).
MeshLab's VCG merge writes scratch files in the working folder, so it runs in a temporary one.

  --small makes them smaller (tens of thousands of faces on a 20,000-face mesh: an eighth of the
                 samples, Poisson depth 6, twice the VCG voxel, half the grid), for the sanitizer build.

usage: make_reconstructions.py MESH OUT_FOLDER [--small] [--big]
"""
import os
import sys
import tempfile
import time
from collections import namedtuple

import numpy as np
import pymeshlab
from skimage.measure import label, marching_cubes

# Points sampled for the first three, screened Poisson's depth, the VCG merge's voxel (percent of
# the box diagonal) and the marching-cubes grid (cells along the longest side).
Size = namedtuple("Size", "samples depth voxel_percent cells")
FULL, SMALL = Size(60000, 8, 0.4, 128), Size(8000, 6, 0.8, 64)


def write_off(path, V, F):
    # float32 (scikit-image) round-trips in 9 digits, float64 (pymeshlab) needs 17.
    fmt = "%.9g" if V.dtype == np.float32 else "%.17g"
    with open(path, "w") as f:
        f.write(f"OFF\n{len(V)} {len(F)} 0\n")
        np.savetxt(f, V, fmt=fmt)
        np.savetxt(f, np.column_stack([np.full(len(F), 3), F]), fmt="%d")


def noisy_cloud(points, sigma, seed):
    """A point cloud layer: points moved by Gaussian noise, normals estimated from neighbours."""
    rng = np.random.default_rng(seed)
    ms = pymeshlab.MeshSet()
    ms.add_mesh(pymeshlab.Mesh(vertex_matrix=points + rng.normal(scale=sigma, size=points.shape)))
    ms.compute_normal_for_point_clouds(k=10)
    return ms


def current(ms):
    m = ms.current_mesh()
    return m.vertex_matrix(), m.face_matrix()


def reconstructions(mesh_path, size):
    ms = pymeshlab.MeshSet()
    ms.load_new_mesh(mesh_path)
    ms.generate_sampling_poisson_disk(samplenum=size.samples)
    points, normals = ms.current_mesh().vertex_matrix(), ms.current_mesh().vertex_normal_matrix()
    sigma = 0.0005 * np.linalg.norm(points.max(0) - points.min(0))
    cloud = noisy_cloud(points, sigma, 1)
    cloud.generate_surface_reconstruction_ball_pivoting()
    yield "ball_pivoting", current(cloud)
    cloud.set_current_mesh(0)
    # One thread: with two, the mesh differs from run to run.
    cloud.generate_surface_reconstruction_screened_poisson(depth=size.depth, threads=1)
    yield "poisson", current(cloud)
    # Range maps: the points facing each of three directions, noise of their own, ball pivoted.
    merge = pymeshlab.MeshSet()
    for k, direction in enumerate(np.eye(3)):
        view = noisy_cloud(points[normals @ direction > -0.2], sigma, 10 + k)
        view.generate_surface_reconstruction_ball_pivoting()
        merge.add_mesh(view.current_mesh())
    sys.stdout.flush()
    saved = os.dup(1), os.dup(2)
    quiet = os.open(os.devnull, os.O_WRONLY)
    os.dup2(quiet, 1)  # the VCG merge prints its progress on stdout and stderr
    os.dup2(quiet, 2)
    try:
        merge.generate_surface_reconstruction_vcg(voxsize=pymeshlab.PercentageValue(size.voxel_percent))
    finally:
        os.dup2(saved[0], 1)
        os.dup2(saved[1], 2)
        for fd in (quiet, *saved):
            os.close(fd)
    yield "vcg", current(merge)


def signed_distance(ms, points, maxdist):
    """MeshLab's signed distance from layer 0 at points; beyond maxdist it gives 2 * maxdist."""
    ms.add_mesh(pymeshlab.Mesh(vertex_matrix=points))
    ms.compute_scalar_by_distance_from_another_mesh_per_vertex(
        measuremesh=ms.current_mesh_id(), refmesh=0, signeddist=True, maxdist=pymeshlab.PureValue(maxdist))
    d = ms.current_mesh().vertex_scalar_array()
    ms.delete_current_mesh()
    return d


def sdf_mc(mesh_path, cells, noise, step, blobs, seed):
    """Marching cubes on the signed distance of the mesh on a grid of `cells` along its longest
    side, with `blobs` small blobs off the surface and Gaussian noise (`noise` cells), rounded to
    multiples of `step` cells. Distances are measured only in a band around the surface (found on
    a grid four times coarser); the rest takes the sign of the coarse grid's flood fill."""
    ms = pymeshlab.MeshSet()
    ms.load_new_mesh(mesh_path)
    V = ms.current_mesh().vertex_matrix()
    h = (V.max(0) - V.min(0)).max() / cells
    low = V.min(0) - 8 * h
    shape = np.ceil((V.max(0) + 8 * h - low) / h).astype(int) + 1
    # Coarse grid: everything, then outside = far cells reachable from the corner.
    cshape = shape // 4 + 2
    cpoints = np.stack(np.meshgrid(*[np.arange(n) for n in cshape], indexing="ij"), -1).reshape(-1, 3)
    coarse = signed_distance(ms, low + 4 * h * cpoints, 16 * h).reshape(cshape)
    far = coarse >= 31.9 * h
    regions = label(far, connectivity=1)
    sign = np.where(far, np.where(regions == regions[0, 0, 0], 1.0, -1.0), np.sign(coarse))
    near = np.abs(coarse) < 7 * h  # holds every fine grid vertex within 3.5 cells of the surface
    # Fine grid: a big value of the coarse sign, the measured distance in the band.
    fine = np.stack(np.meshgrid(*[np.arange(n) for n in shape], indexing="ij"), -1).reshape(-1, 3)
    nearest = tuple(np.rint(fine / 4).astype(int).T)
    band = near[nearest]
    d = 8.0 * sign[nearest]
    d[band] = signed_distance(ms, low + h * fine[band], 12 * h) / h
    d = d.reshape(shape)
    del fine, nearest, band
    rng = np.random.default_rng(seed)
    # Stray measurements: blobs of 0.5 to 1.5 cells radius, 2 to 6 cells out from the surface.
    centres = np.argwhere((d > 2) & (d < 6))
    offsets = np.stack(np.meshgrid(*[np.arange(-2, 3)] * 3, indexing="ij"), -1).reshape(-1, 3)
    for c in centres[rng.choice(len(centres), blobs, replace=False)]:
        at = tuple((c + offsets).T)
        d[at] = np.minimum(d[at], np.linalg.norm(offsets, axis=1) - rng.uniform(0.5, 1.5))
    d += rng.normal(scale=noise, size=d.shape)
    d = np.rint(d / step) * step  # many grid values exactly 0: vertices on grid corners
    V, F, _, _ = marching_cubes(d.astype(np.float32), 0.0, spacing=(h, h, h))
    return (V + low).astype(np.float32), F


def main():
    args = [a for a in sys.argv[1:] if a not in ("--big", "--small")]
    size = SMALL if "--small" in sys.argv else FULL
    if len(args) != 2:
        sys.exit(__doc__)
    mesh_path, out = os.path.abspath(args[0]), os.path.abspath(args[1])
    os.makedirs(out, exist_ok=True)
    todo = [("sdf_mc", lambda: sdf_mc(mesh_path, size.cells, 0.4, 1 / 256, 30, 3))]
    if "--big" in sys.argv:
        todo.append(("sdf_mc_big", lambda: sdf_mc(mesh_path, 400, 0.22, 1 / 256, 150, 4)))
    here = os.getcwd()
    with tempfile.TemporaryDirectory() as scratch:
        os.chdir(scratch)
        start = time.time()
        for name, (V, F) in reconstructions(mesh_path, size):
            write_off(os.path.join(out, name + ".off"), V, F)
            print(f"{name}: {len(V)} vertices, {len(F)} faces, {time.time() - start:.1f} s")
            start = time.time()
        os.chdir(here)
    for name, make in todo:
        start = time.time()
        V, F = make()
        write_off(os.path.join(out, name + ".off"), V, F)
        print(f"{name}: {len(V)} vertices, {len(F)} faces, {time.time() - start:.1f} s")


if __name__ == "__main__":
    main()
