// Charts mapped again free (atlas/chart_map/free_charts.h): flat charts seen along their normal,
// and charts that no rectangle fits keep their own shape.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "atlas/base/tuning.h"
#include "atlas/charts.h"
#include "atlas/chart_map/free_charts.h"
#include "atlas/chart_map/solved_chart.h"
#include "chart_fixtures.h"
#include "generated_meshes.h"
#include "layout_checks.h"
#include "core/stretch.h"

using namespace lowstretch;

// A flat tapered face (1 wide at one end, 0.1 at the other) stretches on its rectangle; seen
// along its normal it is exact (L2 1). A curved cap is not flat and keeps its rectangle.
TEST(FreeCharts, FlatChartIsSeenAlongItsNormalAndCurvedOneKeepsItsRectangle) {
  testmesh::Mesh web = testmesh::grid(12);
  web.V.col(0) = (web.V.col(0).array() - 0.5) * (1 - 0.9 * web.V.col(1).array()) + 0.5;
  std::vector<SolvedChart> charts = {solved_chart_of(web), solved_chart_of(testmesh::hemisphere(8, 16))};
  ASSERT_FALSE(charts[0].map.error);
  ASSERT_FALSE(charts[1].map.error);
  const double web_on_rectangle = charts[0].kept.l2_stretch, cap_on_rectangle = charts[1].kept.l2_stretch;
  EXPECT_GT(web_on_rectangle, kTuning.flat_below);
  see_flat_charts_along_normal(charts);
  EXPECT_TRUE(charts[0].free_boundary);
  EXPECT_NEAR(charts[0].kept.l2_stretch, 1.0, 1e-9);
  EXPECT_EQ(charts[0].kept.flipped + charts[0].kept.degenerate, 0);
  EXPECT_NEAR(charts[0].fill(), 0.55, 0.01);  // the trapezoid's area over its box's: (1 + 0.1) / 2
  EXPECT_FALSE(charts[1].free_boundary);
  EXPECT_EQ(charts[1].kept.l2_stretch, cap_on_rectangle);
}

// A flat 4 x 1 strip mapped with the natural boundary is exact, but the boundary is pinned along
// the strip's diagonal: so its box is 4.12 x 1.94 (fill 0.50). Turned, it fills its box and keeps
// its stretch; a chart on its rectangle is left as it is.
TEST(FreeCharts, FreeChartsAreTurnedToTheirSmallestBox) {
  testmesh::Mesh strip = testmesh::grid(8);
  strip.V.col(0) *= 4;
  std::vector<SolvedChart> charts = {solved_chart_of(strip), solved_chart_of(testmesh::hemisphere(8, 16))};
  solve_onto(charts[0], Options(), 0, true);
  ASSERT_FALSE(charts[0].map.error);
  ASSERT_FALSE(charts[1].map.error);
  EXPECT_LT(charts[0].fill(), 0.6);
  const double strip_stretch = charts[0].kept.l2_stretch;
  const Eigen::MatrixXd cap_uv = charts[1].map.uv;
  turn_free_charts_to_smallest_box(charts);
  EXPECT_GT(charts[0].fill(), 0.98);
  EXPECT_NEAR(std::max(charts[0].aspect(), 1 / charts[0].aspect()), 4.0, 0.1);
  const FaceStretch turned = face_stretch(charts[0].mesh.V, charts[0].mesh.F, charts[0].map.uv);
  EXPECT_EQ(turned.flipped, 0);
  EXPECT_NEAR(l2_stretch(turned), strip_stretch, 1e-9);
  EXPECT_EQ(charts[1].map.uv, cap_uv);
}

