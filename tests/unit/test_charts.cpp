// The entry point, parameterize_charts (atlas/charts.h): a disk keeps parameterize's map or is cut
// into an atlas (NonDisk::Reject, Charts, Atlas), options are checked by name, every face is
// written into one chart, and every mesh that is not a disk (several parts, holes, closed, higher
// genus, non-manifold, misoriented, dust) gets a valid layout: coordinates inside [0,1]^2 by the
// gutter, no flipped or zero-area triangle, no two triangles overlapping.
#include <gtest/gtest.h>

#include <dirent.h>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "atlas/charts.h"
#include "core/half_edges.h"
#include "core/stretch.h"
#include "chart_fixtures.h"
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

// A bound no chart exceeds: one chart per component, cut and holed as need be.
const double kNoSplit = 1e5;

testmesh::Mesh disk_with_two_holes() { return testmesh::punched_grid(20, {{0.3, 0.3}, {0.7, 0.6}}, 0.12); }

// Closed parts of several shapes and sizes: charts solved on both cores at once.
testmesh::Mesh several_parts() {
  testmesh::Mesh m = testmesh::sphere_with_bump();
  const testmesh::Mesh parts[] = {testmesh::torus(24, 12), testmesh::sphere(10, 16), testmesh::double_torus()};
  for (int i = 0; i < 3; ++i) m = testmesh::joined(m, parts[i], 0.5 + i, Eigen::RowVector3d(10 * (i + 1), 0, 0));
  return m;
}

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

// Two triangles that share only a vertex.
testmesh::Mesh bowtie() {
  testmesh::Mesh m;
  m.V.resize(5, 3);
  m.V << 0, 0, 0, 1, 0, 0, 0, 1, 0, -1, 0, 0, 0, -1, 0;
  m.F.resize(2, 3);
  m.F << 0, 1, 2, 0, 3, 4;
  return m;
}

}  // namespace

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

TEST(Charts, ADiskKeepsItsSingleMapByDefaultWhileItIsValid) {
  const testmesh::Mesh disk = testmesh::hemisphere(8, 16);
  const ChartsResult single = charts_of(disk, NonDisk::Reject), by_default = charts_of(disk);
  ASSERT_FALSE(single.error);
  EXPECT_TRUE(single.input_is_disk && by_default.input_is_disk);
  EXPECT_EQ(single.corner_uv, by_default.corner_uv);
}

TEST(Charts, DiskThatMeetsTheBoundIsTheDiskResult) {
  const testmesh::Mesh m = testmesh::grid(12, [](double x, double y) { return 0.1 * std::sin(2 * x) * y; });
  ChartOptions disk;
  const ChartsResult one = parameterize_charts(m.V, m.F, disk);
  ASSERT_FALSE(one.error) << message(one.error);
  ASSERT_LE(one.layout.l2_stretch, ChartOptions().max_stretch);
  const ChartsResult atlas = bounded_atlas(m);
  ASSERT_FALSE(atlas.error) << message(atlas.error);
  EXPECT_TRUE(atlas.input_is_disk);
  EXPECT_EQ(atlas.charts.size(), 1u);
  EXPECT_EQ(atlas.corner_uv, one.corner_uv);
}

TEST(Charts, DiskAboveTheBoundIsCutAndStretchesLess) {
  const testmesh::Mesh m = testmesh::without_face(testmesh::sphere_with_bump(), 0);  // a disk with a long arm
  const ChartsResult one = parameterize_charts(m.V, m.F, ChartOptions());
  ASSERT_FALSE(one.error) << message(one.error);
  ASSERT_GT(one.layout.l2_stretch, ChartOptions().max_stretch);
  const ChartsResult atlas = bounded_atlas(m);
  expect_valid_layout(m.F, atlas);
  EXPECT_FALSE(atlas.input_is_disk);
  EXPECT_GT(atlas.charts.size(), 1u);
  EXPECT_LT(atlas.layout.l2_stretch, one.layout.l2_stretch);
  EXPECT_GT(atlas.seam_length, 0.0);
}

