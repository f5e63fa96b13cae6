// The pack stage alone (repack_atlas): an atlas packed again at another texture size and gutter
// keeps its charts, each moved by a similarity (a quarter turn, a scale, a shift), and is valid
// with the new gutter; input that holds no atlas is refused with a message.
#include <gtest/gtest.h>
#include <cmath>
#include <limits>
#include <map>
#include <vector>

#include "atlas/charts.h"
#include "atlas/repack.h"
#include "generated_meshes.h"
#include "layout_checks.h"

using namespace lowstretch;

namespace {

// Closed and open parts: charts of several shapes.
testmesh::Mesh parts() {
  testmesh::Mesh m = testmesh::torus(16, 8);
  m = testmesh::joined(m, testmesh::hemisphere(6, 12), 0.7, Eigen::RowVector3d(4, 0, 0));
  return testmesh::joined(m, testmesh::punched_grid(10, {{0.5, 0.5}}, 0.2), 1.5, Eigen::RowVector3d(8, 0, 0));
}

ChartOptions other_texture() {
  ChartOptions options;
  options.texture_size = 512;
  options.gutter = 4;  // a wider share of the texture than the default's 2 of 1024
  return options;
}

// Whether every corner of chart `c` of `after` is where a similarity (rotation by a multiple of a
// quarter turn, uniform scale, shift) puts it from `before`, to float rounding.
void expect_same_shape(const testmesh::Mesh& m, const ChartsResult& before, const ChartsResult& after, int c) {
  std::vector<std::pair<Eigen::Vector2d, Eigen::Vector2d>> corners;  // (before, after)
  for (Eigen::Index f = 0; f < m.F.rows(); ++f)
    if (after.face_chart[size_t(f)] == c)
      for (int k = 0; k < 3; ++k) corners.push_back({corner(before, f, k), corner(after, f, k)});
  ASSERT_FALSE(corners.empty());
  // The scale and turn from the corner farthest from the first.
  size_t far = 0;
  for (size_t i = 1; i < corners.size(); ++i)
    if ((corners[i].first - corners[0].first).norm() > (corners[far].first - corners[0].first).norm()) far = i;
  const Eigen::Vector2d from = corners[far].first - corners[0].first, to = corners[far].second - corners[0].second;
  ASSERT_GT(from.norm(), 0);
  const double scale = to.norm() / from.norm();
  const double turn = std::atan2(to.y(), to.x()) - std::atan2(from.y(), from.x());
  const double quarters = turn / (M_PI / 2);
  EXPECT_NEAR(quarters, std::round(quarters), 1e-3) << "chart " << c << " turned by " << turn;
  const Eigen::Rotation2Dd rotate(std::round(quarters) * M_PI / 2);
  for (const auto& p : corners) {
    const Eigen::Vector2d expected = corners[0].second + scale * (rotate * (p.first - corners[0].first));
    EXPECT_LT((p.second - expected).norm(), 1e-5) << "chart " << c;
  }
}

}  // namespace

TEST(Repack, EachChartKeepsItsShapeAndTheNewGutter) {
  const testmesh::Mesh m = parts();
  const ChartsResult before = parameterize_charts(m.V, m.F, ChartOptions());
  ASSERT_FALSE(before.error) << message(before.error);
  ASSERT_GT(before.charts.size(), 3u);
  const ChartOptions options = other_texture();
  const ChartsResult after = repack_atlas(m.V, m.F, before.corner_uv, options);
  ASSERT_FALSE(after.error) << message(after.error);
  expect_valid_layout(m.F, after, &m.V);
  // The same charts: faces together before are together after, and apart before, apart after.
  ASSERT_EQ(after.charts.size(), before.charts.size());
  std::map<int, int> chart_after;
  for (Eigen::Index f = 0; f < m.F.rows(); ++f) {
    const auto found = chart_after.emplace(before.face_chart[size_t(f)], after.face_chart[size_t(f)]).first;
    EXPECT_EQ(found->second, after.face_chart[size_t(f)]) << "face " << f;
  }
  EXPECT_EQ(chart_after.size(), before.charts.size());
  for (int c = 0; c < int(after.charts.size()); ++c) expect_same_shape(m, before, after, c);
  // One texel density for all, and the new gutter between charts and to the border.
  const std::vector<double> density = texel_densities(m.V, m.F, after);
  for (const double d : density) EXPECT_NEAR(d / density[0], 1.0, 1e-4);
  const double g = options.gutter / options.texture_size;
  EXPECT_GE(least_distance_between_charts(m.F, after), g * (1 - 1e-5));
  EXPECT_GE(after.corner_uv.minCoeff(), g * (1 - 1e-6));
  EXPECT_LE(after.corner_uv.maxCoeff(), 1 - g * (1 - 1e-6));
  // Packed again with the options it was made with, the atlas is as tight as the one packed.
  const ChartsResult again = repack_atlas(m.V, m.F, after.corner_uv, options);
  ASSERT_FALSE(again.error);
  EXPECT_NEAR(again.coverage, after.coverage, 0.02 * after.coverage);
}

