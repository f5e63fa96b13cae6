// The atlas as the user gets it (atlas/measure/atlas_result.h): the layout moved inside the
// gutter, rounded to float as MeshLab stores it, and measured on what is stored.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "atlas/charts.h"
#include "atlas/chart_map/solved_chart.h"
#include "atlas/measure/atlas_result.h"
#include "core/stretch.h"
#include "chart_fixtures.h"
#include "generated_meshes.h"
#include "layout_checks.h"

using namespace lowstretch;

namespace {

ChartsResult charts_of(const testmesh::Mesh& m) { return parameterize_charts(m.V, m.F, ChartOptions()); }

// The stretch of the stored corners, measured again here as a mesh of three vertices per face.
double l2_of_stored(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const Eigen::MatrixXd& stored) {
  Eigen::MatrixXd corner_V(3 * F.rows(), 3), corner_uv(3 * F.rows(), 2);
  Eigen::MatrixXi corner_F(F.rows(), 3);
  for (Eigen::Index f = 0; f < F.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      corner_V.row(3 * f + k) = V.row(F(f, k));
      corner_uv.row(3 * f + k) = stored.block(f, 2 * k, 1, 2);
      corner_F(f, k) = int(3 * f + k);
    }
  return l2_stretch(face_stretch(corner_V, corner_F, corner_uv));
}

// A unit square with two interior vertices 1e-9 apart at its centre (faces 1 and 3 hold both).
testmesh::Mesh square_with_close_pair(double apart) {
  testmesh::Mesh m;
  m.V.resize(6, 3);
  m.V << 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0.5, 0.5, 0, 0.5 + apart, 0.5, 0;
  m.F.resize(6, 3);
  m.F << 0, 1, 4, 1, 5, 4, 1, 2, 5, 2, 4, 5, 2, 3, 4, 3, 0, 4;
  return m;
}

// Every face's corners at its vertices' (x, y): the identity map, as a layout in [0,1]^2.
ChartsResult identity_layout(const testmesh::Mesh& m) {
  ChartsResult r;
  r.corner_uv.resize(m.F.rows(), 6);
  for (Eigen::Index f = 0; f < m.F.rows(); ++f)
    for (int k = 0; k < 3; ++k) r.corner_uv.block(f, 2 * k, 1, 2) = m.V.row(m.F(f, k)).head<2>();
  r.face_chart.assign(size_t(m.F.rows()), 0);
  r.charts.resize(1);
  return r;
}

std::vector<int> all_faces(const testmesh::Mesh& m) {
  std::vector<int> faces(size_t(m.F.rows()));
  for (size_t f = 0; f < faces.size(); ++f) faces[f] = int(f);
  return faces;
}

}  // namespace

