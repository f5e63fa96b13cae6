// The gutter a stored atlas keeps (least_gutter): known values on two triangles, and the same as
// every pair of triangles compared (layout_checks) on an atlas whose charts are moved by hand.
#include <gtest/gtest.h>
#include <algorithm>
#include <vector>

#include "atlas/charts.h"
#include "atlas/measure/least_gutter.h"
#include "generated_meshes.h"
#include "layout_checks.h"

using namespace lowstretch;

namespace {

// Two charts of one triangle each: (0.1, 0.1), (0.3, 0.1), (0.1, 0.3) and the same shifted right
// by 0.2 + apart.
Eigen::MatrixXd two_triangles(double apart) {
  Eigen::MatrixXd uv(2, 6);
  uv.row(0) << 0.1, 0.1, 0.3, 0.1, 0.1, 0.3;
  uv.row(1) = uv.row(0);
  for (int k = 0; k < 3; ++k) uv(1, 2 * k) += 0.2 + apart;
  return uv;
}

double border_distance(const Eigen::MatrixXd& uv) { return std::min(uv.minCoeff(), 1 - uv.maxCoeff()); }

}  // namespace

TEST(LeastGutter, KnownValuesOnTwoTriangles) {
  const std::vector<int> charts = {0, 1};
  EXPECT_NEAR(least_gutter(two_triangles(0.003), charts, 0.01), 0.003, 1e-12);
  EXPECT_GE(least_gutter(two_triangles(0.02), charts, 0.01), 0.01);  // farther than looked for
  EXPECT_NEAR(least_gutter(two_triangles(0.06), charts, 0.01), 0.1, 1e-12);  // far: the border's
  EXPECT_EQ(least_gutter(two_triangles(-0.05), charts, 0.01), 0);             // overlapping
  EXPECT_NEAR(least_gutter(two_triangles(0.003), {0, 0}, 0.01), 0.1, 1e-12);  // one chart: the border only
  Eigen::MatrixXd near_border = two_triangles(0.003);
  near_border(0, 0) = near_border(0, 4) = 0.001;
  EXPECT_NEAR(least_gutter(near_border, charts, 0.01), 0.001, 1e-12);
}

// Charts of a real atlas moved towards each other: the same least distance as all pairs of
// triangles of different charts give, wherever it is below what is looked for.
TEST(LeastGutter, TheSameAsEveryPairOfTrianglesCompared) {
  testmesh::Mesh m = testmesh::joined(testmesh::torus(16, 8), testmesh::hemisphere(6, 12), 0.7, Eigen::RowVector3d(4, 0, 0));
  m = testmesh::joined(m, testmesh::punched_grid(10, {{0.5, 0.5}}, 0.2), 1.5, Eigen::RowVector3d(8, 0, 0));
  const ChartsResult atlas = parameterize_charts(m.V, m.F, ChartOptions());
  ASSERT_FALSE(atlas.error);
  ASSERT_GT(atlas.charts.size(), 2u);
  const ChartOptions options;
  const double within = 2 * options.gutter / options.texture_size;
  EXPECT_GE(atlas.least_gutter, options.gutter * (1 - 1e-6));
  int compared = 0;
  for (const double shift : {0.0, 0.001, 0.002, 0.004, 0.01, 0.03}) {
    ChartsResult moved = atlas;
    for (Eigen::Index f = 0; f < m.F.rows(); ++f)
      if (moved.face_chart[size_t(f)] == 0)
        for (int k = 0; k < 3; ++k) moved.corner_uv(f, 2 * k) += shift, moved.corner_uv(f, 2 * k + 1) += shift / 3;
    const double measured = least_gutter(moved.corner_uv, moved.face_chart, within);
    const double every_pair = std::min(least_distance_between_charts(m.F, moved), border_distance(moved.corner_uv));
    if (every_pair < within) {
      EXPECT_NEAR(measured, every_pair, 1e-12) << "shift " << shift;
      ++compared;
    } else {
      EXPECT_GE(measured, std::min(within, border_distance(moved.corner_uv)) - 1e-12) << "shift " << shift;
    }
  }
  EXPECT_GE(compared, 2);
}