// A face whose UV folds is cut out and mapped again: the result is valid whatever it is given.
TEST(Repack, AFoldedFaceIsMappedAgain) {
  const testmesh::Mesh m = parts();
  ChartsResult before = parameterize_charts(m.V, m.F, ChartOptions());
  ASSERT_FALSE(before.error);
  const Eigen::Vector2d a = corner(before, 5, 0);
  before.corner_uv.block(5, 0, 1, 2) = corner(before, 5, 1).transpose();  // face 5 folded onto a line
  before.corner_uv.block(5, 2, 1, 2) = a.transpose();
  ASSERT_LT(signed_area(corner(before, 5, 0), corner(before, 5, 1), corner(before, 5, 2)), 0);
  const ChartsResult after = repack_atlas(m.V, m.F, before.corner_uv, ChartOptions());
  ASSERT_FALSE(after.error) << message(after.error);
  expect_valid_layout(m.F, after, &m.V);
}

// No texture coordinates, NaN ones, or charts with 3D area and none in UV: refused, with what to do.
TEST(Repack, InputWithoutAnAtlasIsRefusedWithAMessage) {
  const testmesh::Mesh m = parts();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const Eigen::MatrixXd none = Eigen::MatrixXd::Constant(m.F.rows(), 6, nan), zero = Eigen::MatrixXd::Zero(m.F.rows(), 6);
  for (const Eigen::MatrixXd* uv : {&none, &zero}) {
    const ChartsResult r = repack_atlas(m.V, m.F, *uv, ChartOptions());
    EXPECT_EQ(r.error.code, ErrorCode::NoTextureCoordinates);
    EXPECT_EQ(r.error.count, m.F.rows());
    EXPECT_NE(message(r.error).find("parameterize the mesh first"), std::string::npos) << message(r.error);
  }
  EXPECT_EQ(repack_atlas(m.V, m.F, Eigen::MatrixXd(), ChartOptions()).error.code, ErrorCode::NoTextureCoordinates);
  ChartOptions bad;
  bad.gutter = 0;
  EXPECT_EQ(repack_atlas(m.V, m.F, zero, bad).error.code, ErrorCode::InvalidOption);
}

// A part of no 3D area has nothing to texture: it sits on a point, the rest is packed.
TEST(Repack, APartOfNoAreaSitsOnAPoint) {
  testmesh::Mesh m = parts();
  const Eigen::Index n = m.V.rows(), faces = m.F.rows();
  m.V.conservativeResize(n + 3, 3);
  m.V.bottomRows(3) << 20, 0, 0, 21, 0, 0, 22, 0, 0;  // on a line
  m.F.conservativeResize(faces + 1, 3);
  m.F.row(faces) << int(n), int(n + 1), int(n + 2);
  const ChartsResult before = parameterize_charts(m.V, m.F, ChartOptions());
  ASSERT_FALSE(before.error) << message(before.error);
  const ChartsResult after = repack_atlas(m.V, m.F, before.corner_uv, other_texture());
  ASSERT_FALSE(after.error) << message(after.error);
  EXPECT_EQ(signed_area(corner(after, faces, 0), corner(after, faces, 1), corner(after, faces, 2)), 0);
  expect_valid_layout(m.F, after, &m.V);
}