// A tall cap cut in parts stretches more than as one square chart: it stays the disk's map.
TEST(Charts, DiskWhoseCutsDoNotPayStaysOneChart) {
  const testmesh::Mesh m = testmesh::tall_cap(16, 32);
  const ChartsResult one = parameterize_charts(m.V, m.F, ChartOptions());
  ASSERT_FALSE(one.error) << message(one.error);
  ASSERT_GT(one.layout.l2_stretch, ChartOptions().max_stretch);
  const ChartsResult atlas = bounded_atlas(m);
  ASSERT_FALSE(atlas.error) << message(atlas.error);
  EXPECT_TRUE(atlas.input_is_disk);
  EXPECT_EQ(atlas.corner_uv, one.corner_uv);
  EXPECT_EQ(atlas.charts.size(), 1u);
  EXPECT_GT(atlas.notes.size(), one.notes.size()) << "the atlas tells why it kept the disk's map";
}

TEST(Charts, ChartsIsTheDefaultAndWhatItFixesIsRejectedWithItsCode) {
  EXPECT_EQ(ChartOptions().non_disk, NonDisk::Charts);
  const std::vector<std::pair<testmesh::Mesh, ErrorCode>> cases = {
      {testmesh::two_grids(3), ErrorCode::SeveralComponents},
      {testmesh::sphere(6, 8), ErrorCode::Closed},
      {disk_with_two_holes(), ErrorCode::SeveralBoundaryLoops},
      {testmesh::without_face(testmesh::torus(12, 8), 0), ErrorCode::NotGenusZero}};
  for (const auto& c : cases) {
    const ChartsResult r = charts_of(c.first, NonDisk::Reject);
    EXPECT_EQ(r.error.code, c.second);
    EXPECT_FALSE(message(r.error).empty());
    EXPECT_EQ(r.corner_uv.size(), 0);
    EXPECT_FALSE(charts_of(c.first).error) << message(r.error) << ": charts fix it";
    EXPECT_TRUE(charts_would_help(r.error.code)) << message(r.error);
  }
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

TEST(Charts, BoundAndChartLimitOutOfRangeAreRefusedByName) {
  const testmesh::Mesh m = testmesh::grid(4);
  const ChartsResult low = bounded_atlas(m, 0.9);
  EXPECT_EQ(low.error.code, ErrorCode::InvalidOption);
  EXPECT_EQ(low.error.option, "max_stretch") << message(low.error);
  const ChartsResult none = bounded_atlas(m, 1.2, 0);
  EXPECT_EQ(none.error.code, ErrorCode::InvalidOption);
  EXPECT_EQ(none.error.option, "max_charts") << message(none.error);
}

TEST(Charts, CutsAheadOutOfRangeAreRefusedByName) {
  ChartOptions options;
  options.non_disk = NonDisk::Atlas;
  options.most_cuts_ahead = -1;
  const testmesh::Mesh m = testmesh::grid(4);
  const ChartsResult r = parameterize_charts(m.V, m.F, options);
  EXPECT_EQ(r.error.code, ErrorCode::InvalidOption);
  EXPECT_EQ(r.error.option, "most_cuts_ahead") << message(r.error);
}

TEST(Charts, TriangleSoupIsRefusedNotCutIntoAChartPerFace) {
  const testmesh::Mesh m = testmesh::soup(testmesh::sphere(6, 8));
  for (const NonDisk mode : {NonDisk::Charts, NonDisk::Atlas}) {
    const ChartsResult r = charts_of(m, mode);
    EXPECT_EQ(r.error.code, ErrorCode::UnweldedVertices) << message(r.error);
    EXPECT_EQ(r.corner_uv.size(), 0);
  }
}

TEST(Charts, SameInputGivesTheSameAtlasByteForByte) {
  const testmesh::Mesh m = several_parts();
  const ChartsResult a = bounded_atlas(m), b = bounded_atlas(m);
  ASSERT_FALSE(a.error) << message(a.error);
  ASSERT_GT(a.charts.size(), 2u);  // worked on several charts, on both cores
  ASSERT_EQ(a.corner_uv.size(), b.corner_uv.size());
  EXPECT_EQ(std::memcmp(a.corner_uv.data(), b.corner_uv.data(), sizeof(double) * size_t(a.corner_uv.size())), 0);
  EXPECT_EQ(a.face_chart, b.face_chart);
}

TEST(Charts, FewerSeamsRefinesEveryChartAndGivesTheSameAtlasEveryRun) {
  // Refining is timed for a disk, counted in steps for an atlas's charts: the time a step takes
  // must not change the atlas.
  const testmesh::Mesh m = testmesh::torus(32, 16);
  ChartOptions options;
  options.non_disk = NonDisk::Atlas;
  options.fewer_seams = true;
  const ChartsResult a = parameterize_charts(m.V, m.F, options), b = parameterize_charts(m.V, m.F, options);
  ASSERT_FALSE(a.error) << message(a.error);
  expect_valid_layout(m.F, a, &m.V);
  ASSERT_EQ(a.corner_uv.size(), b.corner_uv.size());
  EXPECT_EQ(std::memcmp(a.corner_uv.data(), b.corner_uv.data(), sizeof(double) * size_t(a.corner_uv.size())), 0);
  EXPECT_EQ(a.face_chart, b.face_chart);
  const bool refined = std::any_of(a.notes.begin(), a.notes.end(), [](const std::string& note) {
    return note.find(": refined: L2 stretch lowered") != std::string::npos;
  });
  EXPECT_TRUE(refined) << "one note for all the charts refined";
}

TEST(Charts, ChartsCoverEveryFaceExactlyOnce) {
  const testmesh::Mesh m = testmesh::sphere_with_bump();
  const ChartsResult r = bounded_atlas(m);
  ASSERT_FALSE(r.error) << message(r.error);
  std::vector<int> faces(r.charts.size(), 0);
  for (int c : r.face_chart) {
    ASSERT_GE(c, 0);
    ASSERT_LT(c, int(r.charts.size()));
    ++faces[size_t(c)];
  }
  int total = 0;
  for (size_t c = 0; c < r.charts.size(); ++c) {
    EXPECT_EQ(faces[c], r.charts[c].faces) << "chart " << c;
    total += r.charts[c].faces;
  }
  EXPECT_EQ(total, int(m.F.rows()));
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

TEST(Charts, ManyComponents) {
  // Twenty small closed parts and a disk.
  testmesh::Mesh m = testmesh::grid(4);
  const testmesh::Mesh part = testmesh::octahedron();
  for (int i = 0; i < 20; ++i) m = testmesh::joined(m, part, 0.1 + 0.02 * i, Eigen::RowVector3d(3 * i, 0, 0));
  const ChartsResult r = charts_of(m);
  expect_valid_layout(m.F, r);
  EXPECT_EQ(r.charts.size(), 21u);
}

TEST(Charts, NonManifoldVerticesAreMappedPerFan) {
  const testmesh::Mesh m = bowtie();
  EXPECT_EQ(charts_of(m, NonDisk::Reject).error.code, ErrorCode::NonManifoldVertices);
  const ChartsResult r = charts_of(m);
  ASSERT_FALSE(r.error) << message(r.error);
  expect_valid_layout(m.F, r);
  EXPECT_EQ(r.charts.size(), 2u);
  EXPECT_NE(r.face_chart[0], r.face_chart[1]) << "one chart per fan of the shared vertex";
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
    // The vertex where the holes touch, split per fan: its corners take two places in the texture.
    std::vector<Eigen::Vector2d> places;
    for (Eigen::Index f = 0; f < m.F.rows(); ++f)
      for (int k = 0; k < 3; ++k)
        if ((m.V.row(m.F(f, k)).head<2>() - Eigen::RowVector2d(0.375, 0.375)).norm() < 1e-12) {
          const Eigen::Vector2d p = corner(r, f, k);
          if (std::none_of(places.begin(), places.end(), [&](const Eigen::Vector2d& q) { return (p - q).norm() < 1e-9; }))
            places.push_back(p);
        }
    EXPECT_EQ(places.size(), 2u);
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

// A model made of faces (a CAD part) is cut along its sharp edges: every side of a cube is one
// chart (L2 1.08, from the cells' shapes). Cut by stretch alone, the cube stays one chart.
TEST(Charts, ModelMadeOfFacesIsCutAlongItsSharpEdges) {
  const int n = 8, side_faces = 2 * n * n;
  const testmesh::Mesh m = testmesh::cube(n);
  ChartOptions options;
  options.non_disk = NonDisk::Atlas;
  options.min_efficiency = 1;  // no charts merged
  const ChartsResult r = parameterize_charts(m.V, m.F, options);
  expect_valid_layout(m.F, r);
  ASSERT_EQ(r.charts.size(), 6u);
  for (Eigen::Index f = 0; f < m.F.rows(); ++f)
    EXPECT_EQ(r.face_chart[size_t(f)], r.face_chart[size_t(f - f % side_faces)]) << "face " << f;
  for (int side = 1; side < 6; ++side) EXPECT_NE(r.face_chart[size_t(side * side_faces)], r.face_chart[0]) << "side " << side;
  EXPECT_LT(r.layout.l2_stretch, 1.1);  // every side flat: only its cell's shape, not a square, stretches it
  EXPECT_NEAR(r.seam_length, 12.0, 1e-9) << "the seams are the unit cube's twelve edges";
}

// By default its sides are merged across some edges: whole sides per chart, each unfolded flat, so
// fewer seams at little cost in texture.
TEST(Charts, ModelMadeOfFacesMergesSidesForShorterSeams) {
  const int n = 8, side_faces = 2 * n * n;
  const testmesh::Mesh m = testmesh::cube(n);
  ChartOptions options;
  options.non_disk = NonDisk::Atlas;
  const ChartsResult merged = parameterize_charts(m.V, m.F, options);
  options.min_efficiency = 1;
  const ChartsResult sides = parameterize_charts(m.V, m.F, options);
  expect_valid_layout(m.F, merged, &m.V);
  EXPECT_LT(merged.charts.size(), 6u);
  EXPECT_LT(merged.seam_length, 12.0 - 1);  // at least one edge of the cube less
  for (Eigen::Index f = 0; f < m.F.rows(); ++f)
    EXPECT_EQ(merged.face_chart[size_t(f)], merged.face_chart[size_t(f - f % side_faces)]) << "face " << f;
  EXPECT_LT(merged.layout.l2_stretch, 1.1);
  EXPECT_GE(texture_efficiency(merged), 0.9 * texture_efficiency(sides));
}

// A bar of a cube is tried cut two ways (along its sides, and along them to a tighter bound): the
// progress that MeshLab's bar shows goes on from where it was rather than starting again.
TEST(Charts, ProgressNeverGoesBack) {
  testmesh::Mesh m = testmesh::cube(8);
  m.V.col(0) *= 3;  // a bar: the first atlas cuts it in more rounds than it has sides
  ChartOptions options;
  options.non_disk = NonDisk::Atlas;
  double last = -1;
  int reports = 0, backwards = 0;
  options.disk.progress = [&](double fraction, const char*) {
    backwards += fraction < last;
    last = fraction;
    ++reports;
    return true;
  };
  const ChartsResult r = parameterize_charts(m.V, m.F, options);
  ASSERT_FALSE(r.error) << message(r.error);
  EXPECT_GE(reports, 8);  // each atlas reports its rounds of cuts (without the clamp, a step back)
  EXPECT_EQ(backwards, 0);
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

// stage_seconds splits seconds_total: an atlas's stages in the order they ran, between the input's
// and the last step's, none negative, adding up to the total.
TEST(Charts, StageSecondsAddUpToTheTotal) {
  for (const testmesh::Mesh& m : {testmesh::torus(8, 16), testmesh::hemisphere(6, 12)}) {
    const ChartsResult r = parameterize_charts(m.V, m.F, ChartOptions());
    ASSERT_FALSE(r.error);
    ASSERT_GE(r.stage_seconds.size(), 2u);
    EXPECT_EQ(r.stage_seconds.front().stage, "input and whole map");
    EXPECT_EQ(r.stage_seconds.back().stage, "valid as stored");
    double sum = 0;
    for (const StageSeconds& s : r.stage_seconds) {
      EXPECT_GE(s.seconds, 0) << s.stage;
      sum += s.seconds;
    }
    EXPECT_NEAR(sum, r.seconds_total, 1e-9 * r.seconds_total + 1e-12);
    const bool atlas = r.charts.size() > 1;
    EXPECT_EQ(r.stage_seconds.size(), atlas ? 7u : 2u) << r.charts.size() << " charts";
  }
}
