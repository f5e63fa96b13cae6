// The cheapest seam between fixed faces (atlas/cut/cheapest_seam.h) and the straight cut it gives
// split_chart: known lengths on grids, fixed faces kept on their side.
#include <gtest/gtest.h>

#include <array>
#include <vector>

#include "atlas/cut/cheapest_seam.h"
#include "atlas/cut/split_chart.h"
#include "core/half_edges.h"
#include "generated_meshes.h"

using namespace lowstretch;

namespace {

// Every face's neighbours and the edges' 3D lengths, edge k from corner k to corner k + 1.
struct Adjacency {
  std::vector<std::array<int, 3>> neighbour;
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
  const std::vector<char> side = cheapest_seam(a.neighbour, a.length, fixed);
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
    const std::vector<char> side = cheapest_seam(a.neighbour, a.length, fixed);
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
