#include "generated_meshes.h"

#include <cmath>
#include <map>
#include <set>
#include <vector>

namespace testmesh {

namespace {
const double kPi = 3.14159265358979323846;
Mesh from_lists(const std::vector<Eigen::RowVector3d>& v, const std::vector<Eigen::RowVector3i>& f) {
  Mesh m;
  m.V.resize(Eigen::Index(v.size()), 3);
  m.F.resize(Eigen::Index(f.size()), 3);
  for (size_t i = 0; i < v.size(); ++i) m.V.row(Eigen::Index(i)) = v[i];
  for (size_t i = 0; i < f.size(); ++i) m.F.row(Eigen::Index(i)) = f[i];
  return m;
}
}  // namespace

Mesh grid(int n, const std::function<double(double, double)>& height) {
  std::vector<Eigen::RowVector3d> v;
  std::vector<Eigen::RowVector3i> f;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const double x = double(i) / n, y = double(j) / n;
      v.emplace_back(x, y, height ? height(x, y) : 0.0);
    }
  auto id = [n](int i, int j) { return j * (n + 1) + i; };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      if ((i + j) % 2 == 0) {
        f.emplace_back(id(i, j), id(i + 1, j), id(i + 1, j + 1));
        f.emplace_back(id(i, j), id(i + 1, j + 1), id(i, j + 1));
      } else {
        f.emplace_back(id(i, j), id(i + 1, j), id(i, j + 1));
        f.emplace_back(id(i + 1, j), id(i + 1, j + 1), id(i, j + 1));
      }
    }
  return from_lists(v, f);
}

Mesh hemisphere(int rings, int sectors) {
  std::vector<Eigen::RowVector3d> v{{0, 0, 1}};
  std::vector<Eigen::RowVector3i> f;
  for (int r = 1; r <= rings; ++r) {
    const double polar = 0.5 * kPi * r / rings;
    for (int s = 0; s < sectors; ++s) {
      const double a = 2 * kPi * s / sectors;
      v.emplace_back(std::sin(polar) * std::cos(a), std::sin(polar) * std::sin(a), std::cos(polar));
    }
  }
  auto id = [sectors](int r, int s) { return 1 + (r - 1) * sectors + (s % sectors); };
  for (int s = 0; s < sectors; ++s) f.emplace_back(0, id(1, s), id(1, s + 1));
  for (int r = 1; r < rings; ++r)
    for (int s = 0; s < sectors; ++s) {
      f.emplace_back(id(r, s), id(r + 1, s), id(r + 1, s + 1));
      f.emplace_back(id(r, s), id(r + 1, s + 1), id(r, s + 1));
    }
  return from_lists(v, f);
}

Mesh tall_cap(int rings, int sectors) {
  Mesh m = hemisphere(rings, sectors);
  m.V.col(2) *= 2.5;
  m.V.col(0) *= 1.5;
  return m;
}

Mesh octahedron() {
  return from_lists({{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}},
                    {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}});
}

Mesh two_grids(int n) { return joined(grid(n), grid(n), 1, Eigen::RowVector3d(2, 0, 0)); }

Mesh joined(const Mesh& a, const Mesh& b, double scale, const Eigen::RowVector3d& offset) {
  Mesh m;
  m.V.resize(a.V.rows() + b.V.rows(), 3);
  m.F.resize(a.F.rows() + b.F.rows(), 3);
  m.V << a.V, ((b.V * scale).rowwise() + offset);
  m.F << a.F, (b.F.array() + int(a.V.rows())).matrix();
  return m;
}

Mesh with_specks(const Mesh& m, int count, int per_row, double first_x) {
  Mesh out;
  out.V.resize(m.V.rows() + 3 * count, 3);
  out.F.resize(m.F.rows() + count, 3);
  out.V.topRows(m.V.rows()) = m.V;
  out.F.topRows(m.F.rows()) = m.F;
  for (int i = 0; i < count; ++i) {
    const Eigen::RowVector3d at(first_x + i % per_row, i / per_row, 0);
    const Eigen::Index v = m.V.rows() + 3 * i;
    out.V.row(v) = at;
    out.V.row(v + 1) = at + Eigen::RowVector3d(0.01, 0, 0);
    out.V.row(v + 2) = at + Eigen::RowVector3d(0, 0.01, 0);
    out.F.row(m.F.rows() + i) << int(v), int(v + 1), int(v + 2);
  }
  return out;
}

