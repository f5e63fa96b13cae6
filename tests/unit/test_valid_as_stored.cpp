// The last step's guarantee (atlas/measure/valid_as_stored.h): whatever layout reaches it, every
// face with 3D area leaves with a UV triangle of positive area as stored, and nothing overlaps.
#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <map>
#include <set>
#include <vector>

#include "atlas/bound/cut_invalid_charts.h"
#include "atlas/charts.h"
#include "atlas/measure/least_gutter.h"
#include "atlas/measure/valid_as_stored.h"
#include "generated_meshes.h"
#include "layout_checks.h"

using namespace lowstretch;

namespace {

// The disk fuzz_parameterize found folded at its 337th run: 11 vertices near 1e-32 (two on one
// point), 15 faces.
testmesh::Mesh fuzzed_disk() {
  testmesh::Mesh m;
  m.V.resize(11, 3);
  m.V << 1.8979019725174283e-31, 0, 5.6234132519034912e-32,  //
      3.9763536438352534e-32, 0, 3.9763536438352539e-32,     //
      1.2287608515898403e-32, 3.7817370440634958e-32, 3.9763536438352539e-32,
      -3.216937673507466e-32, 2.3372420297457995e-32, 3.9763536438352539e-32,
      -3.2169376735074677e-32, -2.3372420297457986e-32, 3.9763536438352539e-32,
      0, -3.7817370440634958e-32, 3.9763536438352539e-32,  //
      5.6234132519034912e-32, 0, 3.4433475196132094e-48,   //
      -4.5494368871832113e-32, 3.3053593770149312e-32, 3.4433475196132094e-48,
      -4.5494368871832113e-32, 3.3053593770149312e-32, 3.4433475196132094e-48,
      -4.5494368871832124e-32, -3.3053593770149296e-32, 3.4433475196132094e-48,
      1.7377302612314649e-32, -5.3481838170433359e-32, 3.4433475196132094e-48;
  m.F.resize(15, 3);
  m.F << 0, 1, 2, 0, 2, 3, 0, 3, 4, 0, 4, 5, 0, 5, 1, 1, 6, 7, 1, 7, 2, 2, 7, 8, 2, 8, 3, 3, 8, 9, 3, 9, 4, 4, 9, 10, 4,
      10, 5, 5, 10, 6, 5, 6, 1;
  return m;
}

// Face f's UV triangle collapsed onto its first corner (zero area as stored).
void collapse_onto_first_corner(ChartsResult& r, Eigen::Index f) {
  for (int k = 1; k < 3; ++k) r.corner_uv.block(f, 2 * k, 1, 2) = r.corner_uv.block(f, 0, 1, 2);
}

// The mesh moved into [0,1]^3 by one scale, as the atlas measures it.
Eigen::MatrixXd in_unit_box(const Eigen::MatrixXd& V) {
  const Eigen::RowVector3d low = V.colwise().minCoeff();
  return (V.rowwise() - low) / (V.colwise().maxCoeff() - low).maxCoeff();
}

// The faces invalid in float or with 6 decimals, as valid_as_stored guarantees.
std::vector<int> invalid_as_written(const Eigen::MatrixXd& unit_V, const Eigen::MatrixXi& F, const Eigen::MatrixXd& corner_uv) {
  return invalid_faces(unit_V, F, corner_uv, kTuning.least_uv_area, kTuning.written_uv_rounding);
}

std::map<int, std::vector<int>> faces_by_chart(const ChartsResult& r) {
  std::map<int, std::vector<int>> faces;
  for (size_t f = 0; f < r.face_chart.size(); ++f) faces[r.face_chart[f]].push_back(int(f));
  return faces;
}

}  // namespace

TEST(ValidAsStored, TheFuzzedDiskFoldedByHarmonicWeightsComesBackValid) {
  const testmesh::Mesh m = fuzzed_disk();
  ChartOptions options;
  options.disk.weights = InitialWeights::Harmonic;
  options.disk.exponent = 0.3;
  options.disk.max_passes = 2;
  options.texture_size = 256;
  const Result paper = parameterize(m.V, m.F, options.disk);
  ASSERT_FALSE(paper.error);
  EXPECT_GT(paper.passes.at(size_t(paper.chosen_pass)).flipped, 0) << "negative weights fold the paper's map";
  for (const NonDisk mode : {NonDisk::Charts, NonDisk::Atlas}) {
    options.non_disk = mode;
    const ChartsResult r = parameterize_charts(m.V, m.F, options);
    ASSERT_FALSE(r.error) << r.error.detail;
    EXPECT_EQ(r.layout.flipped, 0);
    EXPECT_TRUE(invalid_as_written(in_unit_box(m.V), m.F, r.corner_uv).empty());
    expect_valid_layout(m.F, r, &m.V);
  }
}

