// The cheapest seam between fixed faces (atlas/cut/cheapest_seam.h) and the straight cut it gives
// split_chart: known lengths on grids, fixed faces kept on their side, the shortest path
// (atlas/cut/seam_path.h) as cheap as the max flow, and the max flow where there is no path.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

#include "atlas/cut/cheapest_seam.h"
#include "atlas/cut/seam_path.h"
#include "atlas/cut/split_chart.h"
#include "core/half_edges.h"
#include "generated_meshes.h"

using namespace lowstretch;

namespace {

// Every face's neighbours and the edges' 3D lengths, edge k from corner k to corner k + 1.
struct Adjacency {
  std::vector<std::array<int, 3>> corners, neighbour;
  std::vector<std::array<double, 3>> length;
};

Adjacency adjacency(const testmesh::Mesh& m) {
  const std::vector<int> twin = opposite_half_edges(m.F);
  Adjacency a;
  for (int f = 0; f < int(m.F.rows()); ++f) {
    std::array<int, 3> n{};
    std::array<double, 3> l{};
    for (int k = 0; k < 3; ++k) {
      const int t = twin[size_t(3 * f + k)];
      n[size_t(k)] = t >= 0 ? t / 3 : -1;
      l[size_t(k)] = (m.V.row(m.F(f, (k + 1) % 3)) - m.V.row(m.F(f, k))).norm();
    }
    a.corners.push_back({m.F(f, 0), m.F(f, 1), m.F(f, 2)});
    a.neighbour.push_back(n);
    a.length.push_back(l);
  }
  return a;
}

// The 3D length of the edges between faces of different sides (counted once each).
double seam_length(const Adjacency& a, const std::vector<char>& side) {
  double seam = 0;
  for (size_t f = 0; f < a.neighbour.size(); ++f)
    for (size_t k = 0; k < 3; ++k) {
      const int g = a.neighbour[f][k];
      if (g > int(f) && side[f] != side[size_t(g)]) seam += a.length[f][k];
    }
  return seam;
}

double centroid_x(const testmesh::Mesh& m, int f) { return (m.V(m.F(f, 0), 0) + m.V(m.F(f, 1), 0) + m.V(m.F(f, 2), 0)) / 3; }

}  // namespace

// On the unit square, faces left of x = 0.3 fixed on one side and right of x = 0.7 on the other:
// the cheapest seam between them is a straight line across, of length 1 (no cut is shorter than
// the square is wide), and no fixed face changes side.
TEST(CheapestSeam, StraightAcrossABand) {
  const testmesh::Mesh m = testmesh::grid(20);
  const Adjacency a = adjacency(m);
  std::vector<signed char> fixed(size_t(m.F.rows()));
  for (int f = 0; f < int(m.F.rows()); ++f) fixed[size_t(f)] = centroid_x(m, f) < 0.3 ? 1 : centroid_x(m, f) > 0.7 ? 0 : -1;
  const std::vector<char> side = cheapest_seam(a.corners, a.neighbour, a.length, fixed);
  EXPECT_NEAR(seam_length(a, side), 1.0, 1e-9);
  for (size_t f = 0; f < fixed.size(); ++f)
    if (fixed[f] >= 0) EXPECT_EQ(side[f], fixed[f]) << "face " << f;
}

// With faces fixed on one side only, every free face joins them: no seam at all.
TEST(CheapestSeam, OneSideFixedTakesEveryFace) {
  const testmesh::Mesh m = testmesh::grid(6);
  const Adjacency a = adjacency(m);
  for (const signed char fixed_side : {0, 1}) {
    std::vector<signed char> fixed(size_t(m.F.rows()), -1);
    fixed[5] = fixed_side;
    const std::vector<char> side = cheapest_seam(a.corners, a.neighbour, a.length, fixed);
    for (const char s : side) EXPECT_EQ(s, fixed_side);
  }
}

// A strip four times as long as it is wide is cut straight across: seam 1. Cut at the level set of
// distances over faces alone (seam_band 0) the seam zigzags along the triangles, and is no shorter.
TEST(CheapestSeam, SplitChartCutsAStripStraightAcross) {
  testmesh::Mesh m = testmesh::grid(24);
  m.V.col(0) *= 4;
  const Adjacency a = adjacency(m);
  const std::vector<int> twin = opposite_half_edges(m.F);
  std::vector<int> faces(size_t(m.F.rows()));
  for (int f = 0; f < int(m.F.rows()); ++f) faces[size_t(f)] = f;
  double seam[2] = {0, 0};
  for (const int band : {0, 1}) {
    SplitOptions options;
    if (band == 0) options.seam_band = 0;
    const std::vector<std::vector<int>> parts = split_chart(m.V, m.F, twin, faces, options);
    ASSERT_EQ(parts.size(), 2u);
    std::vector<char> side(faces.size(), 0);
    for (const int f : parts[0]) side[size_t(f)] = 1;
    seam[band] = seam_length(a, side);
  }
  EXPECT_NEAR(seam[1], 1.0, 1e-9);
  EXPECT_GE(seam[0], seam[1] - 1e-9);
}

