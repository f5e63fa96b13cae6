// Small charts put into the texels a tiling leaves empty (atlas/pack/empty_texels.h): only into
// texels no other chart covers, a gutter from every other chart and from the border, at the texel
// density of the tiled charts; and every chart packed by its outline the same way.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <string>
#include <vector>

#include "atlas/charts.h"
#include "atlas/chart_map/solved_chart.h"
#include "atlas/cut/mesh_components.h"
#include "atlas/pack/empty_texels.h"
#include "atlas/pack/lay_out_charts.h"
#include "chart_fixtures.h"
#include "generated_meshes.h"
#include "layout_checks.h"

using namespace lowstretch;

namespace {

// Each chart's UV box and texel density (its UV area over its 3D area).
struct ChartPlaces {
  std::vector<Eigen::AlignedBox2d> box;
  std::vector<double> density;
};
ChartPlaces places_of(const testmesh::Mesh& m, const ChartsResult& r) {
  ChartPlaces places;
  places.box.resize(r.charts.size());
  for (Eigen::Index f = 0; f < m.F.rows(); ++f)
    for (int k = 0; k < 3; ++k) places.box[size_t(r.face_chart[size_t(f)])].extend(corner(r, f, k));
  places.density = texel_densities(m.V, m.F, r);
  return places;
}

// The charts whose UV box lies inside the box of face 0's chart (a plate's top, with a hole),
// each checked to be at that chart's texel density.
std::vector<size_t> charts_inside_the_box_of_face_0(const testmesh::Mesh& m, const ChartsResult& r) {
  const ChartPlaces places = places_of(m, r);
  const size_t top = size_t(r.face_chart[0]);
  std::vector<size_t> inside;
  for (size_t c = 0; c < r.charts.size(); ++c)
    if (c != top && places.box[top].contains(places.box[c])) {
      inside.push_back(c);
      EXPECT_NEAR(places.density[c] / places.density[top], 1.0, 0.05) << "chart " << c;
    }
  return inside;
}

// A host with a large closed hole laid out alone over [0,1]^2 (its map's box onto the square), and
// a guest: grid(3) at `guest_scale`, whose corners are set to -7 (not placed).
struct HostAndGuest {
  testmesh::Mesh m;
  std::vector<SolvedChart> charts;
  Eigen::MatrixXd corner_uv;
  std::vector<int> face_chart;
  Eigen::AlignedBox2d hole;  // the box of the host's hole in the layout
};
HostAndGuest host_and_guest(double guest_scale) {
  HostAndGuest s;
  const testmesh::Mesh host = testmesh::punched_grid(16, {{0.5, 0.5}}, 0.3);
  s.m = testmesh::joined(host, testmesh::grid(3), guest_scale, Eigen::RowVector3d(3, 0, 0));
  std::vector<int> host_faces, guest_faces;
  for (int f = 0; f < int(s.m.F.rows()); ++f) (f < int(host.F.rows()) ? host_faces : guest_faces).push_back(f);
  s.charts = {solved_chart_of(s.m, host_faces), solved_chart_of(s.m, guest_faces)};
  const SolvedChart& h = s.charts[0];
  const auto place = [&](const Eigen::Vector2d& uv) {
    return Eigen::Vector2d(((uv - h.box.min()).array() / h.box.sizes().array()).matrix());
  };
  s.corner_uv = Eigen::MatrixXd::Constant(s.m.F.rows(), 6, -7);
  s.face_chart.assign(size_t(s.m.F.rows()), -1);
  for (size_t j = 0; j < h.faces.size(); ++j) {
    s.face_chart[size_t(h.faces[j])] = 0;
    for (int k = 0; k < 3; ++k) s.corner_uv.block(h.faces[j], 2 * k, 1, 2) = place(h.map.uv.row(h.mesh.F(Eigen::Index(j), k)).transpose()).transpose();
  }
  for (Eigen::Index f = Eigen::Index(h.faces.size()); f < h.mesh.F.rows(); ++f)
    for (int k = 0; k < 3; ++k) s.hole.extend(place(h.map.uv.row(h.mesh.F(f, k)).transpose()));
  return s;
}

}  // namespace

