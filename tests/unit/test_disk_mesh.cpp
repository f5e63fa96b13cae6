// Every way a mesh can fail to be a disk gets its own error code and count.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "atlas/charts.h"
#include "core/disk_mesh.h"
#include "core/parameterize.h"
#include "generated_meshes.h"

using namespace lowstretch;

namespace {
Error check(const testmesh::Mesh& m) {
  DiskMesh disk;
  return make_disk_mesh(m.V, m.F, disk);
}
}  // namespace

TEST(DiskMesh, GridIsADiskWithItsBoundaryLoopCounterClockwise) {
  const testmesh::Mesh m = testmesh::grid(4);
  DiskMesh disk;
  ASSERT_FALSE(make_disk_mesh(m.V, m.F, disk));
  EXPECT_EQ(disk.boundary.size(), 16u);
  EXPECT_EQ(disk.edges.rows(), 4 * 5 * 2 + 16);  // 40 axis edges + 16 diagonals
  double signed_area = 0;  // shoelace over the loop: positive = counter-clockwise
  for (size_t k = 0; k < disk.boundary.size(); ++k) {
    const auto a = disk.V.row(disk.boundary[k]), b = disk.V.row(disk.boundary[(k + 1) % disk.boundary.size()]);
    signed_area += a.x() * b.y() - b.x() * a.y();
  }
  EXPECT_NEAR(signed_area / 2, 1.0, 1e-12);
  // Interior ring of the input's vertex (1,1) (row 6): closed, counter-clockwise around it.
  const int v = int(std::find(disk.input_vertex.begin(), disk.input_vertex.end(), 6) - disk.input_vertex.begin());
  const int degree = disk.ring_start[v + 1] - disk.ring_start[v];
  double winding = 0;
  for (int s = 0; s < degree; ++s) {
    const Eigen::RowVector3d a = disk.V.row(disk.ring[disk.ring_start[v] + s]) - disk.V.row(v);
    const Eigen::RowVector3d b = disk.V.row(disk.ring[disk.ring_start[v] + (s + 1) % degree]) - disk.V.row(v);
    winding += std::atan2(a.x() * b.y() - a.y() * b.x(), a.x() * b.x() + a.y() * b.y());
  }
  EXPECT_NEAR(winding, 2 * 3.14159265358979, 1e-9);
}

TEST(DiskMesh, NoFaces) {
  testmesh::Mesh m;
  m.V = Eigen::MatrixXd::Zero(5, 3);
  m.F.resize(0, 3);
  const Error e = check(m);
  EXPECT_EQ(e.code, ErrorCode::NoFaces);
  EXPECT_EQ(e.count, 5);
}

TEST(DiskMesh, IndexOutOfRange) {
  testmesh::Mesh m = testmesh::grid(2);
  m.F(0, 1) = 99;
  m.F(1, 2) = -1;
  const Error e = check(m);
  EXPECT_EQ(e.code, ErrorCode::IndexOutOfRange);
  EXPECT_EQ(e.count, 2);
}

TEST(DiskMesh, RepeatedVertexInFace) {
  testmesh::Mesh m = testmesh::grid(2);
  m.F(3, 1) = m.F(3, 0);
  EXPECT_EQ(check(m).code, ErrorCode::RepeatedVertexInFace);
}

TEST(DiskMesh, NonFiniteCoordinatesOfAUsedVertex) {
  testmesh::Mesh m = testmesh::grid(2);
  m.V(4, 2) = std::numeric_limits<double>::quiet_NaN();
  m.V(5, 0) = std::numeric_limits<double>::infinity();
  const Error e = check(m);
  EXPECT_EQ(e.code, ErrorCode::NonFiniteCoordinates);
  EXPECT_EQ(e.count, 2);
}

TEST(DiskMesh, UnreferencedVerticesAreIgnoredEvenWhenNaN) {
  testmesh::Mesh m = testmesh::grid(3);
  m.V.conservativeResize(m.V.rows() + 2, 3);
  m.V.bottomRows(2).setConstant(std::numeric_limits<double>::quiet_NaN());
  EXPECT_FALSE(check(m));
}

