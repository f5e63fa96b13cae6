// A chart's mesh (atlas/chart_map/solved_chart.h): its disk and initial weights are prepared when
// it is first mapped, once for every copy of it, with the weights that map asks for.
#include <gtest/gtest.h>

#include <vector>

#include "atlas/chart_map/solved_chart.h"
#include "generated_meshes.h"

using namespace lowstretch;

namespace {

SolvedChart unmapped_chart_of(const testmesh::Mesh& m) {
  SolvedChart chart;
  for (Eigen::Index f = 0; f < m.F.rows(); ++f) chart.faces.push_back(int(f));
  std::vector<int> local_of(size_t(m.V.rows()), -1);
  EXPECT_FALSE(make_chart_mesh(m.V, m.F, chart.faces, local_of, chart.mesh));
  return chart;
}

}  // namespace

// A copy mapped after the original shares its preparation and gets the same map; a chart mapped
// first with mean value weights is prepared with them and maps as one prepared anew does.
TEST(ChartMesh, PreparedOnceWhenFirstMappedWithTheWeightsAskedFor) {
  const testmesh::Mesh cap = testmesh::hemisphere(8, 16);
  SolvedChart chart = unmapped_chart_of(cap);
  ASSERT_TRUE(chart.mesh.prepared);
  SolvedChart copy = chart;
  EXPECT_EQ(copy.mesh.prepared, chart.mesh.prepared);
  solve_onto(chart, Options(), 0);
  solve_onto(copy, Options(), 0);
  ASSERT_FALSE(chart.map.error);
  ASSERT_FALSE(copy.map.error);
  EXPECT_EQ(copy.map.uv, chart.map.uv);
  Error error;
  EXPECT_EQ(chart.mesh.prepared->get(chart.mesh.V, chart.mesh.F, InitialWeights::MeanValue, error).kind, InitialWeights::Floater);

  Options mean_value;
  mean_value.weights = InitialWeights::MeanValue;
  SolvedChart other = unmapped_chart_of(cap);
  solve_onto(other, mean_value, 0);
  ASSERT_FALSE(other.map.error);
  EXPECT_EQ(other.mesh.prepared->get(other.mesh.V, other.mesh.F, InitialWeights::Floater, error).kind, InitialWeights::MeanValue);
  SolvedChart fresh = unmapped_chart_of(cap);
  fresh.mesh.prepared.reset();  // map_chart prepares its own
  solve_onto(fresh, mean_value, 0);
  ASSERT_FALSE(fresh.map.error);
  EXPECT_EQ(fresh.map.uv, other.map.uv);
  EXPECT_GT((other.map.uv - chart.map.uv).cwiseAbs().maxCoeff(), 1e-6);  // the weights changed the map
}