// A plate's top keeps its hole at bound 1.5 (HoleThatWastesTheBoxIsCutOpen); the small squares
// beside it go into the texels that hole leaves empty rather than into cells of their own: inside
// the top's box, at the texel density of the others, a gutter away from every other chart's
// triangles (their boxes now overlap, so the gutter is measured between triangles).
TEST(EmptyTexels, SmallChartsGoIntoTexelsTheTilingLeavesEmpty) {
  testmesh::Mesh m = testmesh::plate_with_hole(8, 1.0 / 8);
  for (int i = 0; i < 12; ++i) m = testmesh::joined(m, testmesh::grid(3), 0.15, Eigen::RowVector3d(3 + i, 0, 0));
  const ChartsResult r = bounded_atlas(m, 1.5);
  expect_valid_layout(m.F, r);
  EXPECT_FALSE(charts_inside_the_box_of_face_0(m, r).empty());
  EXPECT_GE(least_distance_between_charts(m.F, r), ChartOptions().gutter / ChartOptions().texture_size * (1 - 1e-6));
}

// Charts that leave texels empty themselves (here small plates with a round hole, which a box
// would not fit into) go into empty texels by their outline: inside the top's box, at the texel
// density of the others, a gutter away from every other chart's triangles.
TEST(EmptyTexels, ChartsOfAnyShapeGoIntoEmptyTexelsByTheirOutline) {
  testmesh::Mesh m = testmesh::plate_with_hole(8, 1.0 / 8);
  for (int i = 0; i < 8; ++i)
    m = testmesh::joined(m, testmesh::punched_grid(8, {Eigen::RowVector2d(0.5, 0.5)}, 0.2), 0.2, Eigen::RowVector3d(3 + i, 0, 0));
  const ChartsResult r = unmerged_atlas(m, 1.5);
  expect_valid_layout(m.F, r);
  int holed_inside_top = 0;
  for (const size_t c : charts_inside_the_box_of_face_0(m, r)) holed_inside_top += r.charts[c].closed_holes > 0;
  EXPECT_GT(holed_inside_top, 0);
  EXPECT_GE(least_distance_between_charts(m.F, r), ChartOptions().gutter / ChartOptions().texture_size * (1 - 1e-6));
}

TEST(EmptyTexels, AVertexFarAwayGivesNoGuestLargerThanTheTexture) {
  // A fuzzed 3 x 3 quad grid (fanned, as the OFF reader read it) with one vertex 4e9 away and a
  // quad naming a vertex twice: slivers billions of texels long, which once asked the
  // empty-texel placer for a grid of that size (an int overflow and a huge allocation).
  Eigen::MatrixXd V(16, 3);
  V << 0, 0, 0, 0.333333, 0, 0.168294, 0.666667, 0, 0.181859, 1, 0, 0.028224, 0, 0.333333, 0, 0.333333, 0.3, 0.13226,
      0.666667, 0.333333, 0.142921, 1, 0.333333, 0.0221809, 0, 0.666667, 0, 0.333333, 0.666667, 0.0395891,
      4294967295.666667, 0.666667, 0.0427802, 1, 0.666667, 0.00663935, 0, 1, -0.0, 0.333333, 1, -0.0700351, 0.666667, 1,
      -0.0756802, 1, 1, -0.0117453;
  Eigen::MatrixXi F(18, 3);
  F << 0, 1, 5, 0, 5, 4, 1, 2, 6, 1, 6, 5, 3, 3, 7, 3, 7, 6, 4, 5, 9, 4, 9, 8, 5, 6, 10, 5, 10, 9, 6, 7, 11, 6, 11, 10, 8, 9,
      13, 8, 13, 12, 9, 10, 14, 9, 14, 13, 10, 11, 15, 10, 15, 14;
  const ChartsResult r = parameterize_charts(V, F, ChartOptions());
  ASSERT_FALSE(r.error) << message(r.error);
  EXPECT_EQ(r.corner_uv.rows(), F.rows());
  EXPECT_TRUE(r.corner_uv.allFinite());
  EXPECT_EQ(r.layout.flipped, 0);
}