TEST(AtlasResult, MetricsAreThoseOfTheCoordinatesAsStored) {
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

TEST(AtlasResult, TrianglesThatFloatRoundingCollapsesAreMadeChartsOfTheirOwn) {
  // A unit square with two interior vertices 1e-9 apart at its centre: the two triangles between
  // them are tiny but positive in double; every map keeps the flat square, and in float (both
  // vertices round to one point) they would have zero area. Even in disk-only mode the last step
  // (valid_as_stored.h) makes each a chart of its own, and a note says so.
  Eigen::MatrixXd V(6, 3);
  V << 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0.5, 0.5, 0, 0.5 + 1e-9, 0.5, 0;
  Eigen::MatrixXi F(6, 3);
  F << 0, 1, 4, 1, 5, 4, 1, 2, 5, 2, 4, 5, 2, 3, 4, 3, 0, 4;
  ChartOptions disk_only;
  disk_only.non_disk = NonDisk::Reject;
  const ChartsResult r = parameterize_charts(V, F, disk_only);
  ASSERT_FALSE(r.error) << message(r.error);
  const PassMetrics& kept = r.disk_passes.at(size_t(r.chosen_pass));
  EXPECT_EQ(kept.flipped + kept.degenerate, 0);  // in double
  EXPECT_TRUE(r.input_is_disk);  // its passes are the paper's passes over the whole disk
  expect_valid_layout(F, r);
  EXPECT_EQ(r.float_collapsed, 0);
  EXPECT_EQ(r.charts.size(), 3u);
  for (const int tiny : {1, 3})
    for (int f = 0; f < 6; ++f)
      if (f != tiny) EXPECT_NE(r.face_chart[size_t(f)], r.face_chart[size_t(tiny)]) << f << " " << tiny;
  // Apart by 1e-3, nothing collapses: the disk stays one chart, and a note fewer.
  const testmesh::Mesh apart = square_with_close_pair(1e-3);
  const ChartsResult control = parameterize_charts(apart.V, apart.F, disk_only);
  ASSERT_FALSE(control.error) << message(control.error);
  EXPECT_TRUE(control.input_is_disk);
  EXPECT_EQ(control.float_collapsed, 0);
  EXPECT_GT(r.notes.size(), control.notes.size());
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

TEST(AtlasResult, GutterIsCountedInTexelsOfTheStatedTexture) {
  const testmesh::Mesh m = testmesh::grid(8);
  ChartOptions options;
  options.texture_size = 64;
  options.gutter = 0.5;  // the least: half a texel of a 64-texel texture
  const ChartsResult r = parameterize_charts(m.V, m.F, options);
  ASSERT_FALSE(r.error) << message(r.error);
  EXPECT_NEAR(r.corner_uv.minCoeff() * 64, 0.5, 1e-12);
  EXPECT_NEAR(r.corner_uv.maxCoeff() * 64, 63.5, 1e-12);
}

// Two copies of one curved disk: they get cells of one shape, so the same map, and every pass over
// the whole mesh has the stretch of that pass of either copy.
TEST(AtlasResult, PassesOverTheWholeMeshOfTwoEqualDisksAreThoseOfOne) {
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
TEST(AtlasResult, LayoutStretchIsTheAreaWeightedMeanOfTheCharts) {
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

// store() on a layout made here: the identity map of a flat grid, moved inside the gutter (p (1 -
// 2g) + g, g = gutter / texture size) and rounded to float, each value as computed here; measured
// on those values (a flat identity map has stretch 1 everywhere).
TEST(AtlasResult, StoreMovesInsideTheGutterRoundsToFloatAndMeasuresTheStoredValues) {
  testmesh::Mesh m = testmesh::grid(7);
  m.V.col(0) = m.V.col(0).array().square() * 0.9 + 0.1 * m.V.col(0).array();  // uneven columns: values floats cannot hold
  ChartOptions options;
  options.texture_size = 100;
  options.gutter = 3;
  const double g = 0.03;
  ChartsResult r = identity_layout(m);
  const Eigen::MatrixXd before = r.corner_uv;
  store(m.V, m.F, int(m.V.rows()), {all_faces(m)}, options, r);
  for (Eigen::Index i = 0; i < before.rows(); ++i)
    for (Eigen::Index j = 0; j < before.cols(); ++j)
      ASSERT_EQ(r.corner_uv(i, j), double(float(before(i, j) * (1 - 2 * g) + g))) << i << " " << j;
  EXPECT_NEAR(r.corner_uv.minCoeff(), g, 1e-7);
  EXPECT_NEAR(r.corner_uv.maxCoeff(), 1 - g, 1e-7);
  EXPECT_EQ(r.layout.l2_stretch, l2_of_stored(m.V, m.F, r.corner_uv));
  EXPECT_NEAR(r.layout.l2_stretch, 1, 1e-6);
  EXPECT_NEAR(r.charts[0].l2_stretch, 1, 1e-6);
  EXPECT_EQ(r.layout.flipped + r.layout.degenerate, 0);
  EXPECT_NEAR(r.coverage, (1 - 2 * g) * (1 - 2 * g), 1e-6);
  EXPECT_EQ(r.vertex_stretch.size(), m.V.rows());
  EXPECT_EQ(r.face_stretch.size(), m.F.rows());
  EXPECT_EQ(r.subtexel_triangles, 0);
  EXPECT_EQ(r.float_collapsed, 0);
}

// Two vertices 1e-9 apart near UV 0.5, where floats are 6e-8 apart: as stored they are one point,
// so the two triangles between them collapse (counted, measured as degenerate, and a note more);
// 1e-3 apart they stay apart.
TEST(AtlasResult, StoreCountsTheTrianglesFloatRoundingCollapses) {
  for (const double apart : {1e-9, 1e-3}) {
    const testmesh::Mesh m = square_with_close_pair(apart);
    ChartsResult r = identity_layout(m);
    store(m.V, m.F, int(m.V.rows()), {all_faces(m)}, ChartOptions(), r);
    const bool collapses = apart < 1e-6;
    EXPECT_EQ(r.float_collapsed, collapses ? 2 : 0) << apart;
    EXPECT_EQ(r.layout.flipped + r.layout.degenerate, collapses ? 2 : 0) << apart;
    EXPECT_EQ(r.subtexel_triangles, collapses ? 2 : 0) << apart;
    EXPECT_EQ(r.notes.size(), collapses ? 1u : 0u) << apart;
    for (const int f : {1, 3}) EXPECT_EQ(std::isinf(r.face_stretch(f)), collapses) << apart << " face " << f;
    // The identity map elsewhere: the search's efficiency is the coverage, over the faces rounding
    // did not collapse (they become charts of their own as stored), however few they are.
    EXPECT_NEAR(r.l2_of_valid, 1, 1e-6) << apart;
    EXPECT_NEAR(texture_efficiency(r), r.coverage, 1e-6) << apart;
    EXPECT_GT(r.coverage, 0.99) << apart;
    // A fold that rounding does not explain leaves the layout's own infinite stretch.
    r.layout.flipped += 1;
    r.layout.l2_stretch = std::numeric_limits<double>::infinity();
    EXPECT_EQ(texture_efficiency(r), 0) << apart;
  }
}

TEST(AtlasResult, FailedResultCarriesOnlyTheError) {
  const ChartsResult r = failed_result(Error(ErrorCode::ChartsNotPacked, 7));
  EXPECT_EQ(r.error.code, ErrorCode::ChartsNotPacked);
  EXPECT_EQ(r.error.count, 7);
  EXPECT_EQ(r.corner_uv.size(), 0);
  EXPECT_TRUE(r.face_chart.empty());
  EXPECT_TRUE(r.charts.empty());
  EXPECT_TRUE(r.notes.empty());
  EXPECT_EQ(texture_efficiency(r), -1);
  EXPECT_EQ(largest_chart_stretch(r), 0);
}

TEST(AtlasResult, CopyMeasuresKeepsThePassAndItsTimings) {
  PassMetrics from, to;
  from.pass = 5;
  from.l2_stretch = 1.5, from.linf_stretch = 3, from.edge_distortion = 0.1, from.angle_distortion = 0.2;
  from.area_distortion = 0.3, from.flipped = 4, from.degenerate = 2, from.seconds = 9;
  to.pass = 2;
  to.seconds = 1.25;
  copy_measures(from, to);
  EXPECT_EQ(to.pass, 2);
  EXPECT_EQ(to.seconds, 1.25);
  EXPECT_EQ(to.l2_stretch, 1.5);
  EXPECT_EQ(to.linf_stretch, 3);
  EXPECT_EQ(to.edge_distortion, 0.1);
  EXPECT_EQ(to.angle_distortion, 0.2);
  EXPECT_EQ(to.area_distortion, 0.3);
  EXPECT_EQ(to.flipped, 4);
  EXPECT_EQ(to.degenerate, 2);
}

// atlas_of on two charts solved here: a valid layout, each chart's faces in its own chart, and
// every chart's seam length its mesh's (no cut) scaled by `unit`.
TEST(AtlasResult, AtlasOfSolvedChartsIsAValidLayoutOfThem) {
  const testmesh::Mesh m = testmesh::two_grids(5);
  std::vector<int> first, second;
  for (int f = 0; f < int(m.F.rows()); ++f) (f < int(m.F.rows()) / 2 ? first : second).push_back(f);
  std::vector<SolvedChart> charts = {solved_chart_of(m, first), solved_chart_of(m, second)};
  const ChartsResult r = atlas_of(charts, {}, m.V, m.F, 2.0, int(m.V.rows()), ChartOptions());
  ASSERT_FALSE(r.error) << message(r.error);
  expect_valid_layout(m.F, r);
  ASSERT_EQ(r.charts.size(), 2u);
  EXPECT_EQ(r.charts[0].faces, int(first.size()));
  EXPECT_EQ(r.charts[1].faces, int(second.size()));
  EXPECT_NE(r.face_chart[size_t(first[0])], r.face_chart[size_t(second[0])]);
  for (const int f : first) EXPECT_EQ(r.face_chart[size_t(f)], r.face_chart[size_t(first[0])]);
  for (const int f : second) EXPECT_EQ(r.face_chart[size_t(f)], r.face_chart[size_t(second[0])]);
  EXPECT_EQ(r.corner_uv, r.corner_uv.cast<float>().cast<double>());
  EXPECT_EQ(r.seam_length, 0.0);
  EXPECT_NEAR(r.layout.l2_stretch, l2_of_stored(m.V, m.F, r.corner_uv), 1e-12);
}