// Where the given layout, scaled into the new texture, keeps the new gutter and uses the texture
// at least as well as a packing, it is kept: the whole layout moves by one scale and shift.
TEST(Repack, ALayoutThatKeepsTheNewGutterIsKeptScaledWhereItUsesTheTextureBetter) {
  const testmesh::Mesh m = parts();
  const ChartsResult atlas = parameterize_charts(m.V, m.F, ChartOptions());
  ASSERT_FALSE(atlas.error) << message(atlas.error);
  const ChartsResult before = repack_atlas(m.V, m.F, atlas.corner_uv, ChartOptions());  // as the packer lays them out
  ASSERT_FALSE(before.error) << message(before.error);
  // The same share of the texture between charts, on half the texels a side: packed on them, the
  // charts cannot use it as well as the layout made on twice as many.
  ChartOptions twice;
  twice.texture_size = 512;
  twice.gutter = 1;
  const ChartsResult after = repack_atlas(m.V, m.F, before.corner_uv, twice);
  ASSERT_FALSE(after.error) << message(after.error);
  expect_valid_layout(m.F, after, &m.V);
  EXPECT_GE(least_distance_between_charts(m.F, after), twice.gutter / twice.texture_size * (1 - 1e-5));
  EXPECT_GE(texture_efficiency(after), texture_efficiency(before) * (1 - 1e-6));
  ASSERT_FALSE(after.notes.empty());
  EXPECT_NE(after.notes[0].find("kept where they are"), std::string::npos) << after.notes[0];
  // One scale and shift for every corner of every chart: from two far corners, then all.
  Eigen::Index far = 0;
  for (Eigen::Index f = 0; f < m.F.rows(); ++f)
    if ((corner(before, f, 0) - corner(before, 0, 0)).norm() > (corner(before, far, 0) - corner(before, 0, 0)).norm()) far = f;
  const double scale = (corner(after, far, 0) - corner(after, 0, 0)).norm() / (corner(before, far, 0) - corner(before, 0, 0)).norm();
  for (Eigen::Index f = 0; f < m.F.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector2d expected = corner(after, 0, 0) + scale * (corner(before, f, k) - corner(before, 0, 0));
      EXPECT_LT((corner(after, f, k) - expected).norm(), 1e-5) << "face " << f;
    }
  // A gutter the layout does not keep: packed again, with it.
  ChartOptions wider;
  wider.gutter = 8;
  const ChartsResult packed = repack_atlas(m.V, m.F, before.corner_uv, wider);
  ASSERT_FALSE(packed.error) << message(packed.error);
  EXPECT_NE(packed.notes[0].find("packed again"), std::string::npos) << packed.notes[0];
  EXPECT_GE(least_distance_between_charts(m.F, packed), wider.gutter / wider.texture_size * (1 - 1e-5));
}

// A chart stored mirrored (its faces clockwise in UV, as xatlas leaves some) is mirrored back and
// packed whole, as the same chart unmirrored is: not cut into pieces as if every face were flipped.
TEST(Repack, AMirroredChartIsMirroredBackNotCut) {
  const testmesh::Mesh m = parts();
  const ChartsResult before = parameterize_charts(m.V, m.F, ChartOptions());
  ASSERT_FALSE(before.error) << message(before.error);
  ChartsResult mirrored = before;
  int faces = 0;
  for (Eigen::Index f = 0; f < m.F.rows(); ++f)
    if (before.face_chart[size_t(f)] == 0) {
      ++faces;
      for (int k = 0; k < 3; ++k) mirrored.corner_uv(f, 2 * k) = 1 - before.corner_uv(f, 2 * k);  // u -> 1 - u
      ASSERT_LT(signed_area(corner(mirrored, f, 0), corner(mirrored, f, 1), corner(mirrored, f, 2)), 0) << "face " << f;
    }
  ASSERT_GT(faces, 1);
  const ChartOptions options = other_texture();
  const ChartsResult plain = repack_atlas(m.V, m.F, before.corner_uv, options);
  const ChartsResult after = repack_atlas(m.V, m.F, mirrored.corner_uv, options);
  ASSERT_FALSE(plain.error) << message(plain.error);
  ASSERT_FALSE(after.error) << message(after.error);
  expect_valid_layout(m.F, after, &m.V);
  EXPECT_EQ(after.charts.size(), before.charts.size());
  EXPECT_NEAR(after.layout.l2_stretch, plain.layout.l2_stretch, 1e-6 * plain.layout.l2_stretch);
  EXPECT_NEAR(texture_efficiency(after), texture_efficiency(plain), 0.02 * texture_efficiency(plain));
  ASSERT_GE(after.notes.size(), 2u);
  EXPECT_EQ(after.notes[1], "1 chart was mirrored in the texture coordinates (its faces clockwise): mirrored back");
}

