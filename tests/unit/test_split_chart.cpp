// Where a chart is cut (atlas/cut/split_chart.h): two edge-connected parts that hold every face
// exactly once, the cut across a neck rather than through the body.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <queue>
#include <set>
#include <vector>

#include "atlas/cut/split_chart.h"
#include "core/half_edges.h"
#include "generated_meshes.h"

using namespace lowstretch;

namespace {

double face_area(const testmesh::Mesh& m, int f) {
  const Eigen::Vector3d a = m.V.row(m.F(f, 0)), b = m.V.row(m.F(f, 1)), c = m.V.row(m.F(f, 2));
  return 0.5 * (b - a).cross(c - a).norm();
}

// Whether `part` is edge-connected, walking across edges of m to faces of the part.
bool edge_connected(const testmesh::Mesh& m, const std::vector<int>& twin, const std::vector<int>& part) {
  const std::set<int> in(part.begin(), part.end());
  std::set<int> seen = {part[0]};
  std::queue<int> todo;
  todo.push(part[0]);
  while (!todo.empty()) {
    const int f = todo.front();
    todo.pop();
    for (int k = 0; k < 3; ++k) {
      const int t = twin[size_t(3 * f + k)];
      if (t >= 0 && in.count(t / 3) && seen.insert(t / 3).second) todo.push(t / 3);
    }
  }
  return seen.size() == in.size();
}

// Every face of `faces` in exactly one part, and no other face; each part edge-connected.
void expect_a_partition(const testmesh::Mesh& m, const std::vector<int>& twin, const std::vector<int>& faces,
                        const std::vector<std::vector<int>>& parts) {
  std::vector<int> all;
  for (const auto& part : parts) {
    ASSERT_FALSE(part.empty());
    EXPECT_TRUE(edge_connected(m, twin, part));
    all.insert(all.end(), part.begin(), part.end());
  }
  std::vector<int> want = faces;
  std::sort(all.begin(), all.end());
  std::sort(want.begin(), want.end());
  EXPECT_EQ(all, want);
}

// Two unit squares joined by a neck 0.2 wide and 1 long (a grid over [0,3] x [0,1]).
testmesh::Mesh dumbbell(std::vector<int>& faces) {
  testmesh::Mesh m = testmesh::grid(30);
  m.V.col(0) *= 3;
  faces.clear();
  for (int f = 0; f < int(m.F.rows()); ++f) {
    const Eigen::RowVector3d c = (m.V.row(m.F(f, 0)) + m.V.row(m.F(f, 1)) + m.V.row(m.F(f, 2))) / 3;
    if (c.x() < 1 || c.x() > 2 || std::abs(c.y() - 0.5) < 0.1) faces.push_back(f);
  }
  return m;
}

}  // namespace

// The dumbbell is cut across its neck: two parts of about one square each (the neck's area, 0.2,
// goes to one side or is shared), the seam between them no longer than the neck is wide (plus a
// grid step or two along the diagonals).
TEST(SplitChart, DumbbellIsCutAcrossItsNeck) {
  std::vector<int> faces;
  const testmesh::Mesh m = dumbbell(faces);
  const std::vector<int> twin = opposite_half_edges(m.F);
  const std::vector<std::vector<int>> parts = split_chart(m.V, m.F, twin, faces);
  ASSERT_EQ(parts.size(), 2u);
  expect_a_partition(m, twin, faces, parts);
  double total = 0, area[2] = {0, 0};
  for (int p = 0; p < 2; ++p)
    for (const int f : parts[size_t(p)]) area[p] += face_area(m, f);
  total = area[0] + area[1];
  EXPECT_NEAR(total, 2.2, 0.01);
  for (int p = 0; p < 2; ++p) EXPECT_GT(area[p], 0.95) << "part " << p;
  std::vector<int> part_of(size_t(m.F.rows()), -1);
  for (int p = 0; p < 2; ++p)
    for (const int f : parts[size_t(p)]) part_of[size_t(f)] = p;
  double seam = 0;
  for (size_t h = 0; h < twin.size(); ++h)
    if (twin[h] > int(h) && part_of[h / 3] >= 0 && part_of[size_t(twin[h]) / 3] >= 0 && part_of[h / 3] != part_of[size_t(twin[h]) / 3])
      seam += (m.V.row(half_edge_tail(m.F, int(h))) - m.V.row(half_edge_head(m.F, int(h)))).norm();
  EXPECT_GT(seam, 0.19);
  EXPECT_LT(seam, 0.45);
  // The parts come in the order of their first face in `faces`.
  EXPECT_NE(std::find(parts[0].begin(), parts[0].end(), faces[0]), parts[0].end());
  std::vector<int> reversed(faces.rbegin(), faces.rend());
  const std::vector<std::vector<int>> back = split_chart(m.V, m.F, twin, reversed);
  ASSERT_FALSE(back.empty());
  EXPECT_NE(std::find(back[0].begin(), back[0].end(), reversed[0]), back[0].end());
}

// A chart that is only some faces of the mesh (the second of two grids): its parts hold exactly
// those faces.
TEST(SplitChart, PartsHoldOnlyTheChartsFaces) {
  const testmesh::Mesh m = testmesh::two_grids(8);
  const std::vector<int> twin = opposite_half_edges(m.F);
  std::vector<int> faces;
  for (int f = int(m.F.rows()) / 2; f < int(m.F.rows()); ++f) faces.push_back(f);
  const std::vector<std::vector<int>> parts = split_chart(m.V, m.F, twin, faces);
  EXPECT_EQ(parts.size(), 2u);
  expect_a_partition(m, twin, faces, parts);
  // Neither side under the smallest part's share (5%) of the area: equal faces here, so of the faces.
  for (const auto& part : parts) EXPECT_GE(double(part.size()), 0.05 * double(faces.size()));
}

// One face cannot be cut: the chart itself comes back.
TEST(SplitChart, SingleFaceStaysWhole) {
  const testmesh::Mesh m = testmesh::grid(2);
  const std::vector<int> twin = opposite_half_edges(m.F);
  const std::vector<std::vector<int>> parts = split_chart(m.V, m.F, twin, {3});
  ASSERT_EQ(parts.size(), 1u);
  EXPECT_EQ(parts[0], std::vector<int>{3});
}