// A guest a tenth of the host's size goes into the host's hole, the only room the host leaves:
// inside the hole's box, a gutter (in texels of the stored layout) from the host's triangles, at
// the host's texel density, and inside [0,1]^2.
TEST(EmptyTexels, GuestGoesIntoTheHoleAGutterFromTheHostAtItsDensity) {
  HostAndGuest s = host_and_guest(0.1);
  ASSERT_EQ(s.charts[0].mesh.closed_holes, 1);
  ChartOptions options;
  const std::vector<int> unplaced = put_in_empty_texels(s.charts, {1}, options, s.corner_uv, s.face_chart);
  EXPECT_TRUE(unplaced.empty());
  Eigen::AlignedBox2d guest;
  double uv[2] = {0, 0}, area[2] = {0, 0};
  for (Eigen::Index f = 0; f < s.m.F.rows(); ++f) {
    const int c = f < Eigen::Index(s.charts[0].faces.size()) ? 0 : 1;
    ASSERT_EQ(s.face_chart[size_t(f)], c) << "face " << f;
    Eigen::Vector2d p[3];
    for (int k = 0; k < 3; ++k) {
      p[k] = s.corner_uv.block(f, 2 * k, 1, 2).transpose();
      if (c == 1) guest.extend(p[k]);
    }
    const Eigen::Vector3d a = s.m.V.row(s.m.F(f, 0)), b = s.m.V.row(s.m.F(f, 1)), d = s.m.V.row(s.m.F(f, 2));
    area[c] += 0.5 * (b - a).cross(d - a).norm();
    uv[c] += signed_area(p[0], p[1], p[2]);
    if (c == 1) EXPECT_GT(signed_area(p[0], p[1], p[2]), 0) << "face " << f;
  }
  EXPECT_TRUE(s.hole.contains(guest)) << "guest " << guest.min().transpose() << " - " << guest.max().transpose();
  EXPECT_GE(guest.min().minCoeff(), 0.0);
  EXPECT_LE(guest.max().maxCoeff(), 1.0);
  EXPECT_NEAR((uv[1] / area[1]) / (uv[0] / area[0]), 1.0, 1e-6);
  ChartsResult r;
  r.corner_uv = s.corner_uv;
  r.face_chart = s.face_chart;
  const double texels = options.texture_size - 2 * options.gutter;  // per unit of the layout, once stored
  EXPECT_GE(least_distance_between_charts(s.m.F, r) * texels, options.gutter * (1 - 1e-6));
}

// A guest larger than the hole finds no room: it is returned, its corners and chart left as they were.
TEST(EmptyTexels, GuestWithoutRoomIsReturnedUntouched) {
  HostAndGuest s = host_and_guest(1.0);
  const Eigen::MatrixXd before = s.corner_uv;
  const std::vector<int> chart_before = s.face_chart;
  EXPECT_EQ(put_in_empty_texels(s.charts, {1}, ChartOptions(), s.corner_uv, s.face_chart), std::vector<int>{1});
  EXPECT_EQ(s.corner_uv, before);
  EXPECT_EQ(s.face_chart, chart_before);
}

