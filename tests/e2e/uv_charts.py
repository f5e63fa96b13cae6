"""An atlas's charts read from its texture coordinates, as the filter's "Pack again only" reads them
(filter_lowstretch/atlas/repack.h): faces joined where an edge's two corners have the same texcoords
on both sides. Pure Python: the e2e tests and pymeshlab's environment both use it."""


def uv_charts(faces, triangles):
    """Each face's chart, numbered in order of first face. faces: vertex index triples; triangles:
    per face, the (u, v) of its three corners."""
    parent = list(range(len(faces)))

    def find(x):
        while parent[x] != x:
            parent[x] = parent[parent[x]]
            x = parent[x]
        return x

    sides = {}
    for f, (face, uv) in enumerate(zip(faces, triangles)):
        for k in range(3):
            a, b = face[k], face[(k + 1) % 3]
            ends = (tuple(uv[k]), tuple(uv[(k + 1) % 3]))
            key, pair = (min(a, b), max(a, b)), ends if a < b else ends[::-1]
            for g, other in sides.get(key, []):
                if other == pair:
                    parent[find(f)] = find(g)
            sides.setdefault(key, []).append((f, pair))
    number = {}
    return [number.setdefault(find(f), len(number)) for f in range(len(faces))]
