#include "chart_fixtures.h"

#include <gtest/gtest.h>

#include <cmath>

#include "layout_checks.h"

namespace lowstretch {

namespace {

// NonDisk::Atlas at a bound, a chart limit and a least efficiency for merging (1 merges none).
ChartsResult atlas_with(const testmesh::Mesh& m, double max_stretch, int max_charts, double min_efficiency) {
  ChartOptions options;
  options.non_disk = NonDisk::Atlas;
  options.max_stretch = max_stretch;
  options.max_charts = max_charts;
  options.min_efficiency = min_efficiency;
  return parameterize_charts(m.V, m.F, options);
}

}  // namespace

ChartsResult bounded_atlas(const testmesh::Mesh& m, double max_stretch, int max_charts) {
  return atlas_with(m, max_stretch, max_charts, ChartOptions().min_efficiency);
}

ChartsResult unmerged_atlas(const testmesh::Mesh& m, double max_stretch) {
  return atlas_with(m, max_stretch, ChartOptions().max_charts, 1);
}

ChartsResult fine_charts_of(const testmesh::Mesh& m, double max_stretch) {
  ChartOptions options;
  options.non_disk = NonDisk::Charts;
  options.max_stretch = max_stretch;
  options.texture_size = 65536;
  options.gutter = 0.5;
  return parameterize_charts(m.V, m.F, options);
}

SolvedChart solved_chart_of(const testmesh::Mesh& m, std::vector<int> faces) {
  SolvedChart chart;
  if (faces.empty())
    for (Eigen::Index f = 0; f < m.F.rows(); ++f) faces.push_back(int(f));
  chart.faces = faces;
  std::vector<int> local_of(size_t(m.V.rows()), -1);
  EXPECT_FALSE(make_chart_mesh(m.V, m.F, chart.faces, local_of, chart.mesh));
  solve_chart(chart, Options(), 0);
  return chart;
}
double real_uv_area(const SolvedChart& c) {
  double area = 0;
  for (Eigen::Index f = 0; f < Eigen::Index(c.faces.size()); ++f) {
    const Eigen::Vector2d a = c.map.uv.row(c.mesh.F(f, 0)), b = c.map.uv.row(c.mesh.F(f, 1)), d = c.map.uv.row(c.mesh.F(f, 2));
    area += std::abs(signed_area(a, b, d));
  }
  return area;
}

}  // namespace lowstretch