// The empty texels expected are those of the charts that leave their box empty (here the host's
// hole: its cell less its real faces' share of its box, measured here); the guests are the
// smallest rectangles while their texels stay under the chosen share of those.
TEST(EmptyTexels, GuestsAreTheSmallestChartsThatFitTheExpectedEmptyTexels) {
  const testmesh::Mesh host = testmesh::punched_grid(16, {{0.5, 0.5}}, 0.3);
  testmesh::Mesh m = testmesh::joined(host, testmesh::grid(3), 0.2, Eigen::RowVector3d(3, 0, 0));  // area 0.04
  m = testmesh::joined(m, testmesh::grid(3), 0.1, Eigen::RowVector3d(5, 0, 0));                    // area 0.01
  m = testmesh::joined(m, testmesh::grid(3), 1.0, Eigen::RowVector3d(7, 0, 0));                    // area 1
  std::vector<std::vector<int>> parts(4);
  const int per_grid = 18;
  for (int f = 0; f < int(m.F.rows()); ++f) {
    const int after = f - int(host.F.rows());
    parts[after < 0 ? 0 : 1 + after / per_grid].push_back(f);
  }
  std::vector<SolvedChart> charts;
  for (const auto& faces : parts) charts.push_back(solved_chart_of(m, faces));
  const std::vector<double> own = cell_areas(charts);
  const double fill = real_uv_area(charts[0]) / charts[0].box.volume();
  const double empty = own[0] * (1 - fill), total = own[0] + own[1] + own[2] + own[3];
  EXPECT_NEAR(expected_empty_share(charts, own), empty / total, 1e-9);
  EXPECT_GT(empty, 0.1);  // a hole of radius 0.3 in a unit square
  // Rectangles only: the two small grids (0.01 first, then 0.04), not the unit grid nor the host.
  EXPECT_EQ(charts_to_put_in_empty_texels(charts, own, {false, 0.5, false}), (std::vector<int>{2, 1}));
  // A share of the empty texels that holds only the smallest.
  EXPECT_EQ(charts_to_put_in_empty_texels(charts, own, {false, 0.02 / empty, false}), (std::vector<int>{2}));
  EXPECT_TRUE(charts_to_put_in_empty_texels(charts, own, {true, 0.005 / empty, false}).empty());
}

namespace {

// A punched grid and five small grids, one chart each.
std::vector<SolvedChart> six_charts(testmesh::Mesh& m) {
  m = testmesh::punched_grid(16, {{0.5, 0.5}}, 0.3);
  const double scales[] = {0.6, 0.4, 0.25, 0.15, 0.1};
  for (size_t i = 0; i < 5; ++i) m = testmesh::joined(m, testmesh::grid(4), scales[i], Eigen::RowVector3d(3 + 2 * double(i), 0, 0));
  int count = 0;
  const std::vector<int> component = face_components(m.F, count);
  std::vector<std::vector<int>> faces(static_cast<size_t>(count));
  for (Eigen::Index f = 0; f < m.F.rows(); ++f) faces[size_t(component[size_t(f)])].push_back(int(f));
  std::vector<SolvedChart> charts;
  for (const std::vector<int>& part : faces) charts.push_back(solved_chart_of(m, part));
  return charts;
}

// Checks a layout by outline: each chart placed whole, unturned or turned by quarter turns (never
// mirrored), at `density`, a gutter (in texels of the stored layout) from every other chart,
// inside [0,1]^2. Returns the share of the texture covered.
double check_outline_layout(const testmesh::Mesh& m, const std::vector<SolvedChart>& charts, const ChartOptions& options,
                            double density, const ChartsResult& r) {
  std::vector<double> uv(charts.size(), 0), area(charts.size(), 0);
  double covered = 0;
  for (size_t c = 0; c < charts.size(); ++c)
    for (const int f : charts[c].faces) {
      EXPECT_EQ(r.face_chart[size_t(f)], int(c)) << "face " << f;
      const Eigen::Vector2d p[3] = {corner(r, f, 0), corner(r, f, 1), corner(r, f, 2)};
      for (const Eigen::Vector2d& q : p) EXPECT_TRUE(q.minCoeff() >= 0 && q.maxCoeff() <= 1) << "face " << f;
      EXPECT_GT(signed_area(p[0], p[1], p[2]), 0) << "face " << f;
      const Eigen::Vector3d a = m.V.row(m.F(f, 0)), b = m.V.row(m.F(f, 1)), d = m.V.row(m.F(f, 2));
      area[c] += 0.5 * (b - a).cross(d - a).norm();
      uv[c] += signed_area(p[0], p[1], p[2]);
    }
  // The grid is the texture's texels: a unit of the layout is texture_size - 2 gutters cells.
  const double cells = options.texture_size - 2 * options.gutter;
  for (size_t c = 0; c < charts.size(); ++c) {
    EXPECT_NEAR(uv[c] * cells * cells / area[c] / density, 1.0, 1e-6) << "chart " << c;
    covered += uv[c];
  }
  EXPECT_GE(least_distance_between_charts(m.F, r) * cells, options.gutter * (1 - 1e-6));
  return covered;
}

// Packs the charts by outline from `density` (0: none) and checks the layout at the density
// returned (check_outline_layout).
double check_packing(const testmesh::Mesh& m, const std::vector<SolvedChart>& charts, const ChartOptions& options,
                     double& density) {
  ChartsResult r;
  r.corner_uv = Eigen::MatrixXd::Constant(m.F.rows(), 6, -7);
  r.face_chart.assign(size_t(m.F.rows()), -1);
  EXPECT_TRUE(pack_by_outline(charts, options, r.corner_uv, r.face_chart, density));
  return check_outline_layout(m, charts, options, density, r);
}

}  // namespace

