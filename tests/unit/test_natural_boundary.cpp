// The free ("natural") boundary (core/natural_boundary.h): the boundary of the least squares
// conformal map, fitted into [0,1]^2 keeping its aspect ratio.
#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <cmath>
#include <complex>
#include <vector>

#include "core/disk_mesh.h"
#include "core/natural_boundary.h"
#include "generated_meshes.h"

using namespace lowstretch;

namespace {

DiskMesh disk_of(const testmesh::Mesh& m) {
  DiskMesh disk;
  EXPECT_FALSE(make_disk_mesh(m.V, m.F, disk));
  return disk;
}

double signed_polygon_area(const Eigen::MatrixXd& p) {
  double twice = 0;
  for (Eigen::Index i = 0; i < p.rows(); ++i) {
    const Eigen::Index j = (i + 1) % p.rows();
    twice += p(i, 0) * p(j, 1) - p(j, 0) * p(i, 1);
  }
  return 0.5 * twice;
}

}  // namespace

// A flat disk is its own conformal map: its boundary comes back up to a similarity (turned,
// scaled, moved; not mirrored), found here by least squares over the complex numbers.
TEST(NaturalBoundary, FlatDiskReproducesItsOwnBoundaryUpToSimilarity) {
  testmesh::Mesh m = testmesh::grid(8);
  m.V.col(0) = (2 * m.V.col(0) + 0.5 * m.V.col(1)).eval();  // a parallelogram, twice as wide
  m.V.col(1) = (m.V.col(1).array() + 0.2 * m.V.col(0).array().square()).matrix();  // with a curved side
  const DiskMesh disk = disk_of(m);
  Eigen::MatrixXd uv;
  ASSERT_FALSE(natural_boundary(disk, uv));
  const Eigen::Index n = Eigen::Index(disk.boundary.size());
  ASSERT_EQ(uv.rows(), n);
  ASSERT_EQ(uv.cols(), 2);
  // uv = a z + b, z = x + i y: two complex unknowns, as four real ones.
  Eigen::MatrixXd A(2 * n, 4);
  Eigen::VectorXd rhs(2 * n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const double x = disk.V(disk.boundary[size_t(i)], 0), y = disk.V(disk.boundary[size_t(i)], 1);
    A.row(2 * i) << x, -y, 1, 0;
    A.row(2 * i + 1) << y, x, 0, 1;
    rhs(2 * i) = uv(i, 0);
    rhs(2 * i + 1) = uv(i, 1);
  }
  const Eigen::VectorXd s = A.colPivHouseholderQr().solve(rhs);
  EXPECT_LT((A * s - rhs).cwiseAbs().maxCoeff(), 1e-8);
  EXPECT_GT(std::hypot(s(0), s(1)), 0.1);  // not collapsed
  EXPECT_GT(signed_polygon_area(uv), 0);  // counter-clockwise, as the loop is in 3D
}

// Fitted into [0,1]^2 keeping the aspect ratio: inside it, and its longer side spans it.
TEST(NaturalBoundary, CurvedDiskIsFittedIntoTheUnitSquare) {
  for (const testmesh::Mesh& m : {testmesh::hemisphere(8, 16), testmesh::tall_cap(8, 16)}) {
    const DiskMesh disk = disk_of(m);
    Eigen::MatrixXd uv;
    ASSERT_FALSE(natural_boundary(disk, uv));
    ASSERT_EQ(uv.rows(), Eigen::Index(disk.boundary.size()));
    ASSERT_TRUE(uv.allFinite());
    EXPECT_GE(uv.minCoeff(), -1e-12);
    EXPECT_LE(uv.maxCoeff(), 1 + 1e-12);
    const Eigen::Vector2d size = uv.colwise().maxCoeff() - uv.colwise().minCoeff();
    EXPECT_NEAR(size.maxCoeff(), 1.0, 1e-12);
    EXPECT_GT(signed_polygon_area(uv), 0);
  }
}

// The pinned pair are the boundary vertices (about) farthest apart: on a long thin flat strip its
// two far ends, so the map's longer side lies along the strip, and its aspect is the strip's.
TEST(NaturalBoundary, LongStripKeepsItsAspect) {
  testmesh::Mesh m = testmesh::grid(10);
  m.V.col(0) *= 5;
  const DiskMesh disk = disk_of(m);
  Eigen::MatrixXd uv;
  ASSERT_FALSE(natural_boundary(disk, uv));
  const Eigen::Vector2d size = uv.colwise().maxCoeff() - uv.colwise().minCoeff();
  // A 5 x 1 rectangle seen at any angle has a box of aspect at most 5 along the strip, and about 5
  // when the diagonal pin turns it only by atan(1/5).
  const double along = size.maxCoeff() / size.minCoeff();
  EXPECT_GT(along, 1.5);
  EXPECT_LE(along, 5 + 1e-9);
}
