// Non-disk meshes as an atlas (atlas/charts.h): every face gets texture
// coordinates inside [0,1]^2 by the gutter, no chart has a flipped or zero-area triangle, no two triangles overlap,
// and a disk gives exactly what parameterize gives.
#include <gtest/gtest.h>

#include <dirent.h>
#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "atlas/charts.h"
#include "core/half_edges.h"
#include "core/stretch.h"
#include "generated_meshes.h"
#include "layout_checks.h"
#include "tool/mesh_io.h"
#include "vcg_arrays/mesh_arrays.h"

using namespace lowstretch;

namespace {

ChartsResult charts_of(const testmesh::Mesh& m, NonDisk non_disk = NonDisk::Charts,
                       double max_stretch = ChartOptions().max_stretch) {
  ChartOptions options;
  options.non_disk = non_disk;
  options.max_stretch = max_stretch;
  return parameterize_charts(m.V, m.F, options);
}

bool has_note(const ChartsResult& r, const std::string& text) {
  return std::any_of(r.notes.begin(), r.notes.end(), [&](const std::string& n) { return n.find(text) != std::string::npos; });
}

// A bound no chart exceeds: one chart per component, cut and holed as need be.
const double kNoSplit = 1e5;

// A texture so fine that the gutter costs no measurable area: every chart at one texel density.
ChartsResult fine_charts_of(const testmesh::Mesh& m, double max_stretch = kNoSplit) {
  ChartOptions options;
  options.non_disk = NonDisk::Charts;
  options.max_stretch = max_stretch;
  options.texture_size = 65536;
  options.gutter = 0.5;
  return parameterize_charts(m.V, m.F, options);
}

testmesh::Mesh disk_with_two_holes() { return testmesh::punched_grid(20, {{0.3, 0.3}, {0.7, 0.6}}, 0.12); }

}  // namespace

// Every interior edge of the input: the corners of its two faces at each end either share one UV
// (the edge is inside a chart) or do not (the edge is a seam). The seams so found, by 3D length,
// must be the seam length the result reports, and they must be where the map was cut: a
// mesh that needs no cut has none.
double uv_discontinuity_length(const testmesh::Mesh& m, const ChartsResult& r, int& discontinuous_edges) {
  const Eigen::Index nf = m.F.rows();
  std::vector<std::array<long long, 4>> sides;  // (low vertex, high vertex, face, corner of low)
  for (Eigen::Index f = 0; f < nf; ++f)
    for (int k = 0; k < 3; ++k) {
      const int a = m.F(f, k), b = m.F(f, (k + 1) % 3);
      sides.push_back({std::min(a, b), std::max(a, b), f, k});
    }
  std::sort(sides.begin(), sides.end());
  double length = 0;
  discontinuous_edges = 0;
  auto uv_at = [&](long long f, int vertex) {
    for (int k = 0; k < 3; ++k)
      if (m.F(f, k) == vertex) return corner(r, f, k);
    return Eigen::Vector2d(Eigen::Vector2d::Constant(NAN));
  };
  for (size_t i = 0; i + 1 < sides.size(); ++i) {
    if (sides[i][0] != sides[i + 1][0] || sides[i][1] != sides[i + 1][1]) continue;
    const int a = int(sides[i][0]), b = int(sides[i][1]);
    const long long f = sides[i][2], g = sides[i + 1][2];
    const bool same = (uv_at(f, a) - uv_at(g, a)).norm() < 1e-12 && (uv_at(f, b) - uv_at(g, b)).norm() < 1e-12;
    if (!same) {
      length += (m.V.row(a) - m.V.row(b)).norm();
      ++discontinuous_edges;
    }
    ++i;
  }
  return length;
}