TEST(DiskMesh, NonManifoldEdge) {
  testmesh::Mesh m = testmesh::grid(2);  // a third face on the interior diagonal (0, 4)
  m.V.conservativeResize(m.V.rows() + 1, 3);
  m.V.bottomRows(1) << 0.5, 0.5, 1.0;
  m.F.conservativeResize(m.F.rows() + 1, 3);
  m.F.bottomRows(1) << 0, 4, int(m.V.rows()) - 1;
  const Error e = check(m);
  EXPECT_EQ(e.code, ErrorCode::NonManifoldEdges);
  EXPECT_EQ(e.count, 1);
}

TEST(DiskMesh, InconsistentOrientation) {
  testmesh::Mesh m = testmesh::grid(3);
  std::swap(m.F(4, 0), m.F(4, 1));
  EXPECT_EQ(check(m).code, ErrorCode::InconsistentOrientation);
}

TEST(DiskMesh, TwoComponents) {
  const Error e = check(testmesh::two_grids(2));
  EXPECT_EQ(e.code, ErrorCode::SeveralComponents);
  EXPECT_EQ(e.count, 2);
}

TEST(DiskMesh, TriangleSoupIsNamedUnwelded) {
  const testmesh::Mesh m = testmesh::soup(testmesh::grid(3));  // 18 faces, 54 vertices
  const Error e = check(m);
  EXPECT_EQ(e.code, ErrorCode::UnweldedVertices);
  // Every vertex but the grid's two corners with a single face sits on another.
  EXPECT_EQ(e.count, 52);
  EXPECT_FALSE(charts_would_help(e.code));
}

TEST(DiskMesh, PartsMeetingAlongASideStaySeveralComponents) {
  // The second grid's left column sits on the first's right one: 6 of 18 vertices, not a soup.
  const Error e = check(testmesh::joined(testmesh::grid(2), testmesh::grid(2), 1, Eigen::RowVector3d(1, 0, 0)));
  EXPECT_EQ(e.code, ErrorCode::SeveralComponents);
  EXPECT_EQ(e.count, 2);
}

TEST(DiskMesh, NonManifoldVertexOfTwoFansSharingAVertex) {
  testmesh::Mesh m;
  m.V.resize(5, 3);
  m.V << 0, 0, 0, 1, 0, 0, 0, 1, 0, -1, 0, 0, 0, -1, 0;
  m.F.resize(2, 3);
  m.F << 0, 1, 2, 0, 3, 4;
  const Error e = check(m);
  EXPECT_EQ(e.code, ErrorCode::NonManifoldVertices);
  EXPECT_EQ(e.count, 1);
}

TEST(DiskMesh, Closed) {
  const Error e = check(testmesh::octahedron());
  EXPECT_EQ(e.code, ErrorCode::Closed);
  EXPECT_TRUE(charts_would_help(e.code));
}

TEST(DiskMesh, HoleMakesTwoBoundaryLoops) {
  const testmesh::Mesh m = testmesh::without_face(testmesh::grid(4), 2 * 5 + 1);  // an interior face
  const Error e = check(m);
  EXPECT_EQ(e.code, ErrorCode::SeveralBoundaryLoops);
  EXPECT_EQ(e.count, 2);
  EXPECT_TRUE(charts_would_help(e.code));
}

TEST(DiskMesh, PuncturedTorusIsGenusOne) {
  const Error e = check(testmesh::without_face(testmesh::torus(8, 6), 0));
  EXPECT_EQ(e.code, ErrorCode::NotGenusZero);
  EXPECT_EQ(e.count, 1);
}

TEST(DiskMesh, AllFacesZeroArea) {
  testmesh::Mesh m = testmesh::grid(2);
  m.V.col(1).setZero();  // everything on the x axis
  const Error e = check(m);
  EXPECT_EQ(e.code, ErrorCode::ZeroAreaMesh);
  EXPECT_EQ(e.count, 8);
}