// Every chart packed by its outline on an empty grid (pack_by_outline), at one texel density,
// apart and inside the texture; the densest packing covers more than half of the texture.
TEST(PackByOutline, EveryChartAtOneDensityAGutterApartInsideTheTexture) {
  testmesh::Mesh m;
  const std::vector<SolvedChart> charts = six_charts(m);
  double density = 0;
  EXPECT_GT(check_packing(m, charts, ChartOptions(), density), 0.5);
}

// A density to start from (a repair's next round): from the one found, the same layout; from far
// below or above it, a valid one within the bisection's last step of where the search stops, as
// dense as the cold search's give or take the fit's ups and downs (not monotone in density).
TEST(PackByOutline, StartingFromAGivenDensityFindsAsDenseALayout) {
  testmesh::Mesh m;
  const std::vector<SolvedChart> charts = six_charts(m);
  const ChartOptions options;
  double cold = 0;
  const double cold_covered = check_packing(m, charts, options, cold);
  double same = cold;
  EXPECT_EQ(check_packing(m, charts, options, same), cold_covered);
  EXPECT_EQ(same, cold);
  for (const double start : {cold / 5, cold * 1.5}) {
    double warm = start;
    const double covered = check_packing(m, charts, options, warm);
    EXPECT_GT(covered, 0.9 * cold_covered) << "from " << start;
    EXPECT_LT(warm, 1.5 * cold) << "from " << start;
  }
}

// The probe a packing that must reach an efficiency starts with (may_cover_by_outline): at the
// coverage the search found, the charts fit, as they did there; the whole texture they cannot
// cover (a gutter around each); with no coverage asked, they may; with no room, they may not.
TEST(PackByOutline, MayCoverWhatTheSearchCoveredButNotTheWholeTexture) {
  testmesh::Mesh m;
  const std::vector<SolvedChart> charts = six_charts(m);
  const ChartOptions options;
  double density = 0;
  const double covered = check_packing(m, charts, options, density);
  EXPECT_TRUE(may_cover_by_outline(charts, options, covered * (1 - 1e-9)));
  EXPECT_FALSE(may_cover_by_outline(charts, options, 1));
  EXPECT_FALSE(may_cover_by_outline(charts, options, 0.99));
  EXPECT_TRUE(may_cover_by_outline(charts, options, 0));
  ChartOptions tiny = options;
  tiny.texture_size = 8;
  tiny.gutter = 4;  // the border's gutter takes every cell
  EXPECT_FALSE(may_cover_by_outline(charts, tiny, 0));
}