TEST(Charts, ReportedSeamsAreTheUvDiscontinuities) {
  const std::vector<std::pair<const char*, testmesh::Mesh>> cases = {
      {"sphere", testmesh::sphere(10, 16)},
      {"torus", testmesh::torus(16, 10)},
      {"genus 2", testmesh::double_torus()},
      {"punched disk", testmesh::punched_grid(12, {Eigen::RowVector2d(0.5, 0.5)}, 0.2)},
      {"two grids", testmesh::two_grids(6)}};
  for (const auto& c : cases) {
    SCOPED_TRACE(c.first);
    const ChartsResult r = charts_of(c.second);
    ASSERT_FALSE(r.error) << message(r.error);
    int discontinuous = 0;
    const double length = uv_discontinuity_length(c.second, r, discontinuous);
    EXPECT_NEAR(length, r.seam_length, 1e-9 * (1 + r.seam_length));
    // The seams cut inside each chart, and the edges between two charts.
    double summed = 0;
    for (const Chart& chart : r.charts) summed += chart.seam_length;
    const std::vector<int> twin = opposite_half_edges(c.second.F);
    for (size_t h = 0; h < twin.size(); ++h)
      if (twin[h] > int(h) && r.face_chart[h / 3] != r.face_chart[size_t(twin[h]) / 3])
        summed += (c.second.V.row(half_edge_tail(c.second.F, int(h))) - c.second.V.row(half_edge_head(c.second.F, int(h)))).norm();
    EXPECT_NEAR(summed, r.seam_length, 1e-9 * (1 + r.seam_length));
    const bool needs_a_cut = std::string(c.first) != "punched disk" && std::string(c.first) != "two grids";
    EXPECT_EQ(discontinuous > 0, needs_a_cut) << discontinuous << " discontinuous edges";
  }
}

TEST(Charts, DiskGivesParameterizesResult) {
  const testmesh::Mesh m = testmesh::grid(10, [](double x, double y) { return 0.3 * std::sin(3 * x) * y; });
  const Result disk = parameterize(m.V, m.F);
  const ChartsResult r = charts_of(m);
  ASSERT_FALSE(r.error);
  EXPECT_TRUE(r.input_is_disk);
  ASSERT_EQ(r.charts.size(), 1u);
  EXPECT_EQ(r.seam_length, 0.0);
  // The same map, moved inside the gutter (2 texels of a 1024 texture on every side) and rounded
  // to float as MeshLab stores it.
  const double g = 2.0 / 1024;
  for (Eigen::Index f = 0; f < m.F.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector2d moved = disk.uv.row(m.F(f, k)).transpose() * (1 - 2 * g) + Eigen::Vector2d::Constant(g);
      EXPECT_EQ(corner(r, f, k), moved.cast<float>().cast<double>());
    }
  // The square boundary reaches the gutter on every side, and no further.
  EXPECT_NEAR(r.corner_uv.minCoeff(), g, 1e-15);
  EXPECT_NEAR(r.corner_uv.maxCoeff(), 1 - g, 1e-15);
  EXPECT_NEAR(r.coverage, (1 - 2 * g) * (1 - 2 * g), 1e-9);
  const PassMetrics& kept = disk.passes[size_t(disk.chosen_pass)];
  EXPECT_EQ(r.layout.pass, kept.pass);
  EXPECT_NEAR(r.layout.l2_stretch, kept.l2_stretch, 1e-6 * kept.l2_stretch);
  EXPECT_EQ(r.subtexel_triangles, 0);
  EXPECT_EQ(r.float_collapsed, 0);
}

TEST(Charts, MetricsAreThoseOfTheCoordinatesAsStored) {
  const testmesh::Mesh m = testmesh::hemisphere(8, 16);
  const ChartsResult r = charts_of(m);
  ASSERT_FALSE(r.error) << message(r.error);
  EXPECT_EQ(r.corner_uv, r.corner_uv.cast<float>().cast<double>());  // what MeshLab's float holds
  Eigen::MatrixXd corner_V(3 * m.F.rows(), 3), corner_uv(3 * m.F.rows(), 2);
  Eigen::MatrixXi corner_F(m.F.rows(), 3);
  for (Eigen::Index f = 0; f < m.F.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      corner_V.row(3 * f + k) = m.V.row(m.F(f, k));
      corner_uv.row(3 * f + k) = r.corner_uv.block(f, 2 * k, 1, 2);
      corner_F(f, k) = int(3 * f + k);
    }
  EXPECT_NEAR(l2_stretch(face_stretch(corner_V, corner_F, corner_uv)), r.layout.l2_stretch, 1e-12);
}

