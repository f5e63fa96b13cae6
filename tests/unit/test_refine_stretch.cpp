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
  options.max_iterations = 200;  // a small mesh: let it converge
  RefineReport report;
  const Eigen::MatrixXd refined = refine_stretch(disk, shaken, options, report);
  EXPECT_LT(report.iterations, options.max_iterations) << "it converged: the relative decrease stopped it";
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
  refine.refine_iterations = 200;  // a small mesh: let it converge
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

TEST(RefineStretch, ASliverKeepsAUvTriangleATextureResolves) {
  // A flat grid with one interior vertex moved next to the far edge of one of its triangles: that
  // triangle is a sliver of next to no 3D area, and the map with least energy is the mesh's own
  // layout, where the sliver's UV triangle is as thin. Start from that layout with the vertex a
  // little back, the sliver at 4 millionths of the map's area: refining with a least area share
  // of a millionth takes it that far down, no further; without one, to its 3D area.
  const testmesh::Mesh m = testmesh::grid(8);
  DiskMesh grid, disk;
  ASSERT_FALSE(make_disk_mesh(m.V, m.F, grid));
  int sliver = -1, moved = -1;
  for (Eigen::Index f = 0; f < grid.F.rows() && sliver < 0; ++f)
    if (!grid.is_boundary[size_t(grid.F(f, 0))]) sliver = int(f), moved = grid.F(f, 0);
  ASSERT_GE(sliver, 0);
  const Eigen::RowVector2d a = grid.V.block(grid.F(sliver, 1), 0, 1, 2), b = grid.V.block(grid.F(sliver, 2), 0, 1, 2);
  const Eigen::RowVector2d middle = 0.5 * (a + b), away = grid.V.block(moved, 0, 1, 2) - middle;
  testmesh::Mesh thin = m;  // the grid is [0,1]^2, its unit box [-1/2,1/2]^2: the boundary did not move
  thin.V.block(grid.input_vertex[size_t(moved)], 0, 1, 2) = middle + 1e-9 * away + Eigen::RowVector2d(0.5, 0.5);
  ASSERT_FALSE(make_disk_mesh(thin.V, thin.F, disk));
  const auto area = [&](const Eigen::MatrixXd& map, Eigen::Index f) {
    return signed_uv_area(map.row(disk.F(f, 0)), map.row(disk.F(f, 1)), map.row(disk.F(f, 2)));
  };
  Eigen::MatrixXd uv = disk.V.leftCols(2);
  ASSERT_LT(area(uv, sliver), 1e-8) << "the sliver is thin in 3D";
  uv.row(moved) = middle + 4e-6 / area(grid.V.leftCols(2), sliver) * away;
  ASSERT_NEAR(area(uv, sliver), 4e-6, 1e-12);
  RefineOptions options;
  options.relative_decrease = 1e-14;
  options.max_iterations = 200;
  options.least_area_share = 1e-6;
  RefineReport report;
  const Eigen::MatrixXd refined = refine_stretch(disk, uv, options, report);
  ASSERT_TRUE(report.started);
  EXPECT_LT(report.energy_after, report.energy_before);
  EXPECT_GE(area(refined, sliver), 1e-6 * (1 - 1e-9));
  EXPECT_LT(area(refined, sliver), 3e-6) << "the sliver did shrink, toward its least area";
  EXPECT_EQ(non_positive_triangles(disk, refined), 0);
  options.least_area_share = 0;
  const Eigen::MatrixXd free = refine_stretch(disk, uv, options, report);
  EXPECT_LT(area(free, sliver), 1e-9) << "without a least area the sliver shrinks toward its 3D area";
}

TEST(RefineStretch, AFixedNumberOfStepsGivesTheSameMapEveryRun) {
  const testmesh::Mesh m = testmesh::tall_cap(10, 24);
  Options options;
  options.refine = true;
  options.refine_iterations = 2;  // the budget is steps, never seconds
  const Result a = parameterize(m.V, m.F, options), b = parameterize(m.V, m.F, options);
  ASSERT_FALSE(a.error) << message(a.error);
  EXPECT_EQ(a.uv, b.uv);
  options.refine = false;
  const Result plain = parameterize(m.V, m.F, options);
  EXPECT_LT(l2_stretch(face_stretch(m.V, m.F, a.uv)), l2_stretch(face_stretch(m.V, m.F, plain.uv)));
  ASSERT_FALSE(a.notes.empty());
  EXPECT_NE(a.notes.back().find("in 2 iterations"), std::string::npos) << a.notes.back();
  // More steps give less stretch still, and the same map every run too.
  options.refine = true;
  options.refine_iterations = 6;
  const Result c = parameterize(m.V, m.F, options), d = parameterize(m.V, m.F, options);
  ASSERT_FALSE(c.error) << message(c.error);
  EXPECT_EQ(c.uv, d.uv);
  EXPECT_LT(l2_stretch(face_stretch(m.V, m.F, c.uv)), l2_stretch(face_stretch(m.V, m.F, a.uv)));
}

