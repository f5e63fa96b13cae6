// The optional refinement after the paper's passes (core/refine_stretch.h): it lowers the L2
// stretch energy, keeps every triangle positive and the boundary where it was, and finds the
// known optimum of a flat mesh (its own shape).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/disk_mesh.h"
#include "core/parameterize.h"
#include "core/refine_stretch.h"
#include "core/stretch.h"
#include "generated_meshes.h"

using namespace lowstretch;

namespace {

int non_positive_triangles(const DiskMesh& disk, const Eigen::MatrixXd& uv) {
  int count = 0;
  for (Eigen::Index f = 0; f < disk.F.rows(); ++f) {
    const Eigen::RowVector2d a = uv.row(disk.F(f, 0)), b = uv.row(disk.F(f, 1)), c = uv.row(disk.F(f, 2));
    count += !((b - a).x() * (c - a).y() - (c - a).x() * (b - a).y() > 0);
  }
  return count;
}

}  // namespace

TEST(RefineStretch, FlatSquareReturnsToItsOwnShape) {
  // A flat square grid is its own optimum (stretch 1 everywhere) for its own boundary. Start from
  // its shape with the interior shaken (still valid): the refinement must find the shape again.
  const testmesh::Mesh m = testmesh::grid(8);
  DiskMesh disk;
  ASSERT_FALSE(make_disk_mesh(m.V, m.F, disk));
  Eigen::MatrixXd exact = disk.V.leftCols(2);  // the unit box maps [0,1]^2 to [-1/2,1/2]^2
  Eigen::MatrixXd shaken = exact;
  std::mt19937 random(7);
  std::uniform_real_distribution<double> jitter(-0.015, 0.015);  // a fifth of the grid step
  for (Eigen::Index i = 0; i < shaken.rows(); ++i)
    if (!disk.is_boundary[size_t(i)]) shaken.row(i) += Eigen::RowVector2d(jitter(random), jitter(random));
  ASSERT_EQ(non_positive_triangles(disk, shaken), 0);
  RefineOptions options;
  options.relative_decrease = 1e-14;
  RefineReport report;
  const Eigen::MatrixXd refined = refine_stretch(disk, shaken, options, report);
  ASSERT_TRUE(report.started);
  EXPECT_LT(report.energy_after, report.energy_before);
  EXPECT_LT((refined - exact).cwiseAbs().maxCoeff(), 1e-6);
  EXPECT_NEAR(l2_stretch(face_stretch(disk.V, disk.F, refined)), 1.0, 1e-9);
  for (Eigen::Index i = 0; i < refined.rows(); ++i)
    if (disk.is_boundary[size_t(i)]) EXPECT_EQ(refined.row(i), shaken.row(i));
}

TEST(RefineStretch, LowersTheStretchOfACurvedDiskWithoutFlipping) {
  const testmesh::Mesh m = testmesh::tall_cap(10, 24);
  Options plain;
  const Result method = parameterize(m.V, m.F, plain);
  ASSERT_FALSE(method.error) << message(method.error);
  Options refine = plain;
  refine.refine = true;
  refine.refine_time_factor = 1000;  // a small mesh: let it converge
  const Result refined = parameterize(m.V, m.F, refine);
  ASSERT_FALSE(refined.error) << message(refined.error);
  const FaceStretch before = face_stretch(m.V, m.F, method.uv), after = face_stretch(m.V, m.F, refined.uv);
  EXPECT_EQ(after.flipped + after.degenerate, 0);
  EXPECT_LT(l2_stretch(after), 0.99 * l2_stretch(before));
  EXPECT_EQ(refined.chosen_pass, method.chosen_pass);  // the passes are the paper's, untouched
  EXPECT_GT(refined.notes.size(), method.notes.size()) << "a note says what the refinement gained";
}

TEST(RefineStretch, RefusesAMapThatIsAlreadyFlipped) {
  const testmesh::Mesh m = testmesh::grid(4);
  DiskMesh disk;
  ASSERT_FALSE(make_disk_mesh(m.V, m.F, disk));
  Eigen::MatrixXd uv = disk.V.leftCols(2);
  for (Eigen::Index i = 0; i < uv.rows(); ++i)
    if (!disk.is_boundary[size_t(i)]) uv(i, 0) = -uv(i, 0);  // mirror the interior: triangles flip
  RefineReport report;
  const Eigen::MatrixXd out = refine_stretch(disk, uv, RefineOptions(), report);
  EXPECT_FALSE(report.started);
  EXPECT_EQ(out, uv);
}
