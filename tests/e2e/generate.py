"""Small meshes the end-to-end tests make themselves: disks the filter must parameterize, and
meshes it must reject. Each function returns (vertices, faces), faces counter-clockwise seen from
outside, so that the only thing wrong with a bad mesh is the thing its name says."""
import math


def wavy_grid(n=24, amplitude=0.2, offset=(0.0, 0.0, 0.0)):
    """A disk: the unit square as an n x n grid of quads split into triangles, with a bumpy z."""
    ox, oy, oz = offset
    vertices = []
    for j in range(n + 1):
        for i in range(n + 1):
            x, y = i / n, j / n
            z = amplitude * math.sin(2 * math.pi * x) * math.cos(3 * math.pi * y)
            vertices.append((x + ox, y + oy, z + oz))
    faces = []
    for j in range(n):
        for i in range(n):
            v00, v10 = j * (n + 1) + i, j * (n + 1) + i + 1
            v01, v11 = v00 + n + 1, v10 + n + 1
            if (i + j) % 2 == 0:
                faces += [(v00, v10, v11), (v00, v11, v01)]
            else:
                faces += [(v00, v10, v01), (v10, v11, v01)]
    return vertices, faces


def hemisphere(rings=12):
    """A disk: the upper unit hemisphere, a pole and rings of 6*i vertices down to the equator."""
    vertices = [(0.0, 0.0, 1.0)]
    ring_start = [0]
    for r in range(1, rings + 1):
        theta = 0.5 * math.pi * r / rings
        ring_start.append(len(vertices))
        for k in range(6 * r):
            phi = 2 * math.pi * k / (6 * r)
            vertices.append((math.sin(theta) * math.cos(phi), math.sin(theta) * math.sin(phi), math.cos(theta)))
    faces = [(0, ring_start[1] + k, ring_start[1] + (k + 1) % 6) for k in range(6)]
    for r in range(2, rings + 1):
        inner = [ring_start[r - 1] + k for k in range(6 * (r - 1))]
        outer = [ring_start[r] + k for k in range(6 * r)]
        a = b = 0
        while a < len(inner) or b < len(outer):
            # Advance along the ring whose next vertex comes first in angle.
            if b < len(outer) and (a == len(inner) or (b + 1) / len(outer) <= (a + 1) / len(inner)):
                faces.append((inner[a % len(inner)], outer[b], outer[(b + 1) % len(outer)]))
                b += 1
            else:
                faces.append((inner[a], outer[b % len(outer)], inner[(a + 1) % len(inner)]))
                a += 1
    return vertices, faces


def grid_with_unused_vertices(n=16):
    """The wavy grid with three vertices that no face uses (one far away), spread through the list."""
    vertices, faces = wavy_grid(n)
    extra = {5: (9.0, 9.0, 9.0), 40: (0.5, 0.5, 3.0), 100: (-7.0, 2.0, 0.0)}
    new_index, out = [], []
    for k, v in enumerate(vertices):
        if k in extra:
            out.append(extra[k])
        new_index.append(len(out))
        out.append(v)
    return out, [tuple(new_index[i] for i in f) for f in faces]


def two_components():
    """Not a disk: two separate wavy grids."""
    v1, f1 = wavy_grid(8)
    v2, f2 = wavy_grid(8, offset=(2.0, 0.0, 0.0))
    return v1 + v2, f1 + [tuple(i + len(v1) for i in f) for f in f2]


def unwelded():
    """Not welded: the wavy grid as a triangle soup, every face with vertices of its own (as STL
    stores a mesh)."""
    vertices, faces = wavy_grid(8)
    return [vertices[i] for f in faces for i in f], [(3 * k, 3 * k + 1, 3 * k + 2) for k in range(len(faces))]


def tetrahedron():
    """Not a disk: closed."""
    vertices = [(1, 1, 1), (1, -1, -1), (-1, 1, -1), (-1, -1, 1)]
    faces = [(0, 1, 2), (0, 3, 1), (0, 2, 3), (1, 3, 2)]
    return vertices, faces


def octahedron():
    """Not a disk: closed."""
    vertices = [(1, 0, 0), (-1, 0, 0), (0, 1, 0), (0, -1, 0), (0, 0, 1), (0, 0, -1)]
    faces = [(0, 2, 4), (2, 1, 4), (1, 3, 4), (3, 0, 4), (2, 0, 5), (1, 2, 5), (3, 1, 5), (0, 3, 5)]
    return vertices, faces


