"""Mesh files for the end-to-end tests, Python standard library only.

read_ply reads the PLY files MeshLab writes (ASCII or binary, any properties, list properties such
as per-wedge texcoords); read_obj reads the OBJ inputs that the tests hand to meshlabserver as OFF
(its 2020.09 OBJ importer aborts on some valid files); write_off and write_ply write the meshes
the tests generate.
"""
import struct

_PLY_TYPES = {
    "char": "b", "int8": "b", "uchar": "B", "uint8": "B", "short": "h", "int16": "h",
    "ushort": "H", "uint16": "H", "int": "i", "int32": "i", "uint": "I", "uint32": "I",
    "float": "f", "float32": "f", "double": "d", "float64": "d",
}


class PlyElement:
    def __init__(self, name, count):
        self.name = name
        self.count = count
        self.properties = []  # (name, value type, list count type or None)
        self.data = {}        # property name -> list of values (a tuple per row for lists)

    def has(self, prop):
        return any(p[0] == prop for p in self.properties)


class Ply:
    def __init__(self):
        self.format = None
        self.comments = []
        self.elements = {}

    def vertices(self):
        v = self.elements["vertex"].data
        return list(zip(v["x"], v["y"], v["z"]))

    def faces(self):
        return self.elements["face"].data["vertex_indices"]

    def texture_files(self):
        return [c.split(None, 1)[1] for c in self.comments if c.startswith("TextureFile ")]


def read_ply(path):
    with open(path, "rb") as f:
        blob = f.read()
    end = blob.find(b"end_header")
    if not blob.startswith(b"ply") or end < 0:
        raise ValueError(f"{path}: not a PLY file")
    body = blob.index(b"\n", end) + 1
    ply = Ply()
    order = []
    for line in blob[:end].decode("ascii", "replace").splitlines()[1:]:
        words = line.split()
        if not words:
            continue
        if words[0] == "format":
            ply.format = words[1]
        elif words[0] == "comment":
            ply.comments.append(line.split(None, 1)[1] if len(words) > 1 else "")
        elif words[0] == "element":
            element = PlyElement(words[1], int(words[2]))
            ply.elements[element.name] = element
            order.append(element)
        elif words[0] == "property":
            if words[1] == "list":
                order[-1].properties.append((words[4], words[3], words[2]))
            else:
                order[-1].properties.append((words[2], words[1], None))
    if ply.format == "ascii":
        _read_ascii(order, blob[body:].decode("ascii").split())
    elif ply.format in ("binary_little_endian", "binary_big_endian"):
        _read_binary(order, memoryview(blob)[body:], "<" if ply.format == "binary_little_endian" else ">")
    else:
        raise ValueError(f"{path}: unknown PLY format {ply.format}")
    return ply


def _read_ascii(elements, words):
    pos = 0
    for element in elements:
        columns = {p[0]: [] for p in element.properties}
        for _ in range(element.count):
            for name, vtype, ctype in element.properties:
                cast = float if _PLY_TYPES[vtype] in "fd" else int
                if ctype is None:
                    columns[name].append(cast(words[pos]))
                    pos += 1
                else:
                    n = int(words[pos])
                    columns[name].append(tuple(cast(w) for w in words[pos + 1:pos + 1 + n]))
                    pos += 1 + n
        element.data = columns


def _read_binary(elements, data, endian):
    pos = 0
    for element in elements:
        columns = {p[0]: [] for p in element.properties}
        if all(p[2] is None for p in element.properties):
            row = struct.Struct(endian + "".join(_PLY_TYPES[p[1]] for p in element.properties))
            size = row.size * element.count
            for values in row.iter_unpack(data[pos:pos + size]):
                for (name, _, _), value in zip(element.properties, values):
                    columns[name].append(value)
            pos += size
        else:
            readers = []
            for name, vtype, ctype in element.properties:
                value = struct.Struct(endian + _PLY_TYPES[vtype])
                count = struct.Struct(endian + _PLY_TYPES[ctype]) if ctype else None
                readers.append((columns[name], value, count, _PLY_TYPES[vtype]))
            for _ in range(element.count):
                for column, value, count, code in readers:
                    if count is None:
                        column.append(value.unpack_from(data, pos)[0])
                        pos += value.size
                    else:
                        n = count.unpack_from(data, pos)[0]
                        pos += count.size
                        column.append(struct.unpack_from(f"{endian}{n}{code}", data, pos))
                        pos += n * value.size
        element.data = columns
    if pos != len(data):
        raise ValueError(f"PLY body has {len(data) - pos} unread bytes")