TEST(ValidAsStored, EveryWeightBoundaryAndModeGivesAValidAtlas) {
  const std::vector<testmesh::Mesh> meshes = {fuzzed_disk(), testmesh::hemisphere(6, 12), testmesh::torus(8, 16),
                                              testmesh::tall_cap(8, 16)};
  for (const testmesh::Mesh& m : meshes)
    for (const InitialWeights weights : {InitialWeights::Floater, InitialWeights::MeanValue, InitialWeights::Harmonic})
      for (const BoundaryShape boundary : {BoundaryShape::Square, BoundaryShape::Circle, BoundaryShape::Natural})
        for (const NonDisk mode : {NonDisk::Charts, NonDisk::Atlas}) {
          ChartOptions options;
          options.disk.weights = weights;
          options.disk.boundary = boundary;
          options.disk.exponent = 0.3;
          options.non_disk = mode;
          const ChartsResult r = parameterize_charts(m.V, m.F, options);
          ASSERT_FALSE(r.error) << r.error.detail;
          SCOPED_TRACE(testing::Message() << m.F.rows() << " faces, weights " << int(weights) << ", boundary "
                                          << int(boundary) << ", mode " << int(mode));
          EXPECT_TRUE(invalid_as_written(in_unit_box(m.V), m.F, r.corner_uv).empty());
          expect_valid_layout(m.F, r, &m.V);
        }
}

// A valid atlas spoiled by hand: one chart mirrored (every triangle flipped) and one face of
// another collapsed onto a point. The mirrored chart comes back as one chart mapped again, the
// collapsed face as a chart of its own, every other chart with the faces it had.
TEST(ValidAsStored, AFoldedChartIsMappedAgainAndACollapsedFaceGoesAlone) {
  const testmesh::Mesh m = testmesh::sphere(12, 24);
  ChartOptions options;
  options.max_stretch = 1.1;  // several charts (at the default bound the sphere is one)
  ChartsResult r = parameterize_charts(m.V, m.F, options);
  ASSERT_FALSE(r.error);
  const std::map<int, std::vector<int>> before = faces_by_chart(r);
  ASSERT_GE(before.size(), 2u);
  const std::vector<int>& mirrored = before.begin()->second;
  const int collapsed = std::next(before.begin())->second.front();
  double low = 1, high = 0;
  for (const int f : mirrored)
    for (int k = 0; k < 3; ++k) {
      low = std::min(low, r.corner_uv(f, 2 * k));
      high = std::max(high, r.corner_uv(f, 2 * k));
    }
  for (const int f : mirrored)
    for (int k = 0; k < 3; ++k) r.corner_uv(f, 2 * k) = low + high - r.corner_uv(f, 2 * k);
  collapse_onto_first_corner(r, collapsed);
  const Eigen::MatrixXd unit_V = in_unit_box(m.V);
  ASSERT_EQ(invalid_faces(unit_V, m.F, r.corner_uv).size(), mirrored.size() + 1);

  const ChartsResult fixed = valid_as_stored(unit_V, m.F, 1, int(m.V.rows()), options, r);
  ASSERT_FALSE(fixed.error);
  EXPECT_TRUE(invalid_as_written(unit_V, m.F, fixed.corner_uv).empty());
  expect_valid_layout(m.F, fixed, &m.V);
  // Faces grouped as before, but for the collapsed face, now alone.
  std::set<std::vector<int>> groups_before, groups_after;
  for (const auto& chart : before) {
    std::vector<int> faces = chart.second;
    faces.erase(std::remove(faces.begin(), faces.end(), collapsed), faces.end());
    groups_before.insert(faces);
  }
  groups_before.insert({collapsed});
  for (const auto& chart : faces_by_chart(fixed)) groups_after.insert(chart.second);
  EXPECT_EQ(groups_after, groups_before);
  EXPECT_EQ(fixed.charts.size(), before.size() + 1);
}

