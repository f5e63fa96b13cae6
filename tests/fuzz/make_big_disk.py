#!/usr/bin/env python3
"""Writes a big disk for the scale test: an n x n grid of vertices over [0,1]^2 with a wavy z
(2 (n-1)^2 triangles), as binary little-endian PLY (float x y z; uchar/int face lists).

usage: make_big_disk.py OUT.ply [N]      (N = 1415 vertices a side: 2,002,225 vertices)
then:  /usr/bin/time -v build/lowstretch OUT.ply --json --max-passes 2
"""
import array
import math
import sys


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    out = sys.argv[1]
    n = int(sys.argv[2]) if len(sys.argv) > 2 else 1415
    faces = 2 * (n - 1) * (n - 1)
    with open(out, "wb") as f:
        f.write(("ply\nformat binary_little_endian 1.0\ncomment wavy grid disk, make_big_disk.py\n"
                 "element vertex %d\nproperty float x\nproperty float y\nproperty float z\n"
                 "element face %d\nproperty list uchar int vertex_indices\nend_header\n" % (n * n, faces)).encode())
        if sys.byteorder != "little":
            sys.exit("make_big_disk.py: written for a little-endian machine")
        for j in range(n):
            y = j / (n - 1)
            row = array.array("f")
            for i in range(n):
                x = i / (n - 1)
                row.extend((x, y, 0.1 * math.sin(6 * x) * math.cos(4 * y)))
            f.write(row.tobytes())
        for j in range(n - 1):
            row = bytearray()
            for i in range(n - 1):
                a, b, c, d = j * n + i, j * n + i + 1, (j + 1) * n + i + 1, (j + 1) * n + i
                t = (a, b, c, a, c, d) if (i + j) % 2 == 0 else (a, b, d, b, c, d)
                row += b"\x03" + array.array("i", t[:3]).tobytes() + b"\x03" + array.array("i", t[3:]).tobytes()
            f.write(row)
    print("make_big_disk: %s, %d vertices, %d faces" % (out, n * n, faces))


if __name__ == "__main__":
    main()