def read_obj(path):
    """Vertices and polygonal faces of an OBJ file ('v' and 'f' lines; texcoords, normals, groups
    and materials are ignored). Vertex order is kept: nothing is merged."""
    vertices, faces, _ = read_obj_with_texcoords(path)
    return vertices, faces


def read_obj_with_texcoords(path):
    """Vertices, faces and the (u, v) of every face corner that names one ('f v/vt'; None for a
    corner that does not), in face order."""
    vertices, texcoords, faces, corner_uv = [], [], [], []
    with open(path, errors="replace") as f:
        for line in f:
            words = line.split()
            if not words:
                continue
            if words[0] == "v":
                vertices.append(tuple(float(w) for w in words[1:4]))
            elif words[0] == "vt":
                try:
                    texcoords.append((float(words[1]), float(words[2]) if len(words) > 2 else 0.0))
                except (ValueError, IndexError):
                    texcoords.append(None)
            elif words[0] == "f":
                corners = [w.split("/") for w in words[1:]]
                face = [int(c[0]) for c in corners]
                faces.append([i - 1 if i > 0 else len(vertices) + i for i in face])
                corner_uv.extend(_texcoord(texcoords, c[1] if len(c) > 1 else "") for c in corners)
    return vertices, faces, corner_uv


def _texcoord(texcoords, index):
    """The (u, v) an OBJ corner names (1-based, or negative from the end), or None."""
    try:
        i = int(index)
        return texcoords[i - 1 if i > 0 else len(texcoords) + i] if i != 0 else None
    except (ValueError, IndexError):
        return None


def read_off(path):
    """Vertices and faces of an OFF file (comments and the optional colour columns ignored)."""
    with open(path) as f:
        words = [w for line in f for w in line.split("#")[0].split()]
    if not words or not words[0].endswith("OFF"):
        raise ValueError(f"{path}: not an OFF file")
    nv, nf = int(words[1]), int(words[2])
    at = 4
    stride = 7 if words[0] == "COFF" else 3  # COFF: RGBA after each vertex
    vertices = []
    for _ in range(nv):
        vertices.append(tuple(float(w) for w in words[at:at + 3]))
        at += stride
    faces = []
    for _ in range(nf):
        n = int(words[at])
        faces.append([int(w) for w in words[at + 1:at + 1 + n]])
        at += 1 + n
        while at < len(words) and not _is_int(words[at]):  # a face colour given as floats
            at += 1
    return vertices, faces


def _is_int(word):
    return word.lstrip("-").isdigit()


def write_off(path, vertices, faces):
    with open(path, "w") as f:
        f.write(f"OFF\n{len(vertices)} {len(faces)} 0\n")
        for v in vertices:
            f.write("%.9g %.9g %.9g\n" % tuple(v))
        for face in faces:
            f.write(f"{len(face)} " + " ".join(str(i) for i in face) + "\n")


def write_ply(path, vertices, faces, vertex_quality=None):
    """ASCII PLY with optional per-vertex quality (MeshLab loads it as vertex quality)."""
    with open(path, "w") as f:
        f.write(f"ply\nformat ascii 1.0\nelement vertex {len(vertices)}\n"
                "property float x\nproperty float y\nproperty float z\n")
        if vertex_quality is not None:
            f.write("property float quality\n")
        f.write(f"element face {len(faces)}\nproperty list uchar int vertex_indices\nend_header\n")
        for i, v in enumerate(vertices):
            f.write("%.9g %.9g %.9g" % tuple(v))
            f.write(" %g\n" % vertex_quality[i] if vertex_quality is not None else "\n")
        for face in faces:
            f.write(f"{len(face)} " + " ".join(str(i) for i in face) + "\n")