// A repair round (lay_out_around): the charts that were not cut stay where the last layout by
// outline put them; the two halves of the cut one go into the texels left empty, at the same
// density, a gutter from the others. With no room left for a piece (here a gutter of a quarter of
// the texture, twice what the options allow, around the charts that stay and along the border:
// nothing is left free), it says so.
TEST(PackByOutline, ARepairRoundKeepsTheChartsNotCutWhereTheyWere) {
  testmesh::Mesh m;
  std::vector<SolvedChart> charts = six_charts(m);
  const ChartOptions options;
  std::vector<int> all(charts.size());
  std::iota(all.begin(), all.end(), 0);
  ChartsResult last;
  double density = 0;
  ASSERT_FALSE(lay_out(charts, options, m.F.rows(), all, last, density));
  // The largest of the small grids (16 faces, rows bottom to top) cut into its lower and upper half.
  const size_t cut = 1;
  ASSERT_EQ(charts[cut].faces.size(), 32u);
  const std::vector<int> faces = charts[cut].faces;
  std::vector<SolvedChart> next;
  std::vector<int> was;
  for (size_t c = 0; c < charts.size(); ++c)
    if (c != cut) next.push_back(charts[c]), was.push_back(int(c));
  for (const size_t half : {0, 1}) {
    next.push_back(solved_chart_of(m, std::vector<int>(faces.begin() + long(16 * half), faces.begin() + long(16 * half + 16))));
    was.push_back(-1);
  }
  ChartsResult r;
  ASSERT_TRUE(lay_out_around(next, options, last.corner_uv, was, r));
  for (size_t c = 0; c < next.size(); ++c)
    for (const int f : next[c].faces)
      if (was[c] >= 0) EXPECT_EQ(r.corner_uv.row(f), last.corner_uv.row(f)) << "face " << f << " stays";
  check_outline_layout(m, next, options, density, r);

  ChartOptions wide = options;
  wide.gutter = wide.texture_size / 4.0;
  ChartsResult none;
  EXPECT_FALSE(lay_out_around(next, wide, last.corner_uv, was, none));
}

// A ring and a square of more area than the ring that fits into its hole: placed largest first,
// the square takes the room the ring needs beside it; placed longest box first, the ring goes
// first and the square into its hole, at a texel density about twice as high.
TEST(PackByOutline, AChartGoesIntoARingsHoleWhereThatFitsDenser) {
  testmesh::Mesh m = testmesh::joined(testmesh::punched_grid(24, {{0.5, 0.5}}, 0.45), testmesh::grid(4), 0.62,
                                      Eigen::RowVector3d(3, 0, 0));
  int count = 0;
  const std::vector<int> component = face_components(m.F, count);
  ASSERT_EQ(count, 2);
  std::vector<std::vector<int>> faces(2);
  for (Eigen::Index f = 0; f < m.F.rows(); ++f) faces[size_t(component[size_t(f)])].push_back(int(f));
  const std::vector<SolvedChart> charts = {solved_chart_of(m, faces[0]), solved_chart_of(m, faces[1])};
  ASSERT_GT(charts[1].kept.area_3d, charts[0].kept.area_3d) << "the square is the larger chart";
  double density = 0;
  EXPECT_GT(check_packing(m, charts, ChartOptions(), density), 0.4) << "side by side, they cover less than a quarter";
  ChartsResult r;
  r.corner_uv = Eigen::MatrixXd::Constant(m.F.rows(), 6, -7);
  r.face_chart.assign(size_t(m.F.rows()), -1);
  ASSERT_TRUE(pack_by_outline(charts, ChartOptions(), r.corner_uv, r.face_chart, density));
  Eigen::AlignedBox2d ring, square;
  for (size_t c = 0; c < 2; ++c)
    for (const int f : faces[c])
      for (int k = 0; k < 3; ++k) (c == 0 ? ring : square).extend(corner(r, f, k));
  EXPECT_TRUE(ring.contains(square)) << "the square inside the ring's box";
}