TEST(ValidAsStored, AValidResultOrAnErrorComesBackAsItWas) {
  const testmesh::Mesh m = testmesh::hemisphere(6, 12);
  const ChartOptions options;
  const ChartsResult r = parameterize_charts(m.V, m.F, options);
  ASSERT_FALSE(r.error);
  const ChartsResult same = valid_as_stored(in_unit_box(m.V), m.F, 1, int(m.V.rows()), options, r);
  EXPECT_EQ(same.corner_uv, r.corner_uv);
  EXPECT_EQ(same.face_chart, r.face_chart);
  EXPECT_EQ(same.notes, r.notes);
  ChartsResult failed;
  failed.error = {ErrorCode::SolverFailed, 1, ""};
  EXPECT_EQ(valid_as_stored(in_unit_box(m.V), m.F, 1, int(m.V.rows()), options, failed).error.code, ErrorCode::SolverFailed);
}

// A merged scan's specks inside its surface: well-shaped triangles 1e-5 of their faces' size,
// whose UV area at the texture's density is under the least area, in a ring of needles. They are
// told apart from a squashed face; their charts are left whole, and the last step moves each
// alone.
TEST(ValidAsStored, SpecksInsideASurfaceAreMovedAloneAndTheirChartsKept) {
  const testmesh::Mesh base = testmesh::sphere(12, 24);
  const ChartOptions options;
  const ChartsResult plain = parameterize_charts(base.V, base.F, options);
  ASSERT_FALSE(plain.error);
  std::vector<int> specks;
  for (int f = 5; f < base.F.rows(); f += 47) specks.push_back(f);
  const testmesh::Mesh m = testmesh::with_tiny_triangles(base, specks, 1e-5);
  const Eigen::MatrixXd unit_V = in_unit_box(m.V);
  const ChartsResult r = parameterize_charts(m.V, m.F, options);
  ASSERT_FALSE(r.error) << r.error.detail;
  EXPECT_TRUE(invalid_as_written(unit_V, m.F, r.corner_uv).empty());
  expect_valid_layout(m.F, r, &m.V);
  // The specks and the needles around them (whose apexes 6 decimals could swap) go alone; every
  // other chart is one of the charts the sphere has without them.
  std::set<int> ring(specks.begin(), specks.end());
  for (Eigen::Index f = base.F.rows(); f < m.F.rows(); ++f) ring.insert(int(f));
  const std::map<int, std::vector<int>> charts = faces_by_chart(r);
  for (const int f : specks) EXPECT_EQ(charts.at(r.face_chart[size_t(f)]).size(), 1u) << "speck " << f;
  size_t whole = 0;
  for (const auto& chart : charts) {
    if (chart.second.size() > 1) ++whole;
    else EXPECT_EQ(ring.count(chart.second.front()), 1u) << "face " << chart.second.front() << " alone";
  }
  EXPECT_EQ(whole, plain.charts.size());

  // Before the last step: the specks are invalid, but no face is squashed.
  ChartsResult unrepaired = r;
  for (const int f : specks)
    for (int k = 1; k < 3; ++k)  // each speck 1e-6 on a side (under the least area, not flipped)
      unrepaired.corner_uv.block(f, 2 * k, 1, 2) =
          unrepaired.corner_uv.block(f, 0, 1, 2) + 1e-6 * Eigen::RowVector2d(k == 1 ? 1.0 : 0.5, k == 1 ? 0.0 : 1.0);
  const std::vector<int> invalid = invalid_faces(unit_V, m.F, unrepaired.corner_uv);
  EXPECT_EQ(invalid.size(), specks.size());
  EXPECT_TRUE(without_specks(unit_V, m.F, unrepaired.corner_uv, invalid).empty());
  // A face of ordinary size squashed to the same UV area is no speck.
  const int squashed = r.face_chart[0] == r.face_chart[size_t(specks[0])] ? 1 : 0;
  unrepaired.corner_uv.block(squashed, 2, 1, 2) = unrepaired.corner_uv.block(squashed, 0, 1, 2) + Eigen::RowVector2d(1e-6, 0);
  unrepaired.corner_uv.block(squashed, 4, 1, 2) = unrepaired.corner_uv.block(squashed, 0, 1, 2) + Eigen::RowVector2d(0.5e-6, 1e-6);
  EXPECT_EQ(without_specks(unit_V, m.F, unrepaired.corner_uv, invalid_faces(unit_V, m.F, unrepaired.corner_uv)),
            std::vector<int>{squashed});
}