// A jagged sliver has no good rectangle: its corners and squeezed ears stretch it (L2 12.1 over
// the atlas, 14.3 on its chart, when every chart was a rectangle), and at 28 faces it is too small
// to cut. Its natural-boundary map keeps its shape.
TEST(FreeCharts, SliverWithNoGoodRectangleKeepsItsOwnShape) {
  const testmesh::Mesh band = testmesh::jagged_band(8);
  ASSERT_LT(band.F.rows(), 2 * kTuning.smallest_chart);
  const testmesh::Mesh m = testmesh::joined(testmesh::sphere(10, 16), band, 1, Eigen::RowVector3d(40, 0, 0));
  const ChartsResult atlas = bounded_atlas(m);
  expect_valid_layout(m.F, atlas);
  for (size_t c = 0; c < atlas.charts.size(); ++c) EXPECT_LT(atlas.charts[c].l2_stretch, 1.5) << "chart " << c;
  EXPECT_LT(atlas.layout.l2_stretch, 1.5);
}

// A flat face with a hole (the top of a plate) has an exact map, its own shape seen along its
// normal; its rectangle would stretch it around the hole (L2 1.07 there before). The map is one
// linear map for all its faces, stretched at most along the sides of its cell (here 1.6 times
// along one side: L2 1.055). (At bound 1.5 the texels its hole leaves empty do not get it cut:
// HoleThatWastesTheBoxIsCutOpen.)
TEST(FreeCharts, FlatFaceWithAHoleKeepsItsShape) {
  const int n = 8, top_faces = 2 * n * n - 2 * (n / 2) * (n / 2);
  const testmesh::Mesh m = testmesh::plate_with_hole(n, 1.0 / n);
  const ChartsResult r = unmerged_atlas(m, 1.5);
  expect_valid_layout(m.F, r);
  const auto linear_map = [&](int f) {  // from the face's (x, y) to its UV
    Eigen::Matrix2d xy, uv;
    for (int k = 1; k < 3; ++k) {
      xy.col(k - 1) = (m.V.row(m.F(f, k)) - m.V.row(m.F(f, 0))).head<2>().transpose();
      uv.col(k - 1) = (r.corner_uv.block(f, 2 * k, 1, 2) - r.corner_uv.block(f, 0, 1, 2)).transpose();
    }
    return Eigen::Matrix2d(uv * xy.inverse());
  };
  const Eigen::Matrix2d first = linear_map(0);
  for (int f = 1; f < top_faces; ++f) {
    ASSERT_EQ(r.face_chart[size_t(f)], r.face_chart[0]) << "face " << f << ": the top is one chart";
    // UVs are stored as floats: a face's linear map is off by about 1e-7 of its size.
    EXPECT_LT((linear_map(f) - first).norm(), 1e-5 * first.norm()) << "face " << f;
  }
  EXPECT_LT(r.charts[size_t(r.face_chart[0])].l2_stretch, 1.07);  // on its rectangle it had 1.07
}

// Packed by outline, a chart costs its own area, so every chart above kTuning.free_above goes free
// where that stretches it less: the flat tapered face seen along its normal (L2 1), the cap with
// the natural boundary. None folds over itself, none stretches more than on its rectangle, and a
// chart already free is left.
TEST(FreeCharts, ChartsAreFreedWhereThatStretchesThemLess) {
  testmesh::Mesh web = testmesh::grid(12);
  web.V.col(0) = (web.V.col(0).array() - 0.5) * (1 - 0.9 * web.V.col(1).array()) + 0.5;
  std::vector<SolvedChart> charts = {solved_chart_of(web), solved_chart_of(testmesh::hemisphere(8, 16))};
  std::vector<double> on_rectangle;
  for (const SolvedChart& c : charts) {
    ASSERT_FALSE(c.map.error);
    ASSERT_FALSE(c.free_boundary);
    ASSERT_GT(c.kept.l2_stretch, kTuning.free_above);
    on_rectangle.push_back(c.kept.l2_stretch);
  }
  EXPECT_EQ(free_where_it_stretches_less(charts, ChartOptions()), 2);
  for (size_t c = 0; c < charts.size(); ++c) {
    EXPECT_TRUE(charts[c].free_boundary) << "chart " << c;
    EXPECT_LT(charts[c].kept.l2_stretch, on_rectangle[c]) << "chart " << c;
    EXPECT_EQ(charts[c].kept.flipped + charts[c].kept.degenerate, 0) << "chart " << c;
    EXPECT_FALSE(crosses_itself(charts[c])) << "chart " << c;
  }
  EXPECT_NEAR(charts[0].kept.l2_stretch, 1.0, 1e-9);
  const double cap_freed = charts[1].kept.l2_stretch;
  EXPECT_EQ(free_where_it_stretches_less(charts, ChartOptions()), 0);
  EXPECT_EQ(charts[1].kept.l2_stretch, cap_freed);
}