Mesh with_tiny_triangles(const Mesh& m, const std::vector<int>& faces, double scale) {
  Mesh out;
  out.V.resize(m.V.rows() + 3 * Eigen::Index(faces.size()), 3);
  out.F.resize(m.F.rows() + 6 * Eigen::Index(faces.size()), 3);
  out.V.topRows(m.V.rows()) = m.V;
  out.F.topRows(m.F.rows()) = m.F;
  Eigen::Index v = m.V.rows(), f = m.F.rows();
  for (const int face : faces) {
    const int a = m.F(face, 0), b = m.F(face, 1), c = m.F(face, 2);
    const Eigen::RowVector3d centre = (m.V.row(a) + m.V.row(b) + m.V.row(c)) / 3;
    const int p = int(v), q = int(v + 1), r = int(v + 2);
    for (const int corner : {a, b, c}) out.V.row(v++) = centre + scale * (m.V.row(corner) - centre);
    out.F.row(face) << p, q, r;
    out.F.row(f++) << a, b, q;
    out.F.row(f++) << a, q, p;
    out.F.row(f++) << b, c, r;
    out.F.row(f++) << b, r, q;
    out.F.row(f++) << c, a, p;
    out.F.row(f++) << c, p, r;
  }
  return out;
}

Mesh soup(const Mesh& mesh) {
  Mesh m;
  m.V.resize(3 * mesh.F.rows(), 3);
  m.F.resize(mesh.F.rows(), 3);
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      m.V.row(3 * f + k) = mesh.V.row(mesh.F(f, k));
      m.F(f, k) = int(3 * f + k);
    }
  return m;
}

Mesh torus(int rings, int sectors) {
  std::vector<Eigen::RowVector3d> v;
  std::vector<Eigen::RowVector3i> f;
  for (int r = 0; r < rings; ++r)
    for (int s = 0; s < sectors; ++s) {
      const double a = 2 * kPi * r / rings, b = 2 * kPi * s / sectors;
      v.emplace_back((2 + std::cos(b)) * std::cos(a), (2 + std::cos(b)) * std::sin(a), std::sin(b));
    }
  auto id = [&](int r, int s) { return (r % rings) * sectors + (s % sectors); };
  for (int r = 0; r < rings; ++r)
    for (int s = 0; s < sectors; ++s) {
      f.emplace_back(id(r, s), id(r + 1, s), id(r + 1, s + 1));
      f.emplace_back(id(r, s), id(r + 1, s + 1), id(r, s + 1));
    }
  return from_lists(v, f);
}

Mesh jagged_band(int columns) {
  const int nx = columns, ny = 16;
  std::vector<Eigen::RowVector3d> v;
  std::vector<Eigen::RowVector3i> f;
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) {
      const double x = 0.5 * i, y = 0.5 * j;
      v.emplace_back(x, y, 0.4 * std::sin(0.3 * x) + 0.2 * std::cos(0.4 * y));
    }
  auto id = [nx](int i, int j) { return j * (nx + 1) + i; };
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int a = id(i, j), b = id(i + 1, j), c = id(i, j + 1), d = id(i + 1, j + 1);
      const bool even = (i + j) % 2 == 0;
      for (const Eigen::RowVector3i& t : {even ? Eigen::RowVector3i(a, b, d) : Eigen::RowVector3i(a, b, c),
                                          even ? Eigen::RowVector3i(a, d, c) : Eigen::RowVector3i(b, d, c)}) {
        const double cx = (v[size_t(t(0))].x() + v[size_t(t(1))].x() + v[size_t(t(2))].x()) / 3;
        const double cy = (v[size_t(t(0))].y() + v[size_t(t(1))].y() + v[size_t(t(2))].y()) / 3;
        if (std::abs(cy - (2.5 + 0.2 * cx + 0.6 * std::sin(0.5 * cx + 1))) < 0.4) f.push_back(t);
      }
    }
  return from_lists(v, f);
}