TEST(Charts, TrianglesThatFloatRoundingCollapsesAreCountedAndNoted) {
  // A unit square with two interior vertices 1e-9 apart at its centre: the two triangles between
  // them are tiny but positive in double; every map keeps the flat square, and in float (both
  // vertices round to one point) they have zero area.
  Eigen::MatrixXd V(6, 3);
  V << 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0.5, 0.5, 0, 0.5 + 1e-9, 0.5, 0;
  Eigen::MatrixXi F(6, 3);
  F << 0, 1, 4, 1, 5, 4, 1, 2, 5, 2, 4, 5, 2, 3, 4, 3, 0, 4;
  ChartOptions disk_only;
  disk_only.non_disk = NonDisk::Reject;
  const ChartsResult r = parameterize_charts(V, F, disk_only);
  ASSERT_FALSE(r.error) << message(r.error);
  ASSERT_TRUE(r.input_is_disk);
  const PassMetrics& kept = r.disk_passes[size_t(r.chosen_pass)];
  EXPECT_EQ(kept.flipped + kept.degenerate, 0);  // in double
  EXPECT_EQ(r.float_collapsed, 2);
  EXPECT_EQ(r.layout.flipped + r.layout.degenerate, 2);  // as stored
  EXPECT_GE(r.subtexel_triangles, 1);
  EXPECT_TRUE(std::any_of(r.notes.begin(), r.notes.end(),
                          [](const std::string& n) { return n.find("rounded to float") != std::string::npos; }));
  // By default that disk gets charts instead: the tiny triangles apart, each in a cell of its own
  // that float can hold, and every triangle positive as stored.
  const ChartsResult atlas = parameterize_charts(V, F, ChartOptions());
  EXPECT_FALSE(atlas.input_is_disk);
  expect_valid_layout(F, atlas);
  EXPECT_EQ(atlas.float_collapsed, 0);
  for (const int tiny : {1, 3})
    for (int f = 0; f < 6; ++f)
      if (f != tiny) EXPECT_NE(atlas.face_chart[size_t(f)], atlas.face_chart[size_t(tiny)]) << f << " " << tiny;
}

TEST(Charts, GutterIsCountedInTexelsOfTheStatedTexture) {
  const testmesh::Mesh m = testmesh::grid(8);
  ChartOptions options;
  options.texture_size = 64;
  options.gutter = 0.5;  // the least: half a texel of a 64-texel texture
  const ChartsResult r = parameterize_charts(m.V, m.F, options);
  ASSERT_FALSE(r.error) << message(r.error);
  EXPECT_NEAR(r.corner_uv.minCoeff() * 64, 0.5, 1e-12);
  EXPECT_NEAR(r.corner_uv.maxCoeff() * 64, 63.5, 1e-12);
}

TEST(Charts, TextureSizeAndGutterOutOfRangeAreRefusedByName) {
  const testmesh::Mesh m = testmesh::grid(6);
  struct Case { int size; double gutter; const char* option; };
  for (const Case c : {Case{4, 2, "texture_size"}, Case{70000, 2, "texture_size"}, Case{1024, 0.25, "gutter"},
                       Case{1024, 129, "gutter"}, Case{1024, NAN, "gutter"}}) {
    ChartOptions options;
    options.texture_size = c.size;
    options.gutter = c.gutter;
    const ChartsResult r = parameterize_charts(m.V, m.F, options);
    EXPECT_EQ(r.error.code, ErrorCode::InvalidOption) << c.size << " " << c.gutter;
    EXPECT_EQ(r.error.option, c.option);
    EXPECT_EQ(r.corner_uv.size(), 0);
  }
}

TEST(Charts, ChartsIsTheDefaultAndRejectsMessageNamesTheOption) {
  EXPECT_EQ(ChartOptions().non_disk, NonDisk::Charts);
  const std::vector<std::pair<testmesh::Mesh, ErrorCode>> cases = {
      {testmesh::two_grids(3), ErrorCode::SeveralComponents},
      {testmesh::sphere(6, 8), ErrorCode::Closed},
      {disk_with_two_holes(), ErrorCode::SeveralBoundaryLoops},
      {testmesh::without_face(testmesh::torus(12, 8), 0), ErrorCode::NotGenusZero}};
  for (const auto& c : cases) {
    const ChartsResult r = charts_of(c.first, NonDisk::Reject);
    EXPECT_EQ(r.error.code, c.second);
    EXPECT_NE(message(r.error).find("as charts"), std::string::npos) << message(r.error);
    EXPECT_TRUE(charts_would_help(r.error.code)) << message(r.error);
  }
}