TEST(RefineStretch, TheStepBudgetIsChecked) {
  const testmesh::Mesh m = testmesh::tall_cap(10, 24);
  for (const int steps : {0, kMostRefineIterations + 1}) {
    Options options;
    options.refine = true;
    options.refine_iterations = steps;
    const Result r = parameterize(m.V, m.F, options);
    EXPECT_EQ(r.error.code, ErrorCode::InvalidOption) << steps;
    EXPECT_EQ(r.error.option, "refine_iterations");
  }
  EXPECT_GT(Options().refine_iterations, 0);
  EXPECT_EQ(RefineOptions().max_iterations, Options().refine_iterations) << "one default budget";
}

// A 3 x 1 strip bent into a half cylinder is developable: its one map without stretch is the flat
// 3 x 1 rectangle. On the square its L2 stretch is far above 1, and with the boundary kept it
// stays so; with the boundary free the refinement unrolls it (L2 1, sides 3 to 1). What it
// lowers, the stretch energy times the UV area, no scaling changes: from the map ten times as
// large it finds a map as good (of a size of its own: scaling changes nothing it measures).
TEST(RefineStretch, AFreeBoundaryUnrollsABentStrip) {
  const testmesh::Mesh flat_grid = testmesh::grid(12);
  testmesh::Mesh strip = flat_grid;
  const double radius = 3 / M_PI;
  for (Eigen::Index i = 0; i < strip.V.rows(); ++i) {
    const double angle = 3 * strip.V(i, 0) / radius;
    strip.V.row(i) << radius * std::sin(angle), strip.V(i, 1), radius * std::cos(angle);
  }
  const Result on_square = parameterize(strip.V, strip.F, Options());
  ASSERT_FALSE(on_square.error) << message(on_square.error);
  DiskMesh disk;
  ASSERT_FALSE(make_disk_mesh(strip.V, strip.F, disk));
  Eigen::MatrixXd uv(disk.V.rows(), 2);
  for (Eigen::Index i = 0; i < uv.rows(); ++i) uv.row(i) = on_square.uv.row(disk.input_vertex[size_t(i)]);
  const double square_stretch = l2_stretch(face_stretch(disk.V, disk.F, uv));
  ASSERT_GT(square_stretch, 1.2);

  RefineOptions options;
  options.relative_decrease = 1e-12;
  options.max_iterations = 200;
  RefineReport kept, moved, scaled;
  const Eigen::MatrixXd boundary_kept = refine_stretch(disk, uv, options, kept);
  EXPECT_GT(l2_stretch(face_stretch(disk.V, disk.F, boundary_kept)), 1.1);
  options.free_boundary = true;
  const Eigen::MatrixXd unrolled = refine_stretch(disk, uv, options, moved);
  ASSERT_TRUE(moved.started);
  const FaceStretch flat = face_stretch(disk.V, disk.F, unrolled);
  EXPECT_EQ(flat.flipped + flat.degenerate, 0);
  EXPECT_NEAR(l2_stretch(flat), 1.0, 1e-3);
  // Its sides: the strip's long side over its short one, as in 3D (the map may turn).
  const auto row_at = [&](double x, double y) {
    Eigen::Index at = 0;
    (flat_grid.V.leftCols(2).rowwise() - Eigen::RowVector2d(x, y)).rowwise().squaredNorm().minCoeff(&at);
    for (Eigen::Index i = 0; i < disk.V.rows(); ++i)
      if (disk.input_vertex[size_t(i)] == at) return i;
    return Eigen::Index(-1);
  };
  const Eigen::RowVector2d corner = unrolled.row(row_at(0, 0));
  const double long_side = (unrolled.row(row_at(1, 0)) - corner).norm(), short_side = (unrolled.row(row_at(0, 1)) - corner).norm();
  EXPECT_NEAR(long_side / short_side, 3.0, 0.01);
  const Eigen::MatrixXd from_larger = refine_stretch(disk, 10 * uv, options, scaled);
  EXPECT_NEAR(l2_stretch(face_stretch(disk.V, disk.F, from_larger)), l2_stretch(flat), 1e-6);
}
