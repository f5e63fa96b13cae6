// Where the charts go (atlas/pack/lay_out_charts.h): each chart's cell area at one texel density,
// every chart fitted into its cell of the tiling a gutter from every other and from the border.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "atlas/charts.h"
#include "atlas/chart_map/solved_chart.h"
#include "atlas/pack/lay_out_charts.h"
#include "chart_fixtures.h"
#include "generated_meshes.h"
#include "layout_checks.h"

using namespace lowstretch;

// Charts are the gutter apart, in texels of the chosen texture (tiled, their bounding boxes are;
// packed by outline, their triangles), and the border of [0,1]^2 is a gutter away.
TEST(LayOutCharts, GutterBetweenChartsIsCountedInTexels) {
  const testmesh::Mesh m = testmesh::sphere_with_bump();
  for (const auto& texture : std::vector<std::pair<int, double>>{{1024, 2}, {512, 4}, {4096, 1}}) {
    ChartOptions options;
    options.non_disk = NonDisk::Atlas;
    options.texture_size = texture.first;
    options.gutter = texture.second;
    const ChartsResult r = parameterize_charts(m.V, m.F, options);
    ASSERT_FALSE(r.error) << message(r.error);
    const double g = texture.second / texture.first;
    std::vector<Eigen::AlignedBox2d> box(r.charts.size());
    for (Eigen::Index f = 0; f < m.F.rows(); ++f)
      for (int k = 0; k < 3; ++k) box[size_t(r.face_chart[size_t(f)])].extend(corner(r, f, k));
    for (size_t a = 0; a < box.size(); ++a) {
      EXPECT_GE(box[a].min().minCoeff(), g * (1 - 1e-6));
      EXPECT_LE(box[a].max().maxCoeff(), 1 - g * (1 - 1e-6));
    }
    EXPECT_GE(least_distance_between_charts(m.F, r), g * (1 - 1e-6)) << "at " << texture.first;
  }
}

// One grid twice as wide as four others: areas 4, 1, 1, 1, 1 tile the square as one half and four
// eighths, every cell within twice its chart's shape, so every chart fills its cell.
TEST(LayOutCharts, DisjointDisksGetOneChartEachAtTheSameTexelDensity) {
  const testmesh::Mesh grid = testmesh::grid(6);
  testmesh::Mesh m;
  m.V.resize(5 * grid.V.rows(), 3);
  m.F.resize(5 * grid.F.rows(), 3);
  for (int copy = 0; copy < 5; ++copy) {
    const double scale = copy == 0 ? 2 : 1;
    m.V.middleRows(copy * grid.V.rows(), grid.V.rows()) = (scale * grid.V).rowwise() + Eigen::RowVector3d(3 * copy, 0, 0);
    m.F.middleRows(copy * grid.F.rows(), grid.F.rows()) = (grid.F.array() + copy * int(grid.V.rows())).matrix();
  }
  const ChartsResult r = fine_charts_of(m);
  ASSERT_FALSE(r.error) << message(r.error);
  ASSERT_EQ(r.charts.size(), 5u);
  EXPECT_EQ(r.seam_length, 0.0);
  std::vector<double> uv(5, 0.0);
  for (Eigen::Index f = 0; f < m.F.rows(); ++f)
    uv[size_t(r.face_chart[size_t(f)])] += signed_area(corner(r, f, 0), corner(r, f, 1), corner(r, f, 2));
  const int big = r.face_chart[0];
  for (int c = 0; c < 5; ++c)
    if (c != big) EXPECT_NEAR(uv[size_t(big)] / uv[size_t(c)], 4.0, 4e-3) << "chart " << c;
}

// A grid with a hole closed for its solve and a grid without: the holed chart's cell holds the
// hole's empty texels too, so that both charts have one texel density (its cell once held only
// its area, squeezing it into part of its share).
TEST(LayOutCharts, ChartWithAClosedHoleHasTheTexelDensityOfTheOthers) {
  const testmesh::Mesh m = testmesh::joined(testmesh::punched_grid(20, {{0.5, 0.5}}, 0.25), testmesh::grid(20), 1,
                                            Eigen::RowVector3d(3, 0, 0));
  const ChartsResult r = fine_charts_of(m);
  ASSERT_FALSE(r.error) << message(r.error);
  ASSERT_EQ(r.charts.size(), 2u);
  const int holed = r.face_chart[0];
  ASSERT_EQ(r.charts[size_t(holed)].closed_holes, 1);
  const std::vector<double> density = texel_densities(m.V, m.F, r);
  EXPECT_NEAR(density[0] / density[1], 1.0, 0.05);
}

// Scan debris: thousands of loose triangles beside the part that matters. Each gets a cell of
// the smallest size a gutter allows (4000 cells a gutter wide at least, more than a tenth of the
// 1024-texel texture), which takes texture from the rest; a note says so.
TEST(LayOutCharts, TinyPartsThatTakeMuchOfTheTextureAreNoted) {
  testmesh::Mesh m = testmesh::sphere(16, 24);
  const Eigen::Index sphere_faces = m.F.rows();
  const ChartsResult alone = bounded_atlas(m);
  ASSERT_FALSE(alone.error) << message(alone.error);
  const auto sphere_uv_area = [&](const ChartsResult& r) {
    double area = 0;
    for (Eigen::Index f = 0; f < sphere_faces; ++f) area += signed_area(corner(r, f, 0), corner(r, f, 1), corner(r, f, 2));
    return area;
  };
  m = testmesh::with_specks(m, 4000, 64, 2);
  const ChartsResult r = bounded_atlas(m);
  ASSERT_FALSE(r.error) << message(r.error);
  EXPECT_GE(r.charts.size(), 4001u);  // the sphere, and a chart per speck
  EXPECT_LT(sphere_uv_area(r), 0.9 * sphere_uv_area(alone));
  EXPECT_GT(r.notes.size(), alone.notes.size());
}