TEST(Charts, TriangleSoupIsRefusedNotCutIntoAChartPerFace) {
  const testmesh::Mesh m = testmesh::soup(testmesh::sphere(6, 8));
  for (const NonDisk mode : {NonDisk::Charts, NonDisk::Atlas}) {
    const ChartsResult r = charts_of(m, mode);
    EXPECT_EQ(r.error.code, ErrorCode::UnweldedVertices) << message(r.error);
    EXPECT_EQ(r.corner_uv.size(), 0);
  }
}

TEST(Charts, PunchedDiskIsOneChartWithItsHolesOpen) {
  const testmesh::Mesh m = disk_with_two_holes();
  const ChartsResult r = charts_of(m);
  expect_valid_layout(m.F, r);
  EXPECT_FALSE(r.input_is_disk);
  ASSERT_EQ(r.charts.size(), 1u);
  EXPECT_EQ(r.charts[0].closed_holes, 2);
  EXPECT_EQ(r.seam_length, 0.0);
  // One chart fills the square; the virtual faces were dropped, so the holes are not covered.
  EXPECT_LT(r.coverage, 0.98);
}

TEST(Charts, SphereIsCutAlongOneSeam) {
  const testmesh::Mesh m = testmesh::sphere(16, 24);
  const ChartsResult r = charts_of(m, NonDisk::Charts, kNoSplit);
  expect_valid_layout(m.F, r);
  ASSERT_EQ(r.charts.size(), 1u);
  // A path between two far-apart vertices of the unit sphere: about half a great circle.
  EXPECT_GT(r.seam_length, 2.5);
  EXPECT_LT(r.seam_length, 4.0);
}

TEST(Charts, OctahedronOpensToo) {
  const testmesh::Mesh m = testmesh::octahedron();  // every pair of vertices is one or two edges apart
  const ChartsResult r = charts_of(m);
  expect_valid_layout(m.F, r);
  EXPECT_GT(r.seam_length, 0.0);
}

TEST(Charts, TorusIsCutOpen) {
  const testmesh::Mesh m = testmesh::torus(32, 16);
  const ChartsResult r = charts_of(m, NonDisk::Charts, kNoSplit);
  expect_valid_layout(m.F, r);
  ASSERT_EQ(r.charts.size(), 1u);
  // Two loops, one around the tube (circumference 2 pi) at least.
  EXPECT_GT(r.seam_length, 6.0);
}

TEST(Charts, PuncturedTorusWithAHole) {
  testmesh::Mesh m = testmesh::without_face(testmesh::torus(24, 12), 0);
  m = testmesh::without_face(m, 300);
  const ChartsResult r = charts_of(m, NonDisk::Charts, kNoSplit);
  expect_valid_layout(m.F, r);
  ASSERT_EQ(r.charts.size(), 1u);
  EXPECT_EQ(r.charts[0].closed_holes, 1);
  EXPECT_GT(r.seam_length, 0.0);
}

TEST(Charts, GenusTwoIsCutOpen) {
  const testmesh::Mesh m = testmesh::double_torus();
  const long long euler = m.V.rows() - 3 * m.F.rows() / 2 + m.F.rows();
  ASSERT_EQ(euler, -2);                                                  // closed genus 2 ...
  ASSERT_EQ(parameterize(m.V, m.F).error.code, ErrorCode::Closed);      // ... manifold and oriented
  const ChartsResult r = charts_of(m, NonDisk::Charts, kNoSplit);
  expect_valid_layout(m.F, r);
  ASSERT_EQ(r.charts.size(), 1u);
  EXPECT_GT(r.seam_length, 0.0);
}