def three_holes(n=20):
    """Not a disk: a grid with two square holes, so three boundary loops (unused vertices dropped)."""
    vertices, faces = wavy_grid(n)
    def in_hole(face):
        xs = [vertices[i][0] * n for i in face]
        ys = [vertices[i][1] * n for i in face]
        cx, cy = sum(xs) / 3, sum(ys) / 3
        return (4 < cx < 8 and 4 < cy < 8) or (12 < cx < 16 and 12 < cy < 16)
    faces = [f for f in faces if not in_hole(f)]
    used = sorted({i for f in faces for i in f})
    new_index = {old: new for new, old in enumerate(used)}
    return [vertices[i] for i in used], [tuple(new_index[i] for i in f) for f in faces]


def point_cloud():
    """Not a mesh: the wavy grid's vertices and no face."""
    vertices, _ = wavy_grid(8)
    return vertices, []


def disk_with_flap(n=16, every=7):
    """The wavy grid plus a separate strip (a second component) whose vertices and faces are
    interleaved with the grid's. Returns (vertices, faces, quality): quality is 1 on the strip and
    0 on the grid, so that MeshLab can select the strip by quality and delete it. The grid's own
    vertices and faces keep their relative order, so deleting the strip gives wavy_grid(n) back."""
    grid_v, grid_f = wavy_grid(n)
    strip_v = [(2.0 + 0.1 * (k // 2), 0.1 * (k % 2), 0.0) for k in range(12)]
    strip_f = [(k, k + 2, k + 1) if k % 2 == 0 else (k, k + 1, k + 2) for k in range(10)]
    vertices, quality, grid_index, strip_index = [], [], [], []
    for k, v in enumerate(grid_v):  # one strip vertex after every `every` grid vertices
        if k % every == every - 1 and len(strip_index) < len(strip_v):
            strip_index.append(len(vertices))
            vertices.append(strip_v[len(strip_index) - 1])
            quality.append(1.0)
        grid_index.append(len(vertices))
        vertices.append(v)
        quality.append(0.0)
    while len(strip_index) < len(strip_v):
        strip_index.append(len(vertices))
        vertices.append(strip_v[len(strip_index) - 1])
        quality.append(1.0)
    faces, strip_left = [], list(strip_f)
    for k, f in enumerate(grid_f):
        if k % every == every - 1 and strip_left:
            faces.append(tuple(strip_index[i] for i in strip_left.pop(0)))
        faces.append(tuple(grid_index[i] for i in f))
    faces += [tuple(strip_index[i] for i in f) for f in strip_left]
    return vertices, faces, quality


def torus(rings=24, sectors=12):
    """Not a disk: closed, genus 1."""
    vertices = [((2 + math.cos(2 * math.pi * s / sectors)) * math.cos(2 * math.pi * r / rings),
                 (2 + math.cos(2 * math.pi * s / sectors)) * math.sin(2 * math.pi * r / rings),
                 math.sin(2 * math.pi * s / sectors)) for r in range(rings) for s in range(sectors)]
    def vid(r, s):
        return (r % rings) * sectors + s % sectors
    faces = []
    for r in range(rings):
        for s in range(sectors):
            faces += [(vid(r, s), vid(r + 1, s), vid(r + 1, s + 1)), (vid(r, s), vid(r + 1, s + 1), vid(r, s + 1))]
    return vertices, faces


def sphere(rings=12, sectors=16):
    """Not a disk: closed, genus 0 (a UV sphere)."""
    vertices = [(0.0, 0.0, 1.0), (0.0, 0.0, -1.0)]
    for r in range(1, rings):
        theta = math.pi * r / rings
        vertices += [(math.sin(theta) * math.cos(2 * math.pi * s / sectors),
                      math.sin(theta) * math.sin(2 * math.pi * s / sectors), math.cos(theta)) for s in range(sectors)]
    def vid(r, s):
        return 2 + (r - 1) * sectors + s % sectors
    faces = [(0, vid(1, s), vid(1, s + 1)) for s in range(sectors)]
    faces += [(1, vid(rings - 1, s + 1), vid(rings - 1, s)) for s in range(sectors)]
    for r in range(1, rings - 1):
        for s in range(sectors):
            faces += [(vid(r, s), vid(r + 1, s), vid(r + 1, s + 1)), (vid(r, s), vid(r + 1, s + 1), vid(r, s + 1))]
    return vertices, faces


DISKS = {"wavy_grid": wavy_grid, "hemisphere": hemisphere, "grid_with_unused_vertices": grid_with_unused_vertices}
BAD = {"two_components": two_components, "tetrahedron": tetrahedron, "octahedron": octahedron,
       "three_holes": three_holes, "point_cloud": point_cloud, "unwelded": unwelded}
# Not disks, but manifold and oriented: "Make charts" parameterizes them.
NON_DISKS = {"two_components": two_components, "three_holes": three_holes, "octahedron": octahedron,
             "torus": torus, "sphere": sphere}
