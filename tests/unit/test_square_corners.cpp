// Square corners avoid collapsing boundary triangles.
#include <gtest/gtest.h>

#include <cmath>

#include "core/disk_mesh.h"
#include "core/parameterize.h"
#include "core/square_corners.h"

using namespace lowstretch;

namespace {
// A convex n-gon triangulated as a fan from vertex 0: every triangle has three boundary
// vertices and every fan edge is an interior edge between boundary vertices.
void fan_polygon(int n, Eigen::MatrixXd& V, Eigen::MatrixXi& F) {
  V.resize(n, 3);
  for (int i = 0; i < n; ++i) V.row(i) << std::cos(2 * 3.14159265358979 * i / n), std::sin(2 * 3.14159265358979 * i / n), 0.1 * (i % 2);
  F.resize(n - 2, 3);
  for (int i = 0; i < n - 2; ++i) F.row(i) << 0, i + 1, i + 2;
}
}  // namespace

TEST(SquareCorners, QuarterChoiceWhenNothingCollapses) {
  Eigen::MatrixXd V(5, 3);
  V << 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0.5, 0.5, 0.2;
  Eigen::MatrixXi F(4, 3);
  F << 0, 1, 4, 1, 2, 4, 2, 3, 4, 3, 0, 4;
  DiskMesh disk;
  ASSERT_FALSE(make_disk_mesh(V, F, disk));
  const SquareCorners c = choose_square_corners(disk);
  EXPECT_FALSE(c.moved);
  EXPECT_EQ(c.collapsed_chords, 0);
  EXPECT_EQ(c.corners, (std::array<int, 4>{0, 1, 2, 3}));
}

TEST(SquareCorners, FanPolygonGetsCornersAtItsEarTips) {
  Eigen::MatrixXd V;
  Eigen::MatrixXi F;
  fan_polygon(12, V, F);
  DiskMesh disk;
  ASSERT_FALSE(make_disk_mesh(V, F, disk));
  const SquareCorners c = choose_square_corners(disk);
  EXPECT_TRUE(c.moved);
  EXPECT_EQ(c.collapsed_chords, 0);
  // The two ears (0,1,2) and (0,10,11) need corners at their tips 1 and 11.
  const std::vector<int> loop = disk.boundary;
  std::vector<int> corner_vertices;
  for (int p : c.corners) corner_vertices.push_back(loop[size_t(p)]);
  EXPECT_NE(std::find(corner_vertices.begin(), corner_vertices.end(), 1), corner_vertices.end());
  EXPECT_NE(std::find(corner_vertices.begin(), corner_vertices.end(), 11), corner_vertices.end());

  const Result r = parameterize(V, F);
  ASSERT_FALSE(r.error);
  for (const PassMetrics& p : r.passes) {
    EXPECT_EQ(p.flipped, 0);
    EXPECT_EQ(p.degenerate, 0);
  }
}

TEST(SquareCorners, MoreEarsThanCornersBowTheSidesInsteadOfCollapsing) {
  // A 15-gon with five ears (3i, 3i+1, 3i+2): five tips cannot all be corners of a square.
  const int n = 15;
  Eigen::MatrixXd V(n, 3);
  for (int i = 0; i < n; ++i) V.row(i) << std::cos(2 * 3.14159265358979 * i / n), std::sin(2 * 3.14159265358979 * i / n), 0;
  Eigen::MatrixXi F(n - 2, 3);
  for (int i = 0; i < 5; ++i) {
    F.row(i) << 3 * i, 3 * i + 1, 3 * i + 2;
    F.row(5 + i) << 3 * i, 3 * i + 2, (3 * i + 3) % n;
  }
  F.row(10) << 0, 3, 6;
  F.row(11) << 0, 6, 9;
  F.row(12) << 0, 9, 12;
  DiskMesh disk;
  ASSERT_FALSE(make_disk_mesh(V, F, disk));
  const SquareCorners c = choose_square_corners(disk);
  EXPECT_GT(c.collapsed_chords, 0);
  const Result r = parameterize(V, F);
  ASSERT_FALSE(r.error);
  for (const PassMetrics& p : r.passes) {
    EXPECT_EQ(p.flipped, 0);
    EXPECT_EQ(p.degenerate, 0);
  }
  EXPECT_FALSE(r.notes.empty());
}