// One grid twice as wide as four others: areas 4, 1, 1, 1, 1 tile the square as one half and four
// eighths, every cell within twice its chart's shape, so every chart fills its cell.
TEST(Charts, DisjointDisksGetOneChartEachAtTheSameTexelDensity) {
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
TEST(Charts, ChartWithAClosedHoleHasTheTexelDensityOfTheOthers) {
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

// Two copies of one curved disk: they get cells of one shape, so the same map, and every pass over
// the whole mesh has the stretch of that pass of either copy.
TEST(Charts, PassesOverTheWholeMeshOfTwoEqualDisksAreThoseOfOne) {
  const testmesh::Mesh one = testmesh::hemisphere(8, 16);
  testmesh::Mesh two;
  two.V.resize(2 * one.V.rows(), 3);
  two.F.resize(2 * one.F.rows(), 3);
  two.V << one.V, one.V.rowwise() + Eigen::RowVector3d(10, 0, 0);
  two.F << one.F, (one.F.array() + int(one.V.rows())).matrix();
  const ChartsResult r = fine_charts_of(two);
  ASSERT_FALSE(r.error) << message(r.error);
  ASSERT_EQ(r.charts.size(), 2u);
  EXPECT_NEAR(r.charts[0].l2_stretch, r.charts[1].l2_stretch, 1e-6 * r.charts[0].l2_stretch);
  EXPECT_EQ(r.charts[0].passes, r.charts[1].passes);
  ASSERT_EQ(int(r.passes.size()), r.charts[0].passes);
  for (size_t k = 0; k < r.passes.size(); ++k) {
    EXPECT_EQ(r.passes[k].pass, int(k));
    EXPECT_EQ(r.passes[k].flipped, 0);
  }
  // The kept pass over the whole mesh is the layout (measured again after rounding to float).
  EXPECT_NEAR(r.passes[size_t(r.charts[0].chosen_pass)].l2_stretch, r.layout.l2_stretch, 1e-4 * r.layout.l2_stretch);
}

// The layout's L2 stretch two ways: measured on the layout, and from the charts' own (kept) L2
// stretch. A chart's own is normalized by its own density d = UV area / 3D area, the layout's by
// the whole's: L2^2 = (sum A_uv / sum A) * sum (A L2_c^2 / d) / sum A. (The second grid is more
// curved, so larger: its cell is more than twice off its shape and it fills only part of it, at
// a lower density.)
TEST(Charts, LayoutStretchIsTheAreaWeightedMeanOfTheCharts) {
  testmesh::Mesh m = testmesh::two_grids(6);
  m.V.col(2) = (m.V.col(0).array() * 3).sin() * 0.3;  // curved, so the charts differ
  m.V.bottomRows(m.V.rows() / 2).col(2) *= 2;
  const ChartsResult r = fine_charts_of(m);
  ASSERT_FALSE(r.error) << message(r.error);
  std::vector<double> area(r.charts.size(), 0.0), uv(r.charts.size(), 0.0);
  for (Eigen::Index f = 0; f < m.F.rows(); ++f) {
    const Eigen::Vector3d a = m.V.row(m.F(f, 0)), b = m.V.row(m.F(f, 1)), c = m.V.row(m.F(f, 2));
    area[size_t(r.face_chart[size_t(f)])] += 0.5 * (b - a).cross(c - a).norm();
    uv[size_t(r.face_chart[size_t(f)])] += signed_area(corner(r, f, 0), corner(r, f, 1), corner(r, f, 2));
  }
  double weighted = 0, total = 0, total_uv = 0;
  for (size_t c = 0; c < r.charts.size(); ++c) {
    weighted += area[c] * r.charts[c].l2_stretch * r.charts[c].l2_stretch / (uv[c] / area[c]);
    total += area[c];
    total_uv += uv[c];
  }
  EXPECT_NEAR(r.layout.l2_stretch, std::sqrt(total_uv / total * weighted / total), 1e-9 * r.layout.l2_stretch);
}

TEST(Charts, ManyComponents) {
  // Twenty small closed parts and a disk.
  testmesh::Mesh m = testmesh::grid(4);
  const testmesh::Mesh part = testmesh::octahedron();
  for (int i = 0; i < 20; ++i) m = testmesh::joined(m, part, 0.1 + 0.02 * i, Eigen::RowVector3d(3 * i, 0, 0));
  const ChartsResult r = charts_of(m);
  expect_valid_layout(m.F, r);
  EXPECT_EQ(r.charts.size(), 21u);
}

// Two triangles that share only a vertex.
testmesh::Mesh bowtie() {
  testmesh::Mesh m;
  m.V.resize(5, 3);
  m.V << 0, 0, 0, 1, 0, 0, 0, 1, 0, -1, 0, 0, 0, -1, 0;
  m.F.resize(2, 3);
  m.F << 0, 1, 2, 0, 3, 4;
  return m;
}

TEST(Charts, NonManifoldVerticesAreMappedPerFan) {
  const testmesh::Mesh m = bowtie();
  EXPECT_EQ(charts_of(m, NonDisk::Reject).error.code, ErrorCode::NonManifoldVertices);
  const ChartsResult r = charts_of(m);
  ASSERT_FALSE(r.error) << message(r.error);
  expect_valid_layout(m.F, r);
  EXPECT_EQ(r.charts.size(), 2u);
  EXPECT_TRUE(has_note(r, "1 non-manifold vertex ("));
  // The shared vertex's stretch, over both faces, from the faces' own (area-weighted RMS).
  ASSERT_EQ(r.vertex_stretch.size(), 5);
  const double shared = std::sqrt(0.5 * (r.face_stretch(0) * r.face_stretch(0) + r.face_stretch(1) * r.face_stretch(1)));
  EXPECT_NEAR(r.vertex_stretch(0), shared, 1e-12);
  EXPECT_NEAR(r.vertex_stretch(1), r.face_stretch(0), 1e-12);
}

// Holes that touch at a vertex, as a scan's dropouts do: one vertex of the grid is a corner of
// two removed squares (diagonally), so its faces form two fans.
TEST(Charts, HolesTouchingAtAVertexAreOneAtlas) {
  testmesh::Mesh m = testmesh::grid(8);
  std::vector<Eigen::RowVector3i> kept;
  for (Eigen::Index f = 0; f < m.F.rows(); ++f) {
    const Eigen::RowVector3d c = (m.V.row(m.F(f, 0)) + m.V.row(m.F(f, 1)) + m.V.row(m.F(f, 2))) / 3;
    const bool square_a = c.x() > 0.25 && c.x() < 0.375 && c.y() > 0.25 && c.y() < 0.375;
    const bool square_b = c.x() > 0.375 && c.x() < 0.5 && c.y() > 0.375 && c.y() < 0.5;
    if (!square_a && !square_b) kept.push_back(m.F.row(f));
  }
  m.F.resize(Eigen::Index(kept.size()), 3);
  for (size_t f = 0; f < kept.size(); ++f) m.F.row(Eigen::Index(f)) = kept[f];
  EXPECT_EQ(charts_of(m, NonDisk::Reject).error.code, ErrorCode::NonManifoldVertices);
  for (const NonDisk mode : {NonDisk::Charts, NonDisk::Atlas}) {
    const ChartsResult r = charts_of(m, mode);
    ASSERT_FALSE(r.error) << message(r.error);
    expect_valid_layout(m.F, r);
    EXPECT_TRUE(has_note(r, "1 non-manifold vertex ("));
  }
}

TEST(Charts, MisorientedAndNonManifoldEdgesAreCutOpenForTheCharts) {
  // A closed mesh with one face turned over.
  testmesh::Mesh turned = testmesh::octahedron();
  std::swap(turned.F(0, 1), turned.F(0, 2));
  // Three faces on one edge (a fin), and four.
  testmesh::Mesh fin = testmesh::two_grids(2);
  fin.F.conservativeResize(fin.F.rows() + 1, 3);
  fin.F.bottomRows(1) << 0, 4, 12;  // 0-4 is an interior diagonal
  testmesh::Mesh fins = fin;
  fins.F.conservativeResize(fins.F.rows() + 1, 3);
  fins.F.bottomRows(1) << 4, 0, 13;
  const std::vector<std::pair<testmesh::Mesh, ErrorCode>> cases = {
      {turned, ErrorCode::InconsistentOrientation}, {fin, ErrorCode::NonManifoldEdges}, {fins, ErrorCode::NonManifoldEdges}};
  for (const auto& c : cases) {
    EXPECT_EQ(charts_of(c.first, NonDisk::Reject).error.code, c.second);
    const testmesh::Mesh before = c.first;
    const ChartsResult r = charts_of(c.first);
    expect_valid_layout(c.first.F, r);
    EXPECT_TRUE(c.first.F == before.F && c.first.V == before.V) << "the input is not changed";
    EXPECT_EQ(r.vertex_stretch.rows(), c.first.V.rows());
  }
}

TEST(Charts, FacesOfZeroAreaPartsGetZeroAreaCoordinates) {
  testmesh::Mesh m = testmesh::grid(4);
  const Eigen::Index n = m.V.rows(), faces = m.F.rows();
  // Dust of zero area: a triangle on a line, away from the grid, and a face naming a vertex twice.
  m.V.conservativeResize(n + 3, 3);
  m.V.bottomRows(3) << 2, 2, 2, 3, 3, 3, 4, 4, 4;
  m.F.conservativeResize(faces + 2, 3);
  m.F.bottomRows(2) << int(n), int(n) + 1, int(n) + 2, 0, 0, 1;
  EXPECT_EQ(charts_of(m, NonDisk::Reject).error.code, ErrorCode::RepeatedVertexInFace);
  const ChartsResult r = charts_of(m);
  expect_valid_layout(m.F, r, &m.V);
  for (const Eigen::Index f : {faces, faces + 1})
    EXPECT_EQ(signed_area(corner(r, f, 0), corner(r, f, 1), corner(r, f, 2)), 0) << "face " << f;
  for (Eigen::Index f = 0; f < faces; ++f) EXPECT_GT(signed_area(corner(r, f, 0), corner(r, f, 1), corner(r, f, 2)), 0);
  EXPECT_NEAR(r.layout.l2_stretch, 1, 1e-6) << "a flat grid, and dust that adds no area";
}

TEST(Charts, ADiskKeepsItsSingleMapByDefaultWhileItIsValid) {
  const testmesh::Mesh disk = testmesh::hemisphere(8, 16);
  const ChartsResult single = charts_of(disk, NonDisk::Reject), by_default = charts_of(disk);
  ASSERT_FALSE(single.error);
  EXPECT_TRUE(single.input_is_disk && by_default.input_is_disk);
  EXPECT_EQ(single.corner_uv, by_default.corner_uv);
}

TEST(Charts, SharedNonDiskMeshes) {
  const std::string folder = LOWSTRETCH_SHARED_MESHES;
  std::vector<std::string> paths;
  for (const std::string& sub : {std::string(""), std::string("/bad")})
    if (DIR* dir = opendir((folder + sub).c_str())) {
      while (dirent* entry = readdir(dir)) {
        const std::string name = entry->d_name;
        for (const char* prefix : {"holes", "bad_closed_", "bad_components", "bad_genus1_", "bad_holes", "bad_quads", "bad_nonmanifold"})
          if (name.rfind(prefix, 0) == 0) paths.push_back(folder + sub + "/" + name);
      }
      closedir(dir);
    }
  if (paths.empty()) GTEST_SKIP() << "no non-disk meshes in " << folder;
  std::sort(paths.begin(), paths.end());
  for (const std::string& path : paths) {
    SCOPED_TRACE(path);
    ToolMesh mesh;
    std::string error;
    ASSERT_TRUE(read_mesh(path, mesh, error)) << error;
    testmesh::Mesh m;
    mesh_to_arrays(mesh, m.V, m.F);
    const ChartsResult r = charts_of(m);
    expect_valid_layout(m.F, r);
    EXPECT_FALSE(r.input_is_disk);
  }
}

// Scans carry zero-length edges. On the boundary, the two ends of one must stay apart in the
// texture as MeshLab stores it (float), or the triangle on it collapses: at an arc-length floor of
// 1e-6 of a mean boundary edge they were 1e-8 apart on this grid's top side, under a float's step
// there; an armadillo with 300 collapsed edges lost 6 triangles in its atlas that way.
TEST(Charts, ZeroLengthBoundaryEdgeKeepsItsTriangleInFloat) {
  testmesh::Mesh m = testmesh::grid(100, [](double x, double y) { return 0.3 * std::sin(2 * x + y); });
  const int top_middle = 100 * 101 + 50;
  m.V.row(top_middle) = m.V.row(top_middle + 1);
  for (BoundaryShape shape : {BoundaryShape::Square, BoundaryShape::Circle}) {
    ChartOptions options;
    options.disk.boundary = shape;
    const ChartsResult r = parameterize_charts(m.V, m.F, options);
    ASSERT_FALSE(r.error) << message(r.error);
    EXPECT_TRUE(r.input_is_disk);
    EXPECT_EQ(r.layout.flipped, 0) << to_string(shape);
    EXPECT_EQ(r.layout.degenerate, 0) << to_string(shape);  // measured on the UV rounded to float
  }
}

TEST(Charts, AScanWithEveryDefectAtOnceGetsAValidAtlas) {
  // A closed sphere given what reconstructions leave: a fin, a T-junction closed by a flat face,
  // a vertex duplicated under one face, a face naming a vertex twice, and dust (a tiny
  // tetrahedron and a flat triangle apart).
  testmesh::Mesh m = testmesh::sphere(10, 16);
  const auto add_vertex = [&m](const Eigen::RowVector3d& p) {
    m.V.conservativeResize(m.V.rows() + 1, 3);
    m.V.bottomRows(1) = p;
    return int(m.V.rows()) - 1;
  };
  const auto add_face = [&m](int a, int b, int c) {
    m.F.conservativeResize(m.F.rows() + 1, 3);
    m.F.bottomRows(1) << a, b, c;
  };
  const Eigen::Index sphere_faces = m.F.rows();
  // The fin: a third face on face 0's first edge.
  add_face(m.F(0, 1), m.F(0, 0), add_vertex(m.V.row(m.F(0, 2)) * 1.5));
  // The T-junction: face 40 (a, b, c) becomes (a, t, c), (t, b, c) and the flat (a, b, t).
  const int a = m.F(40, 0), b = m.F(40, 1), c = m.F(40, 2);
  const int t = add_vertex((m.V.row(a) + m.V.row(b)) / 2);
  m.F.row(40) << a, t, c;
  add_face(t, b, c);
  add_face(a, b, t);
  // A duplicate: face 80's first vertex copied, the face moved onto the copy.
  m.F(80, 0) = add_vertex(m.V.row(m.F(80, 0)));
  add_face(m.F(90, 0), m.F(90, 0), m.F(90, 1));
  // Dust.
  const int d = add_vertex(Eigen::RowVector3d(3, 3, 3));
  for (const Eigen::RowVector3d& p : {Eigen::RowVector3d(3.01, 3, 3), Eigen::RowVector3d(3, 3.01, 3), Eigen::RowVector3d(3, 3, 3.01)})
    add_vertex(p);
  add_face(d, d + 2, d + 1);
  add_face(d, d + 1, d + 3);
  add_face(d, d + 3, d + 2);
  add_face(d + 1, d + 2, d + 3);
  const int e = add_vertex(Eigen::RowVector3d(-3, 0, 0));
  add_vertex(Eigen::RowVector3d(-2, 0, 0));
  add_vertex(Eigen::RowVector3d(-1.5, 0, 0));
  add_face(e, e + 1, e + 2);

  EXPECT_EQ(charts_of(m, NonDisk::Reject).error.code, ErrorCode::RepeatedVertexInFace);
  const testmesh::Mesh before = m;
  const ChartsResult r = charts_of(m);
  expect_valid_layout(m.F, r, &m.V);
  EXPECT_TRUE(m.F == before.F && m.V == before.V) << "the input is not changed";
  EXPECT_EQ(r.vertex_stretch.rows(), m.V.rows());
  EXPECT_LE(r.charts.size(), 12u) << "the sphere's few charts and the dust's, not one chart per face";
  EXPECT_GT(m.F.rows(), sphere_faces);
}
