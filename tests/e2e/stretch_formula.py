"""The stretch of a parameterization as the core computes it (filter_lowstretch/core/METHOD.md
section 2), written once for the Python tests (e2e.py, test_pymeshlab.py)."""
import math


def derivatives(e1, e2, uv):
    """The 3D derivatives S_s, S_t of the map of a triangle with 3D edge vectors e1 = p2 - p1,
    e2 = p3 - p1 and texcoords uv = (s1, t1, s2, t2, s3, t3), and its parameter area A_U; the
    derivatives are None when A_U <= 0."""
    s1, t1, s2, t2, s3, t3 = uv
    area_u = 0.5 * ((s2 - s1) * (t3 - t1) - (s3 - s1) * (t2 - t1))
    if area_u <= 0:
        return None, None, area_u
    ss = [(e1[c] * (t3 - t1) - e2[c] * (t2 - t1)) / (2 * area_u) for c in range(3)]
    st = [(e2[c] * (s2 - s1) - e1[c] * (s3 - s1)) / (2 * area_u) for c in range(3)]
    return ss, st, area_u


def face_sigma(e1, e2, uv):
    """Stretch sqrt((a + c) / 2) of a triangle (arguments as derivatives()) and its parameter area
    A_U; inf when A_U <= 0."""
    ss, st, area_u = derivatives(e1, e2, uv)
    if ss is None:
        return math.inf, area_u
    return math.sqrt(0.5 * (sum(x * x for x in ss) + sum(x * x for x in st))), area_u


def edges_and_area(p1, p2, p3):
    """The edge vectors p2 - p1, p3 - p1 of a triangle and its 3D area."""
    e1 = [p2[c] - p1[c] for c in range(3)]
    e2 = [p3[c] - p1[c] for c in range(3)]
    cross = (e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0])
    return e1, e2, 0.5 * math.sqrt(sum(x * x for x in cross))


def map_stretch(vertices, faces, corner_uv):
    """Per face A_U and normalized sigma(T), the normalized L2 stretch and the 3D areas of a map
    given per corner: corner_uv[3 f + k] = (s, t) of corner k of face f."""
    area_u, sigma, area = [], [], []
    for f, (i, j, k) in enumerate(faces):
        e1, e2, a = edges_and_area(vertices[i], vertices[j], vertices[k])
        uv = (*corner_uv[3 * f], *corner_uv[3 * f + 1], *corner_uv[3 * f + 2])
        s, au = face_sigma(e1, e2, uv)
        sigma.append(s)
        area_u.append(au)
        area.append(a)
    scale = math.sqrt(sum(abs(x) for x in area_u) / sum(area))
    l2 = scale * math.sqrt(sum(a * s * s for a, s in zip(area, sigma)) / sum(area))
    return area_u, [scale * s for s in sigma], l2, area


def map_linf(vertices, faces, corner_uv):
    """The normalized Linf stretch of a map given per corner: the largest singular value of any
    triangle's map, sqrt((a + c + sqrt((a - c)^2 + 4 b^2)) / 2), times the same scale as map_stretch;
    inf when a triangle is flipped or has zero area."""
    worst, area_u_sum, area_sum = 0.0, 0.0, 0.0
    for f, (i, j, k) in enumerate(faces):
        e1, e2, a3 = edges_and_area(vertices[i], vertices[j], vertices[k])
        ss, st, area_u = derivatives(e1, e2, (*corner_uv[3 * f], *corner_uv[3 * f + 1], *corner_uv[3 * f + 2]))
        area_u_sum += abs(area_u)
        area_sum += a3
        if ss is None:
            worst = math.inf
            continue
        a, b, c = (sum(x * x for x in ss), sum(x * y for x, y in zip(ss, st)), sum(y * y for y in st))
        worst = max(worst, math.sqrt(0.5 * (a + c + math.sqrt((a - c) ** 2 + 4 * b * b))))
    return math.sqrt(area_u_sum / area_sum) * worst
