// Fixed boundary positions (core/boundary_map.h): the boundary loop on the circle or the square,
// counter-clockwise, spaced by 3D arc length, corners where they are asked for.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

#include "atlas/charts.h"
#include "core/boundary_map.h"
#include "core/disk_mesh.h"
#include "generated_meshes.h"

using namespace lowstretch;

namespace {

// grid(n) with its columns uneven (x -> x^2 spread): boundary edges of many lengths.
testmesh::Mesh uneven_grid(int n) {
  testmesh::Mesh m = testmesh::grid(n);
  m.V.col(0) = (0.3 * m.V.col(0).array() + 0.7 * m.V.col(0).array().square()).matrix();
  return m;
}

DiskMesh disk_of(const testmesh::Mesh& m) {
  DiskMesh disk;
  EXPECT_FALSE(make_disk_mesh(m.V, m.F, disk));
  return disk;
}

// The 3D length of loop edge i (from boundary[i] to boundary[i + 1], wrapping).
double loop_edge(const DiskMesh& disk, size_t i) {
  const size_t n = disk.boundary.size();
  return (disk.V.row(disk.boundary[i]) - disk.V.row(disk.boundary[(i + 1) % n])).norm();
}

}  // namespace

TEST(BoundaryMap, ArcLengthsAreTheLoopsEdgeLengthsSummed) {
  const DiskMesh disk = disk_of(uneven_grid(6));
  const std::vector<double> arc = boundary_arc_lengths(disk);
  ASSERT_EQ(arc.size(), disk.boundary.size() + 1);
  EXPECT_EQ(arc[0], 0.0);
  for (size_t i = 0; i < disk.boundary.size(); ++i) EXPECT_NEAR(arc[i + 1] - arc[i], loop_edge(disk, i), 1e-12) << i;
  EXPECT_NEAR(arc.back(), 4.0, 1e-12);  // the unit square's perimeter, however its columns are spread
}

TEST(BoundaryMap, ZeroLengthEdgeGetsAPositiveArcLength) {
  testmesh::Mesh m = testmesh::grid(6);
  m.V.row(6 * 7 + 3) = m.V.row(6 * 7 + 4);  // two neighbours on the top side at one point
  const DiskMesh disk = disk_of(m);
  const std::vector<double> arc = boundary_arc_lengths(disk);
  for (size_t i = 0; i + 1 < arc.size(); ++i) EXPECT_GT(arc[i + 1], arc[i]) << i;
  EXPECT_NEAR(arc.back(), 4.0, 1e-3);
}

// On the circle inscribed in [0,1]^2, counter-clockwise, the angle between two points that of
// their arc's share of the perimeter.
TEST(BoundaryMap, CirclePointsAreOnTheCircleInOrderSpacedByArcLength) {
  const DiskMesh disk = disk_of(uneven_grid(6));
  const Eigen::MatrixXd uv = circle_boundary(disk);
  ASSERT_EQ(uv.rows(), Eigen::Index(disk.boundary.size()));
  const size_t n = disk.boundary.size();
  double perimeter = 0;
  for (size_t i = 0; i < n; ++i) perimeter += loop_edge(disk, i);
  for (size_t i = 0; i < n; ++i) {
    const Eigen::Vector2d p = uv.row(Eigen::Index(i)).transpose() - Eigen::Vector2d(0.5, 0.5);
    const Eigen::Vector2d q = uv.row(Eigen::Index((i + 1) % n)).transpose() - Eigen::Vector2d(0.5, 0.5);
    EXPECT_NEAR(p.norm(), 0.5, 1e-12) << i;
    const double turn = std::atan2(p.x() * q.y() - p.y() * q.x(), p.dot(q));  // counter-clockwise is positive
    EXPECT_NEAR(turn, 2 * M_PI * loop_edge(disk, i) / perimeter, 1e-9) << i;
  }
}