// More debris than the tiling has cells for, each a few texels wide inside its gutter (500 specks
// on a 128-texel texture with a 3-texel gutter): packed by their outlines, which need no such
// floor, instead of refused (then maybe packed by outline again, with charts freed).
TEST(LayOutCharts, MoreTinyPartsThanTheTilingHasCellsForArePackedByTheirOutlines) {
  const testmesh::Mesh m = testmesh::with_specks(testmesh::sphere(16, 24), 500, 25, 2);
  ChartOptions options;
  options.non_disk = NonDisk::Atlas;
  options.texture_size = 128;
  options.gutter = 3;
  const ChartsResult r = parameterize_charts(m.V, m.F, options);
  ASSERT_FALSE(r.error) << message(r.error);
  expect_valid_layout(m.F, r);
  EXPECT_GE(r.charts.size(), 502u) << "the sphere cut, and a chart per speck";
  EXPECT_LT(r.layout.l2_stretch, 1.5) << "the sphere cut into charts, not mapped whole";
  EXPECT_TRUE(std::any_of(r.notes.begin(), r.notes.end(), [](const std::string& n) {
    return n.find("packed by their outlines") != std::string::npos || n.find("every chart packed by its outline") != std::string::npos;
  }));
}

// A chart that fills its box gets its 3D area; one with a closed hole gets its area over the share
// of its box its real faces cover (measured here from its map), so that its hole's texels are
// counted in its cell.
TEST(LayOutCharts, CellAreasAreTheChartsAreasOverTheShareOfTheBoxTheyFill) {
  const testmesh::Mesh grid = testmesh::grid(8), punched = testmesh::punched_grid(16, {{0.5, 0.5}}, 0.25);
  const std::vector<SolvedChart> charts = {solved_chart_of(grid), solved_chart_of(punched)};
  ASSERT_EQ(charts[0].mesh.closed_holes, 0);
  ASSERT_EQ(charts[1].mesh.closed_holes, 1);
  const std::vector<double> areas = cell_areas(charts);
  ASSERT_EQ(areas.size(), 2u);
  EXPECT_NEAR(areas[0], 1.0, 1e-9);  // the flat unit grid
  EXPECT_NEAR(charts[1].kept.area_3d, 1 - 0.25 * 0.25 * M_PI, 0.05);  // the grid less a disk of radius 0.25
  const double fill = real_uv_area(charts[1]) / charts[1].box.volume();
  EXPECT_LT(fill, 0.95);
  EXPECT_NEAR(areas[1], charts[1].kept.area_3d / fill, 1e-9 * areas[1]);
}

// lay_out on charts solved here: every face written in its chart, every chart inside [0,1]^2 by
// half the gutter (store() adds the rest), and the boxes of two charts a gutter apart, as they lie
// in different cells of a tiling of the square, each less half the gutter on every side.
TEST(LayOutCharts, EveryChartInItsCellHalfAGutterInside) {
  const testmesh::Mesh grid = testmesh::grid(6), cap = testmesh::hemisphere(6, 12);
  testmesh::Mesh m = testmesh::joined(grid, cap, 1, Eigen::RowVector3d(3, 0, 0));
  m = testmesh::joined(m, testmesh::grid(4), 0.5, Eigen::RowVector3d(6, 0, 0));
  const int a = int(grid.F.rows()), b = a + int(cap.F.rows());  // faces of the grid, then of the cap
  std::vector<std::vector<int>> parts(3);
  for (int f = 0; f < int(m.F.rows()); ++f) parts[f < a ? 0 : f < b ? 1 : 2].push_back(f);
  std::vector<SolvedChart> charts;
  for (const auto& faces : parts) charts.push_back(solved_chart_of(m, faces));
  ChartOptions options;
  options.texture_size = 256;
  options.gutter = 4;
  const double g = 4.0 / 256, inset = 0.5 * g / (1 - 2 * g);
  ChartsResult r;
  double outline_density = 0;
  ASSERT_FALSE(lay_out(charts, options, m.F.rows(), {}, r, outline_density));
  ASSERT_EQ(r.corner_uv.rows(), m.F.rows());
  std::vector<Eigen::AlignedBox2d> box(3);
  for (size_t c = 0; c < 3; ++c)
    for (const int f : parts[c]) {
      ASSERT_EQ(r.face_chart[size_t(f)], int(c)) << "face " << f;
      EXPECT_GT(signed_area(corner(r, f, 0), corner(r, f, 1), corner(r, f, 2)), 0) << "face " << f;
      for (int k = 0; k < 3; ++k) box[c].extend(corner(r, f, k));
    }
  for (size_t c = 0; c < 3; ++c) {
    EXPECT_GE(box[c].min().minCoeff(), inset * (1 - 1e-9)) << "chart " << c;
    EXPECT_LE(box[c].max().maxCoeff(), 1 - inset * (1 - 1e-9)) << "chart " << c;
    for (size_t d = c + 1; d < 3; ++d) {
      const Eigen::Vector2d apart = (box[d].min() - box[c].max()).cwiseMax(box[c].min() - box[d].max());
      EXPECT_GE(apart.maxCoeff(), 2 * inset * (1 - 1e-9)) << "charts " << c << " and " << d;
    }
  }
}
