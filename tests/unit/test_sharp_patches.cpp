// Patches between sharp edges (atlas/cut/sharp_patches.h): the faces of a model made of faces.
#include <gtest/gtest.h>

#include <vector>

#include "atlas/cut/sharp_patches.h"
#include "generated_meshes.h"

using namespace lowstretch;

TEST(SharpPatches, CubeFallsIntoItsSixSides) {
  const int n = 4, side_faces = 2 * n * n;
  const testmesh::Mesh m = testmesh::cube(n);
  const std::vector<std::vector<int>> patches = patches_between_sharp_edges(m.V, m.F, 80);
  ASSERT_EQ(patches.size(), 6u);
  for (size_t s = 0; s < 6; ++s) {
    std::vector<int> side(static_cast<size_t>(side_faces));
    for (int k = 0; k < side_faces; ++k) side[size_t(k)] = int(s) * side_faces + k;
    EXPECT_EQ(patches[s], side) << "side " << s;
  }
}

TEST(SharpPatches, EdgesLessSharpThanTheAngleJoin) {
  // The cube's edges turn the normal by 90 degrees: below 95 they are not sharp.
  EXPECT_EQ(patches_between_sharp_edges(testmesh::cube(4).V, testmesh::cube(4).F, 95).size(), 1u);
  // A sphere of 16 x 24 turns the normal by at most 15 degrees from face to face.
  const testmesh::Mesh ball = testmesh::sphere(16, 24);
  EXPECT_EQ(patches_between_sharp_edges(ball.V, ball.F, 30).size(), 1u);
  EXPECT_GT(patches_between_sharp_edges(ball.V, ball.F, 5).size(), 100u);
}