// A chart given overlapping itself with no face flipped (a flat strip curled one and a quarter
// turns round in UV, as a peer's long chart can come) is charted again: valid, no pixel covered
// twice, its stretch near the strip's own (none), and a note says so.
TEST(Repack, AChartThatOverlapsItselfIsChartedAgain) {
  const int along = 60;
  testmesh::Mesh strip;
  strip.V.resize(2 * (along + 1), 3);
  Eigen::MatrixXd uv(strip.V.rows(), 2);
  for (int i = 0; i <= along; ++i)
    for (int j = 0; j < 2; ++j) {
      const double turn = 2.5 * M_PI * i / along, radius = 1.0 - 0.2 * j;  // inward with j: counter-clockwise
      strip.V.row(2 * i + j) << 2.5 * M_PI * 0.9 * i / along, 0.2 * j, 0;
      uv.row(2 * i + j) << 0.5 + 0.4 * radius * std::cos(turn), 0.5 + 0.4 * radius * std::sin(turn);
    }
  strip.F.resize(2 * along, 3);
  for (int i = 0; i < along; ++i) {
    strip.F.row(2 * i) << 2 * i, 2 * i + 2, 2 * i + 3;
    strip.F.row(2 * i + 1) << 2 * i, 2 * i + 3, 2 * i + 1;
  }
  ChartsResult given;
  given.corner_uv.resize(strip.F.rows(), 6);
  for (Eigen::Index f = 0; f < strip.F.rows(); ++f)
    for (int k = 0; k < 3; ++k) given.corner_uv.block(f, 2 * k, 1, 2) = uv.row(strip.F(f, k));
  for (Eigen::Index f = 0; f < strip.F.rows(); ++f)
    ASSERT_GT(signed_area(corner(given, f, 0), corner(given, f, 1), corner(given, f, 2)), 0) << "face " << f;
  given.charts.resize(1);
  ASSERT_GT(overlapping_pixels(given), 0);  // the curl's last quarter turn lies on its first
  const ChartsResult after = repack_atlas(strip.V, strip.F, given.corner_uv, ChartOptions());
  ASSERT_FALSE(after.error) << message(after.error);
  expect_valid_layout(strip.F, after, &strip.V);
  EXPECT_LT(after.layout.l2_stretch, 1.05);
  ASSERT_GE(after.notes.size(), 2u);
  EXPECT_EQ(after.notes[1], "1 chart overlapped itself in the texture coordinates: charted again");
}

// A chart whose texture coordinates all sit on one point (a peer's collapsed chart) has no shape to
// keep: charted again, the rest packed as given; refused only where no chart has UV area.
TEST(Repack, AChartWithNoUvAreaIsChartedAgain) {
  const testmesh::Mesh m = parts();
  ChartsResult before = parameterize_charts(m.V, m.F, ChartOptions());
  ASSERT_FALSE(before.error) << message(before.error);
  int faces = 0;
  for (Eigen::Index f = 0; f < m.F.rows(); ++f)
    if (before.face_chart[size_t(f)] == 1) {
      ++faces;
      for (int k = 0; k < 3; ++k) before.corner_uv.block(f, 2 * k, 1, 2) << 0.25, 0.75;
    }
  ASSERT_GT(faces, 1);
  const ChartsResult after = repack_atlas(m.V, m.F, before.corner_uv, ChartOptions());
  ASSERT_FALSE(after.error) << message(after.error);
  expect_valid_layout(m.F, after, &m.V);
  EXPECT_LT(after.layout.l2_stretch, ChartOptions().max_stretch);
  ASSERT_GE(after.notes.size(), 2u);
  EXPECT_EQ(after.notes[1], std::to_string(faces) + " faces of charts with no area in the texture coordinates: charted again");
}