// MeshLab's ASCII PLY writer prints texture coordinates with 6 decimals. A sliver of area 2e-11
// (above the least area, valid in float) whose apex is 0.4e-6 off its base collapses so: it is
// invalid, it goes alone, and then every face keeps a positive area with 6 decimals.
TEST(ValidAsStored, ASliverThatSixDecimalsCollapseGoesAlone) {
  const testmesh::Mesh m = testmesh::sphere(12, 24);
  const ChartOptions options;
  ChartsResult r = parameterize_charts(m.V, m.F, options);
  ASSERT_FALSE(r.error);
  const Eigen::MatrixXd unit_V = in_unit_box(m.V);
  const int sliver = 0;
  Eigen::RowVector2d a = r.corner_uv.block(sliver, 0, 1, 2);
  a = (a * 1e6).array().round() / 1e6;
  r.corner_uv.row(sliver) << a.x(), a.y(), a.x() + 1e-4, a.y(), a.x() + 5e-5, a.y() + 0.4e-6;
  ASSERT_GT(signed_area(corner(r, sliver, 0), corner(r, sliver, 1), corner(r, sliver, 2)), kTuning.least_uv_area);
  EXPECT_TRUE(invalid_faces(unit_V, m.F, r.corner_uv).empty()) << "valid in float";
  EXPECT_EQ(invalid_as_written(unit_V, m.F, r.corner_uv), std::vector<int>{sliver});

  const ChartsResult fixed = valid_as_stored(unit_V, m.F, 1, int(m.V.rows()), options, r);
  ASSERT_FALSE(fixed.error);
  EXPECT_EQ(faces_by_chart(fixed).at(fixed.face_chart[sliver]), std::vector<int>{sliver});
  const Eigen::MatrixXd written = (fixed.corner_uv * 1e6).array().round() / 1e6;
  for (Eigen::Index f = 0; f < m.F.rows(); ++f) {
    const auto at = [&](int k) { return Eigen::Vector2d(written.block(f, 2 * k, 1, 2).transpose()); };
    EXPECT_GT(signed_area(at(0), at(1), at(2)), 0) << "face " << f;
  }
}

namespace {

double point_segment_distance(const Eigen::Vector2d& p, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  const Eigen::Vector2d d = b - a;
  const double t = d.squaredNorm() > 0 ? std::min(1.0, std::max(0.0, (p - a).dot(d) / d.squaredNorm())) : 0;
  return (p - (a + t * d)).norm();
}

// The distance between two UV triangles that do not overlap: the least from a corner of one to a
// side of the other.
double triangle_distance(const ChartsResult& r, Eigen::Index f, Eigen::Index g) {
  double least = std::numeric_limits<double>::infinity();
  for (const auto& pair : {std::make_pair(f, g), std::make_pair(g, f)})
    for (int k = 0; k < 3; ++k)
      for (int s = 0; s < 3; ++s)
        least = std::min(least, point_segment_distance(corner(r, pair.first, k), corner(r, pair.second, s),
                                                       corner(r, pair.second, (s + 1) % 3)));
  return least;
}

// The distance from face `alone` to the nearest other face in UV.
double nearest_other_face(const ChartsResult& r, Eigen::Index alone) {
  double nearest = std::numeric_limits<double>::infinity();
  for (Eigen::Index f = 0; f < Eigen::Index(r.face_chart.size()); ++f)
    if (f != alone) nearest = std::min(nearest, triangle_distance(r, alone, f));
  return nearest;
}

}  // namespace

