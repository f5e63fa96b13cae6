// Charts mapped again free (atlas/chart_map/free_charts.h): flat charts seen along their normal.
#include <gtest/gtest.h>

#include <vector>

#include "atlas/base/tuning.h"
#include "atlas/chart_map/free_charts.h"
#include "atlas/chart_map/solved_chart.h"
#include "generated_meshes.h"

using namespace lowstretch;

namespace {

// All of m as one chart, mapped by the method onto its own rectangle.
SolvedChart chart_on_rectangle(const testmesh::Mesh& m) {
  SolvedChart chart;
  for (Eigen::Index f = 0; f < m.F.rows(); ++f) chart.faces.push_back(int(f));
  std::vector<int> local_of(size_t(m.V.rows()), -1);
  EXPECT_FALSE(make_chart_mesh(m.V, m.F, chart.faces, local_of, chart.mesh));
  solve_chart(chart, Options(), 0);
  return chart;
}

}  // namespace

// A flat tapered face (1 wide at one end, 0.1 at the other) stretches on its rectangle; seen
// along its normal it is exact (L2 1). A curved cap is not flat and keeps its rectangle.
TEST(FreeCharts, FlatChartIsSeenAlongItsNormalAndCurvedOneKeepsItsRectangle) {
  testmesh::Mesh web = testmesh::grid(12);
  web.V.col(0) = (web.V.col(0).array() - 0.5) * (1 - 0.9 * web.V.col(1).array()) + 0.5;
  std::vector<SolvedChart> charts = {chart_on_rectangle(web), chart_on_rectangle(testmesh::hemisphere(8, 16))};
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