// A grid's own corners as the square's: every point lands on the grid's own boundary (x, y),
// turned so that the first corner is (0,0): each side's points spaced by arc length along it.
TEST(BoundaryMap, SquareWithTheGridsCornersIsTheGridsOwnBoundary) {
  const testmesh::Mesh m = uneven_grid(6);
  const DiskMesh disk = disk_of(m);
  std::array<int, 4> corners{};
  int found = 0;
  for (size_t i = 0; i < disk.boundary.size(); ++i) {
    const Eigen::RowVector3d p = m.V.row(disk.input_vertex[size_t(disk.boundary[i])]);  // disk.V is in the unit box
    if ((p.x() == 0 || p.x() == 1) && (p.y() == 0 || p.y() == 1)) corners[size_t(found++)] = int(i);
  }
  ASSERT_EQ(found, 4);
  const Eigen::MatrixXd uv = square_boundary(disk, corners);
  ASSERT_EQ(uv.rows(), Eigen::Index(disk.boundary.size()));
  // The quarter turn about the centre that takes the first corner's (x, y) to (0, 0).
  const Eigen::Vector2d first = m.V.row(disk.input_vertex[size_t(disk.boundary[size_t(corners[0])])]).head<2>().transpose();
  Eigen::Matrix2d turn = Eigen::Matrix2d::Identity();
  const Eigen::Matrix2d quarter = (Eigen::Matrix2d() << 0, -1, 1, 0).finished();
  for (int k = 0; k < 4 && ((turn * (first - Eigen::Vector2d(0.5, 0.5))).array() + 0.5).abs().maxCoeff() > 1e-12; ++k)
    turn = quarter * turn;
  for (size_t i = 0; i < disk.boundary.size(); ++i) {
    const Eigen::Vector2d own = m.V.row(disk.input_vertex[size_t(disk.boundary[i])]).head<2>().transpose();
    const Eigen::Vector2d expected = (turn * (own - Eigen::Vector2d(0.5, 0.5))).array() + 0.5;
    EXPECT_LT((uv.row(Eigen::Index(i)).transpose() - expected).norm(), 1e-12) << i;
  }
  for (int k = 0; k < 4; ++k) {
    const Eigen::Vector2d c = uv.row(corners[size_t(k)]).transpose();
    const Eigen::Vector2d want[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    EXPECT_LT((c - want[k]).norm(), 1e-12) << "corner " << k;
  }
}

// With aspect 2 the square is a rectangle twice as wide as high, fitted into [0,1]^2; with aspect
// 0, one with sides as long as the arcs between the corners (a grid three times as wide as high).
TEST(BoundaryMap, RectangleOfTheAspectAskedForOrOfTheArcs) {
  testmesh::Mesh m = testmesh::grid(6);
  m.V.col(0) *= 3;
  const DiskMesh disk = disk_of(m);
  std::array<int, 4> corners{};
  int found = 0;
  for (size_t i = 0; i < disk.boundary.size(); ++i) {
    const Eigen::RowVector3d p = m.V.row(disk.input_vertex[size_t(disk.boundary[i])]);  // disk.V is in the unit box
    if ((p.x() == 0 || p.x() == 3) && (p.y() == 0 || p.y() == 1)) corners[size_t(found++)] = int(i);
  }
  ASSERT_EQ(found, 4);
  for (const double aspect : {2.0, 0.0}) {
    const Eigen::MatrixXd uv = square_boundary(disk, corners, {}, aspect);
    const Eigen::Vector2d size = uv.colwise().maxCoeff() - uv.colwise().minCoeff();
    EXPECT_NEAR(std::max(size.x(), size.y()), 1.0, 1e-12) << aspect;
    EXPECT_GE(uv.minCoeff(), -1e-12);
    EXPECT_LE(uv.maxCoeff(), 1 + 1e-12);
    const double want = aspect == 2 ? 2 : 3;  // the first corner's side along u is a long side of the grid, or not
    const double got = size.x() / size.y();
    EXPECT_TRUE(std::abs(got - want) < 1e-9 || (aspect == 0 && std::abs(got - 1 / want) < 1e-9)) << aspect << ": " << got;
  }
}

// Scans carry zero-length edges. On the boundary, the two ends of one must stay apart in the
// texture as MeshLab stores it (float), or the triangle on it collapses: at an arc-length floor of
// 1e-6 of a mean boundary edge they were 1e-8 apart on this grid's top side, under a float's step
// there; an armadillo with 300 collapsed edges lost 6 triangles in its atlas that way.
TEST(BoundaryMap, ZeroLengthBoundaryEdgeKeepsItsTriangleInFloat) {
  testmesh::Mesh m = testmesh::grid(100, [](double x, double y) { return 0.3 * std::sin(2 * x + y); });
  const int top_middle = 100 * 101 + 50;
  m.V.row(top_middle) = m.V.row(top_middle + 1);
  for (BoundaryShape shape : {BoundaryShape::Square, BoundaryShape::Circle}) {
    ChartOptions options;
    options.disk.boundary = shape;
    const ChartsResult r = parameterize_charts(m.V, m.F, options);
    ASSERT_FALSE(r.error) << message(r.error);
    EXPECT_TRUE(r.input_is_disk);
    EXPECT_EQ(r.layout.flipped, 0) << to_string(shape);
    EXPECT_EQ(r.layout.degenerate, 0) << to_string(shape);  // measured on the UV rounded to float
  }
}