Mesh sphere(int rings, int sectors) {
  std::vector<Eigen::RowVector3d> v{{0, 0, 1}, {0, 0, -1}};
  std::vector<Eigen::RowVector3i> f;
  for (int r = 1; r < rings; ++r) {
    const double polar = kPi * r / rings;
    for (int s = 0; s < sectors; ++s) {
      const double a = 2 * kPi * s / sectors;
      v.emplace_back(std::sin(polar) * std::cos(a), std::sin(polar) * std::sin(a), std::cos(polar));
    }
  }
  auto id = [sectors](int r, int s) { return 2 + (r - 1) * sectors + (s % sectors); };
  for (int s = 0; s < sectors; ++s) {
    f.emplace_back(0, id(1, s), id(1, s + 1));
    f.emplace_back(1, id(rings - 1, s + 1), id(rings - 1, s));
  }
  for (int r = 1; r + 1 < rings; ++r)
    for (int s = 0; s < sectors; ++s) {
      f.emplace_back(id(r, s), id(r + 1, s), id(r + 1, s + 1));
      f.emplace_back(id(r, s), id(r + 1, s + 1), id(r, s + 1));
    }
  return from_lists(v, f);
}

Mesh punched_grid(int n, const std::vector<Eigen::RowVector2d>& centres, double radius) {
  const Mesh g = grid(n);
  Mesh m = g;
  Eigen::Index kept = 0;
  for (Eigen::Index f = 0; f < g.F.rows(); ++f) {
    const Eigen::RowVector3d c = (g.V.row(g.F(f, 0)) + g.V.row(g.F(f, 1)) + g.V.row(g.F(f, 2))) / 3;
    bool inside = false;
    for (const Eigen::RowVector2d& centre : centres) inside |= (c.head<2>() - centre).norm() < radius;
    if (!inside) m.F.row(kept++) = g.F.row(f);
  }
  m.F.conservativeResize(kept, 3);
  return m;
}

Mesh double_torus() {
  const Mesh t = torus(16, 8);
  Mesh m;
  const Eigen::Index nv = t.V.rows(), nf = t.F.rows();
  m.V.resize(2 * nv, 3);
  m.V << t.V, (t.V.rowwise() + Eigen::RowVector3d(8, 0, 0));
  m.F.resize(2 * (nf - 1) + 6, 3);
  m.F << t.F.bottomRows(nf - 1), (t.F.bottomRows(nf - 1).array() + int(nv)).matrix(), Eigen::MatrixXi::Zero(6, 3);
  // Each hole's loop runs against its removed face (a, b, c): a -> c -> b.
  const int p[3] = {t.F(0, 0), t.F(0, 2), t.F(0, 1)};
  const int q[3] = {t.F(0, 0) + int(nv), t.F(0, 2) + int(nv), t.F(0, 1) + int(nv)};
  for (int i = 0; i < 3; ++i) {
    const int k = (3 - i) % 3, k_next = (3 - i - 1 + 3) % 3;
    m.F.row(2 * (nf - 1) + 2 * i) << p[(i + 1) % 3], p[i], q[k];
    m.F.row(2 * (nf - 1) + 2 * i + 1) << p[(i + 1) % 3], q[k], q[k_next];
  }
  return m;
}

Mesh without_face(const Mesh& mesh, int face) {
  Mesh m = mesh;
  m.F.resize(mesh.F.rows() - 1, 3);
  for (Eigen::Index f = 0, g = 0; f < mesh.F.rows(); ++f)
    if (f != face) m.F.row(g++) = mesh.F.row(f);
  return m;
}

