// Square corners avoid collapsing boundary triangles.
#include <gtest/gtest.h>

#include <cmath>

#include "core/boundary_map.h"
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

TEST(SquareCorners, MoreEarsThanCornersBendTheSidesSlightlyInsteadOfCollapsing) {
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
  EXPECT_EQ(c.kinks.size(), size_t(c.collapsed_chords));
  const Result r = parameterize(V, F);
  ASSERT_FALSE(r.error);
  for (const PassMetrics& p : r.passes) {
    EXPECT_EQ(p.flipped, 0);
    EXPECT_EQ(p.degenerate, 0);
  }
  EXPECT_FALSE(r.notes.empty());
  // The square stays a square: the kinked side bulges by at most kKinkBulge of its length, so the map
  // covers nearly all of its bounding square (a side bowed by a quarter covered about 0.8).
  double covered = 0;
  for (Eigen::Index f = 0; f < F.rows(); ++f) {
    const Eigen::RowVector2d a = r.uv.row(F(f, 0)), b = r.uv.row(F(f, 1)), c2 = r.uv.row(F(f, 2));
    covered += 0.5 * std::abs((b - a).x() * (c2 - a).y() - (c2 - a).x() * (b - a).y());
  }
  EXPECT_GT(covered, 0.985);
  EXPECT_LE(covered, 1.0 + 1e-12);
}

TEST(SquareCorners, KinkedSideIsConvexAndBendsAtEveryKink) {
  // A 40-gon boundary on one side of the square with kinks at 10 and 25 (of the first side,
  // positions 0..10 .. 40): the bulge is concave and strictly above every chord over a kink.
  const int n = 40;
  Eigen::MatrixXd V(n + 1, 3);
  for (int i = 0; i < n; ++i) V.row(i) << std::cos(2 * 3.14159265358979 * i / n), std::sin(2 * 3.14159265358979 * i / n), 0;
  V.row(n) << 0, 0, 0;
  Eigen::MatrixXi F(n, 3);
  for (int i = 0; i < n; ++i) F.row(i) << i, (i + 1) % n, n;
  DiskMesh disk;
  ASSERT_FALSE(make_disk_mesh(V, F, disk));
  const std::array<int, 4> corners{0, 10, 20, 30};
  const Eigen::MatrixXd plain = square_boundary(disk, corners);
  const Eigen::MatrixXd kinked = square_boundary(disk, corners, {3, 7});
  // Only the first side (positions 0..10, along y = 0 before fitting) moves off its line.
  const auto cross = [](const Eigen::RowVector2d& a, const Eigen::RowVector2d& b, const Eigen::RowVector2d& c) {
    return (b - a).x() * (c - a).y() - (c - a).x() * (b - a).y();
  };
  for (int i = 1; i < 10; ++i)  // every consecutive triple turns left: the side is convex
    EXPECT_GE(cross(kinked.row(i - 1), kinked.row(i), kinked.row(i + 1)), -1e-15) << i;
  EXPECT_GT(cross(kinked.row(2), kinked.row(3), kinked.row(4)), 1e-6);   // bends at the kinks
  EXPECT_GT(cross(kinked.row(6), kinked.row(7), kinked.row(8)), 1e-6);
  EXPECT_NEAR(cross(kinked.row(4), kinked.row(5), kinked.row(6)), 0.0, 1e-12);  // straight between
  const double bulge = (kinked.col(1).minCoeff() - kinked.row(0).y());
  EXPECT_LT(bulge, 0.0);   // outward is -y for the first side
  EXPECT_GE(bulge, -kKinkBulge / (1 + kKinkBulge) - 1e-12);
  EXPECT_NEAR(cross(plain.row(2), plain.row(3), plain.row(4)), 0.0, 1e-12);  // without kinks: a line
}
