// Boundary loops (core/boundary_loops.h): each loop in order with the faces on its left, and the
// longest one in 3D.
#include <gtest/gtest.h>

#include <vector>

#include "core/boundary_loops.h"
#include "core/half_edges.h"
#include "generated_meshes.h"

using namespace lowstretch;

TEST(BoundaryLoops, GridHasOneLoopInOrderWithItsFacesOnTheLeft) {
  const int n = 4;
  const testmesh::Mesh m = testmesh::grid(n);
  const std::vector<int> twin = opposite_half_edges(m.F);
  const std::vector<std::vector<int>> loops = boundary_loops(m.F, twin, int(m.V.rows()));
  ASSERT_EQ(loops.size(), 1u);
  ASSERT_EQ(loops[0].size(), size_t(4 * n));
  // Each step of the loop is a boundary half-edge of a face (so the face is on its left).
  for (size_t i = 0; i < loops[0].size(); ++i) {
    const int a = loops[0][i], b = loops[0][(i + 1) % loops[0].size()];
    bool found = false;
    for (int h = 0; h < int(twin.size()); ++h) found = found || (twin[size_t(h)] < 0 && half_edge_tail(m.F, h) == a && half_edge_head(m.F, h) == b);
    EXPECT_TRUE(found) << a << " -> " << b;
  }
  EXPECT_EQ(longest_loop(m.V, loops), 0u);
}

// A grid with two holes of different sizes: three loops; the outer one (perimeter 4) is the longest.
TEST(BoundaryLoops, HolesAreLoopsOfTheirOwnAndTheOuterOneIsLongest) {
  const testmesh::Mesh m = testmesh::punched_grid(16, {{0.3, 0.3}, {0.7, 0.7}}, 0.1);
  const std::vector<std::vector<int>> loops = boundary_loops(m.F, opposite_half_edges(m.F), int(m.V.rows()));
  ASSERT_EQ(loops.size(), 3u);
  const size_t outer = longest_loop(m.V, loops);
  EXPECT_EQ(loops[outer].size(), 64u);
  double length = 0;
  for (size_t i = 0; i < loops[outer].size(); ++i)
    length += (m.V.row(loops[outer][i]) - m.V.row(loops[outer][(i + 1) % loops[outer].size()])).norm();
  EXPECT_NEAR(length, 4.0, 1e-12);
  EXPECT_EQ(longest_loop(m.V, {}), 0u);
  EXPECT_TRUE(boundary_loops(testmesh::octahedron().F, opposite_half_edges(testmesh::octahedron().F), 6).empty());
}
