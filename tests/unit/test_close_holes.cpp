// Holes closed virtually (atlas/cut/close_holes.h): every loop but the longest gets faces, and
// the result is a disk.
#include <gtest/gtest.h>

#include <vector>

#include "atlas/cut/close_holes.h"
#include "core/boundary_loops.h"
#include "core/disk_mesh.h"
#include "core/half_edges.h"
#include "generated_meshes.h"

using namespace lowstretch;

TEST(CloseHoles, LeavesOnlyTheLongestLoop) {
  testmesh::Mesh m = testmesh::punched_grid(16, {{0.3, 0.3}, {0.7, 0.7}, {0.3, 0.75}}, 0.1);
  const std::vector<std::vector<int>> loops = boundary_loops(m.F, opposite_half_edges(m.F), int(m.V.rows()));
  ASSERT_EQ(loops.size(), 4u);
  const size_t outer = longest_loop(m.V, loops);
  EXPECT_EQ(loops[outer].size(), 64u);  // the square's border: 4 x 16 edges
  const Eigen::Index faces = m.F.rows();
  close_holes(m.V, m.F, loops, outer);
  EXPECT_EQ(m.F.rows(), faces + Eigen::Index(loops[0].size() + loops[1].size() + loops[2].size() + loops[3].size() -
                                              loops[outer].size()));
  DiskMesh disk;
  const Error e = make_disk_mesh(m.V, m.F, disk);  // the unused vertices of the holes are ignored
  EXPECT_FALSE(e) << message(e);
  EXPECT_EQ(disk.boundary.size(), 64u);
}