namespace {

// Faces fixed by a level of a x + b y: below lo on side 1, above hi on side 0.
std::vector<signed char> fixed_by_level(const testmesh::Mesh& m, double a, double b, double lo, double hi) {
  std::vector<signed char> fixed(size_t(m.F.rows()));
  for (int f = 0; f < int(m.F.rows()); ++f) {
    double level = 0;
    for (int k = 0; k < 3; ++k) level += (a * m.V(m.F(f, k), 0) + b * m.V(m.F(f, k), 1)) / 3;
    fixed[size_t(f)] = level < lo ? 1 : level > hi ? 0 : -1;
  }
  return fixed;
}

void expect_fixed_kept(const std::vector<signed char>& fixed, const std::vector<char>& side) {
  for (size_t f = 0; f < fixed.size(); ++f)
    if (fixed[f] >= 0) EXPECT_EQ(side[f], fixed[f]) << "face " << f;
}

}  // namespace

// On a bumpy grid (seam costs vary), and on it with two holes in the band, bands across it at
// several slopes and widths: the shortest path between the border arcs is found (through a hole
// where that is cheaper), and its seam costs what Boykov-Kolmogorov's minimum cut costs, every
// fixed face on its side.
TEST(CheapestSeam, ShortestPathCostsWhatTheMaxFlowDoes) {
  const auto bumps = [](double x, double y) { return 0.15 * std::sin(9 * x) * std::cos(7 * y + 3 * x); };
  testmesh::Mesh holed = testmesh::punched_grid(30, {Eigen::RowVector2d(0.5, 0.35), Eigen::RowVector2d(0.45, 0.75)}, 0.12);
  for (int v = 0; v < int(holed.V.rows()); ++v) holed.V(v, 2) = bumps(holed.V(v, 0), holed.V(v, 1));
  const double bands[][4] = {{1, 0, 0.3, 0.7}, {1, 0.5, 0.2, 0.9}, {1, -1, -0.4, 0.3}, {0.3, 1, 0.45, 0.55}, {1, 1, 0.2, 1.7}};
  for (const testmesh::Mesh& m : {testmesh::grid(30, bumps), holed}) {
    const Adjacency a = adjacency(m);
    for (const auto& b : bands) {
      const std::vector<signed char> fixed = fixed_by_level(m, b[0], b[1], b[2], b[3]);
      std::vector<char> by_path;
      ASSERT_TRUE(cheapest_seam_as_path(a.corners, a.neighbour, a.length, fixed, by_path)) << "band " << b[0] << " " << b[1];
      const std::vector<char> by_flow = cheapest_seam_by_max_flow(a.neighbour, a.length, fixed);
      EXPECT_NEAR(seam_length(a, by_path), seam_length(a, by_flow), 1e-9 * seam_length(a, by_flow));
      EXPECT_GT(seam_length(a, by_path), 0.2);  // the corner band x + y < 0.2 cuts off least
      expect_fixed_kept(fixed, by_path);
    }
  }
}

// No path where the chart is not of genus 0 (a torus with a face taken out, a closed sphere) or
// the faces fixed on one side do not meet the border (an island in the middle): `side` is left
// alone, and cheapest_seam takes the max flow's seam there, which closes around the island (a
// ring of six edges at least).
TEST(CheapestSeam, NoPathAroundAHoleOrAnIslandTheMaxFlowCuts) {
  const testmesh::Mesh handle = testmesh::without_face(testmesh::torus(10, 16), 0);
  const testmesh::Mesh plain = testmesh::grid(20);
  const testmesh::Mesh sphere = testmesh::sphere(12, 16);
  const Adjacency torus = adjacency(handle), whole = adjacency(plain), closed = adjacency(sphere);
  std::vector<signed char> poles(size_t(sphere.F.rows()), -1);
  for (int f = 0; f < int(sphere.F.rows()); ++f) {
    const double z = (sphere.V(sphere.F(f, 0), 2) + sphere.V(sphere.F(f, 1), 2) + sphere.V(sphere.F(f, 2), 2)) / 3;
    poles[size_t(f)] = z > 0.5 ? 1 : z < -0.5 ? 0 : -1;
  }
  std::vector<signed char> island(size_t(plain.F.rows()), -1);
  for (int f = 0; f < int(plain.F.rows()); ++f) {
    const Eigen::RowVector3d c = (plain.V.row(plain.F(f, 0)) + plain.V.row(plain.F(f, 1)) + plain.V.row(plain.F(f, 2))) / 3;
    if ((c.head<2>() - Eigen::RowVector2d(0.5, 0.5)).norm() < 0.1) island[size_t(f)] = 1;
    if (c.x() > 0.9) island[size_t(f)] = 0;
  }
  const struct {
    const Adjacency& a;
    std::vector<signed char> fixed;
  } cases[] = {{torus, fixed_by_level(handle, 1, 0, -1, 1)}, {whole, island}, {closed, poles}};
  for (const auto& c : cases) {
    std::vector<char> side(3, 7);
    EXPECT_FALSE(cheapest_seam_as_path(c.a.corners, c.a.neighbour, c.a.length, c.fixed, side));
    EXPECT_EQ(side, std::vector<char>(3, 7));
    const std::vector<char> chosen = cheapest_seam(c.a.corners, c.a.neighbour, c.a.length, c.fixed);
    EXPECT_EQ(chosen, cheapest_seam_by_max_flow(c.a.neighbour, c.a.length, c.fixed));
    expect_fixed_kept(c.fixed, chosen);
  }
  EXPECT_GT(seam_length(whole, cheapest_seam(whole.corners, whole.neighbour, whole.length, island)), 6 * 0.05 - 1e-9);
}