Mesh cube(int n) {
  // Each side: its origin and two edge directions whose cross product points out of the cube.
  const int sides[6][9] = {{0, 0, 0, 0, 1, 0, 1, 0, 0}, {0, 0, 1, 1, 0, 0, 0, 1, 0}, {0, 0, 0, 1, 0, 0, 0, 0, 1},
                           {0, 1, 0, 0, 0, 1, 1, 0, 0}, {0, 0, 0, 0, 0, 1, 0, 1, 0}, {1, 0, 0, 0, 1, 0, 0, 0, 1}};
  const Mesh g = grid(n);
  std::map<std::vector<long>, int> welded;  // the shared edges' vertices, by their grid position
  std::vector<Eigen::RowVector3d> v;
  std::vector<Eigen::RowVector3i> f;
  for (const auto& side : sides) {
    const Eigen::RowVector3d origin(side[0], side[1], side[2]), u(side[3], side[4], side[5]), w(side[6], side[7], side[8]);
    std::vector<int> index(size_t(g.V.rows()));
    for (Eigen::Index i = 0; i < g.V.rows(); ++i) {
      const Eigen::RowVector3d p = origin + g.V(i, 0) * u + g.V(i, 1) * w;
      const std::vector<long> key = {std::lround(p.x() * n), std::lround(p.y() * n), std::lround(p.z() * n)};
      const auto found = welded.emplace(key, int(v.size()));
      if (found.second) v.push_back(p);
      index[size_t(i)] = found.first->second;
    }
    for (Eigen::Index t = 0; t < g.F.rows(); ++t) f.emplace_back(index[size_t(g.F(t, 0))], index[size_t(g.F(t, 1))], index[size_t(g.F(t, 2))]);
  }
  return from_lists(v, f);
}

Mesh plate_with_hole(int n, double thickness) {
  const Mesh g = grid(n);
  std::vector<Eigen::RowVector3i> top;
  for (Eigen::Index f = 0; f < g.F.rows(); ++f) {
    const Eigen::RowVector3d c = (g.V.row(g.F(f, 0)) + g.V.row(g.F(f, 1)) + g.V.row(g.F(f, 2))) / 3;
    if (std::abs(c.x() - 0.5) > 0.25 || std::abs(c.y() - 0.5) > 0.25) top.push_back(g.F.row(f));
  }
  // Grid vertex i is i on top and i + (n + 1)^2 at the bottom.
  const int below = int(g.V.rows());
  std::vector<Eigen::RowVector3d> v;
  for (Eigen::Index i = 0; i < g.V.rows(); ++i) v.emplace_back(g.V(i, 0), g.V(i, 1), thickness);
  for (Eigen::Index i = 0; i < g.V.rows(); ++i) v.emplace_back(g.V(i, 0), g.V(i, 1), 0.0);
  std::vector<Eigen::RowVector3i> f = top;
  for (const Eigen::RowVector3i& t : top) f.emplace_back(t(0) + below, t(2) + below, t(1) + below);
  std::set<std::pair<int, int>> edges;
  for (const Eigen::RowVector3i& t : top)
    for (int k = 0; k < 3; ++k) edges.emplace(t(k), t((k + 1) % 3));
  for (const std::pair<int, int>& e : edges)
    if (!edges.count({e.second, e.first})) {  // a boundary edge a -> b of the top: the wall hangs below it
      f.emplace_back(e.second, e.first, e.first + below);
      f.emplace_back(e.second, e.first + below, e.second + below);
    }
  return from_lists(v, f);
}

Mesh sphere_with_bump() {
  Mesh m = sphere(24, 32);
  for (Eigen::Index v = 0; v < m.V.rows(); ++v) {
    const double x = m.V(v, 0);
    if (x > 0.5) m.V(v, 0) += 6 * (x - 0.5);  // pull one side out into an arm
  }
  return m;
}

Mesh ball_with_arms() {
  Mesh m = sphere(64, 96);
  for (Eigen::Index v = 0; v < m.V.rows(); ++v)
    for (int axis : {0, 1, 2}) {
      const double x = m.V(v, axis);
      if (x > 0.7) m.V(v, axis) += 30 * (x - 0.7);
      if (x < -0.7) m.V(v, axis) += 20 * (x + 0.7);
    }
  return m;
}

}  // namespace testmesh