// The genus-2 solid's atlas: its charts, freed where that stretches them less, pack by their
// outlines better than tiled, and the layout stays valid (no flip, zero-area triangle or overlap).
TEST(FreeCharts, AtlasPackedByOutlineWithChartsFreedIsValid) {
  const testmesh::Mesh m = testmesh::double_torus();
  const ChartsResult r = bounded_atlas(m);
  expect_valid_layout(m.F, r);
  EXPECT_TRUE(std::any_of(r.notes.begin(), r.notes.end(), [](const std::string& n) {
    return n.find("charts mapped free where that stretches them less") != std::string::npos;
  }));
}

// Where charts are refined (Fewer seams), a free chart is refined again with its boundary moving
// too: the natural boundary of a square with a steep bump near a corner is conformal, which
// shrinks the bump (L2 2.9), and a moving boundary gives it room. The chart keeps the new map only
// as it uses its box better (fill / L2^2), with no flip and an outline that does not cross itself;
// a chart on its rectangle, and every chart where nothing is refined, are left as they are.
TEST(FreeCharts, RefinedFreeChartsMoveTheirBoundaryToo) {
  ChartOptions refining;
  refining.disk.refine = true;
  refining.disk.refine_iterations = kTuning.refine_steps;
  const testmesh::Mesh bumped = testmesh::grid(16, [](double x, double y) {
    return std::exp(-((x - 0.8) * (x - 0.8) + (y - 0.8) * (y - 0.8)) / 0.01);
  });
  std::vector<SolvedChart> charts = {solved_chart_of(bumped), solved_chart_of(testmesh::hemisphere(8, 16))};
  solve_onto(charts[0], refining.disk, 0, true);
  for (const SolvedChart& c : charts) ASSERT_FALSE(c.map.error);
  ASSERT_TRUE(charts[0].free_boundary);
  ASSERT_EQ(charts[0].kept.flipped + charts[0].kept.degenerate, 0);
  const std::vector<SolvedChart> before = charts;
  refine_free_outlines(charts, ChartOptions());
  for (size_t c = 0; c < charts.size(); ++c) EXPECT_EQ(charts[c].map.uv, before[c].map.uv) << "chart " << c;
  refine_free_outlines(charts, refining);
  const auto box_use = [](const SolvedChart& c) { return c.fill() / (c.kept.l2_stretch * c.kept.l2_stretch); };
  EXPECT_TRUE(charts[0].free_boundary);
  EXPECT_LT(charts[0].kept.l2_stretch, 0.6 * before[0].kept.l2_stretch) << before[0].kept.l2_stretch;
  EXPECT_GT(box_use(charts[0]), box_use(before[0]));
  EXPECT_EQ(charts[0].kept.flipped + charts[0].kept.degenerate, 0);
  EXPECT_FALSE(crosses_itself(charts[0]));
  const FaceStretch measured = face_stretch(charts[0].mesh.V, charts[0].mesh.F.topRows(Eigen::Index(charts[0].faces.size())), charts[0].map.uv);
  EXPECT_NEAR(l2_stretch(measured), charts[0].kept.l2_stretch, 1e-9) << "the kept measure is the map's";
  EXPECT_EQ(charts[1].map.uv, before[1].map.uv);
}