TEST(ValidAsStored, AFaceMovedAloneGoesIntoFreeTexelsAndTheRestKeepsItsPlaceAndGutters) {
  const testmesh::Mesh m = testmesh::sphere(12, 24);
  ChartOptions options;
  options.max_stretch = 1.1;  // several charts (at the default bound the sphere is one)
  ChartsResult r = parameterize_charts(m.V, m.F, options);
  ASSERT_FALSE(r.error);
  ASSERT_GE(r.charts.size(), 2u);
  const Eigen::Index collapsed = 0;
  collapse_onto_first_corner(r, collapsed);
  const Eigen::MatrixXd unit_V = in_unit_box(m.V);
  ASSERT_EQ(invalid_faces(unit_V, m.F, r.corner_uv).size(), 1u);

  const ChartsResult fixed = valid_as_stored(unit_V, m.F, 1, int(m.V.rows()), options, r);
  ASSERT_FALSE(fixed.error);
  EXPECT_TRUE(invalid_as_written(unit_V, m.F, fixed.corner_uv).empty());
  expect_valid_layout(m.F, fixed, &m.V);
  // The layout that stays is not squeezed: every other face keeps its UV (up to float rounding).
  for (Eigen::Index f = 0; f < m.F.rows(); ++f)
    if (f != collapsed) EXPECT_LT((fixed.corner_uv.row(f) - r.corner_uv.row(f)).cwiseAbs().maxCoeff(), 1e-6) << "face " << f;
  // The face alone keeps the gutter from every other face.
  EXPECT_GE(nearest_other_face(fixed, collapsed), options.gutter / options.texture_size * (1 - 1e-6));
  EXPECT_EQ(fixed.charts.size(), r.charts.size() + 1);
}

// Hundreds of faces moved alone (a real scan's Poisson reconstruction had 249): the strip's cells
// stay wide enough for half a gutter on each side, so the faces keep a gutter between them too.
TEST(ValidAsStored, ManyFacesInTheStripKeepAGutterBetweenThem) {
  const testmesh::Mesh m = testmesh::grid(150);
  const ChartOptions options;
  ChartsResult r = parameterize_charts(m.V, m.F, options);
  ASSERT_FALSE(r.error);
  for (Eigen::Index collapsed = 7; collapsed < m.F.rows(); collapsed += 151)
    collapse_onto_first_corner(r, collapsed);
  const ChartsResult fixed = valid_as_stored(in_unit_box(m.V), m.F, 1, int(m.V.rows()), options, r);
  ASSERT_FALSE(fixed.error);
  ASSERT_GT(fixed.charts.size(), 250u);
  expect_valid_layout(m.F, fixed, &m.V);
  const double g = options.gutter / options.texture_size;
  EXPECT_GE(least_gutter(fixed.corner_uv, fixed.face_chart, 2 * g), g * (1 - 1e-6));
}

TEST(ValidAsStored, WithNoFreeTexelsTheStripKeepsTheGutterFromTheDiskBelow) {
  // A flat grid is a disk: its one chart fills the square, and the hole the face leaves (under 7
  // texels wide) cannot take a square a gutter from it; so the face moved alone goes into the strip
  // along the top and the disk is scaled below it.
  const testmesh::Mesh m = testmesh::grid(150);
  const ChartOptions options;
  ChartsResult r = parameterize_charts(m.V, m.F, options);
  ASSERT_FALSE(r.error);
  ASSERT_EQ(r.charts.size(), 1u);
  const Eigen::Index collapsed = 7;
  collapse_onto_first_corner(r, collapsed);
  const Eigen::MatrixXd unit_V = in_unit_box(m.V);

  const ChartsResult fixed = valid_as_stored(unit_V, m.F, 1, int(m.V.rows()), options, r);
  ASSERT_FALSE(fixed.error);
  EXPECT_TRUE(invalid_as_written(unit_V, m.F, fixed.corner_uv).empty());
  expect_valid_layout(m.F, fixed, &m.V);
  ASSERT_EQ(fixed.charts.size(), 2u);
  double moved = 0;
  for (Eigen::Index f = 0; f < m.F.rows(); ++f)
    if (f != collapsed) moved = std::max(moved, (fixed.corner_uv.row(f) - r.corner_uv.row(f)).cwiseAbs().maxCoeff());
  EXPECT_GT(moved, 1e-3) << "the disk is scaled below the strip";
  EXPECT_GE(nearest_other_face(fixed, collapsed), options.gutter / options.texture_size * (1 - 1e-6));
}
