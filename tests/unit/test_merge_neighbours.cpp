// Neighbouring charts merged for shorter seams (atlas/bound/merge_neighbours.h): every merge joins
// two neighbours into one chart, removing the seam between them; the growth is the charts' texture
// cost over their cost before; the atlas keeps the least efficiency it is given.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "atlas/base/tuning.h"
#include "atlas/bound/deciding_map.h"
#include "atlas/bound/merge_neighbours.h"
#include "atlas/chart_map/free_charts.h"
#include "atlas/bound/split_until_bounded.h"
#include "atlas/charts.h"
#include "chart_fixtures.h"
#include "core/half_edges.h"
#include "generated_meshes.h"
#include "layout_checks.h"

using namespace lowstretch;

namespace {

// The charts of m cut by stretch to `bound`.
std::vector<SolvedChart> cut_charts(const testmesh::Mesh& m, double bound) {
  std::vector<int> all(size_t(m.F.rows()));
  for (size_t f = 0; f < all.size(); ++f) all[f] = int(f);
  ChartOptions options;
  options.max_stretch = bound;
  std::vector<SolvedChart> leaves, uncut;
  std::vector<std::string> notes;
  const Error e = split_until_bounded(m.V, m.F, {all}, options, leaves, uncut, notes);
  EXPECT_FALSE(e) << message(e);
  return leaves;
}

// The chart of every face, -1 if none; fails if a face is in two charts.
std::vector<int> chart_of_faces(const std::vector<SolvedChart>& charts, Eigen::Index faces) {
  std::vector<int> chart(size_t(faces), -1);
  for (size_t c = 0; c < charts.size(); ++c)
    for (const int f : charts[c].faces) {
      EXPECT_EQ(chart[size_t(f)], -1) << "face " << f << " is in two charts";
      chart[size_t(f)] = int(c);
    }
  return chart;
}

// The seams counted edge by edge: the 3D length of the edges between faces of different charts.
double seam_between(const testmesh::Mesh& m, const std::vector<int>& twin, const std::vector<int>& chart) {
  double length = 0;
  for (size_t h = 0; h < twin.size(); ++h) {
    const int t = twin[h];
    if (t < int(h) || chart[h / 3] == chart[size_t(t / 3)]) continue;
    const int f = int(h / 3), k = int(h % 3);
    length += (m.V.row(m.F(f, k)) - m.V.row(m.F(f, (k + 1) % 3))).norm();
  }
  return length;
}

double total_cost(const std::vector<SolvedChart>& charts) {
  double cost = 0;
  for (const SolvedChart& c : charts) cost += texture_cost(c);
  return cost;
}

}  // namespace

TEST(MergeNeighbours, EveryMergeJoinsTwoChartsShorteningTheSeamsAndItsGrowthIsTheCostRatio) {
  size_t merges = 0;
  for (const testmesh::Mesh& m : {testmesh::sphere_with_bump(), testmesh::torus(32, 16), testmesh::ball_with_arms()}) {
    const std::vector<int> twin = opposite_half_edges(m.F);
    const std::vector<SolvedChart> charts = cut_charts(m, 1.05);
    ASSERT_TRUE(std::all_of(charts.begin(), charts.end(), [](const SolvedChart& c) { return std::isfinite(texture_cost(c)); }));
    NeighbourMerging merging(charts, m.V, m.F, twin, ChartOptions());
    merging.merge_within(1.3);
    EXPECT_LE(merging.growth(merging.merges()), 1.3);
    const std::vector<SolvedChart> none = merging.charts_after(0);
    ASSERT_EQ(none.size(), charts.size());
    const double before = total_cost(none);
    double seam = seam_between(m, twin, chart_of_faces(none, m.F.rows()));
    EXPECT_NEAR(merging.seam_between_after(0), seam, 1e-9 * seam);  // summed as merged, against edge by edge
    for (size_t k = 1; k <= merging.merges(); ++k, ++merges) {
      const std::vector<SolvedChart> after = merging.charts_after(k);
      const std::vector<int> chart = chart_of_faces(after, m.F.rows());
      EXPECT_EQ(std::count(chart.begin(), chart.end(), -1), 0) << "every face is in a chart";
      EXPECT_EQ(after.size(), charts.size() - k);
      const double shorter = seam_between(m, twin, chart);
      EXPECT_LT(shorter, seam);
      EXPECT_NEAR(merging.seam_between_after(k), shorter, 1e-9 * seam);
      EXPECT_NEAR(merging.growth(k), total_cost(after) / before, 1e-9);
      for (const SolvedChart& c : after) EXPECT_EQ(c.kept.flipped + c.kept.degenerate, 0);
      seam = shorter;
    }
  }
  EXPECT_GT(merges, 3u) << "the meshes give charts to merge";
}

TEST(MergeNeighbours, TheSameChartsGiveTheSameMerges) {
  const testmesh::Mesh m = testmesh::ball_with_arms();
  const std::vector<SolvedChart> charts = cut_charts(m, 1.05);
  const std::vector<int> twin = opposite_half_edges(m.F);
  NeighbourMerging a(charts, m.V, m.F, twin, ChartOptions()), b(charts, m.V, m.F, twin, ChartOptions());
  a.merge_within(1.2);
  b.merge_within(1.1);
  b.merge_within(1.2);  // step by step as far
  ASSERT_EQ(a.merges(), b.merges());
  const std::vector<SolvedChart> ca = a.charts_after(a.merges()), cb = b.charts_after(b.merges());
  ASSERT_EQ(ca.size(), cb.size());
  for (size_t c = 0; c < ca.size(); ++c) EXPECT_EQ(ca[c].faces, cb[c].faces);
}

namespace {

// What the merging note says: "N charts merged for shorter seams (...): efficiency E (coverage /
// L2^2) against U, at least L" (U: the unmerged atlas's efficiency, L: the least kept).
struct MergeNote {
  bool found = false;
  double unmerged = 0, least = 0;
};
MergeNote merge_note(const ChartsResult& r) {
  MergeNote note;
  for (const std::string& n : r.notes) {
    if (n.find("merged for shorter seams (") == std::string::npos) continue;
    note.found = true;
    note.unmerged = std::stod(n.substr(n.rfind("against ") + 8));
    note.least = std::stod(n.substr(n.rfind("at least ") + 9));
  }
  return note;
}

}  // namespace

TEST(MergeNeighbours, TheAtlasKeepsTheLeastEfficiencyWithShorterSeams) {
  int merged = 0;
  for (const testmesh::Mesh& m : {testmesh::sphere_with_bump(), testmesh::torus(32, 16), testmesh::ball_with_arms()}) {
    ChartOptions options;
    options.non_disk = NonDisk::Atlas;
    options.min_efficiency = 1;  // no chart merged
    const ChartsResult cut = parameterize_charts(m.V, m.F, options);
    ASSERT_FALSE(cut.error) << message(cut.error);
    double seam = cut.seam_length;
    for (const bool fewer : {false, true}) {
      options.min_efficiency = 0;  // the default: kTuning's floor and share of the unmerged atlas's
      options.fewer_seams = fewer;
      const ChartsResult r = parameterize_charts(m.V, m.F, options);
      ASSERT_FALSE(r.error) << message(r.error);
      expect_valid_layout(m.F, r, &m.V);
      EXPECT_LE(r.seam_length, seam);
      if (r.charts.size() < cut.charts.size()) {
        ++merged;
        const MergeNote note = merge_note(r);
        ASSERT_TRUE(note.found);
        // Fewer seams merges an atlas already below its floor too, keeping its efficiency.
        EXPECT_GE(note.least, fewer ? std::min(kTuning.merge_floor[1], note.unmerged) : kTuning.merge_floor[0]);
        EXPECT_GE(texture_efficiency(r), note.least * (1 - 1e-5));  // the note rounds to 6 digits
      }
      seam = r.seam_length;
    }
  }
  EXPECT_GT(merged, 0) << "some atlas had charts merged";
}

// Specks of debris, each given a cell of the tiling, keep a torus's atlas below Fewer seams's floor
// (0.555). Fewer seams still merges its charts, keeping the unmerged atlas's efficiency, as its note
// says; by default nothing is merged below the floor.
TEST(MergeNeighbours, FewerSeamsMergesAnAtlasThatDebrisKeepsBelowTheFloor) {
  const testmesh::Mesh m = testmesh::with_specks(testmesh::torus(32, 16), 300, 20, 3);
  ChartOptions options;
  options.non_disk = NonDisk::Atlas;
  options.texture_size = 256;
  options.min_efficiency = 1;  // no chart merged
  const ChartsResult cut = parameterize_charts(m.V, m.F, options);
  ASSERT_FALSE(cut.error) << message(cut.error);
  options.min_efficiency = 0;
  const ChartsResult by_default = parameterize_charts(m.V, m.F, options);
  ASSERT_FALSE(by_default.error) << message(by_default.error);
  EXPECT_EQ(by_default.charts.size(), cut.charts.size());
  options.fewer_seams = true;
  const ChartsResult fewer = parameterize_charts(m.V, m.F, options);
  expect_valid_layout(m.F, fewer, &m.V);
  EXPECT_LT(fewer.charts.size(), cut.charts.size());
  EXPECT_LT(fewer.seam_length, cut.seam_length);
  const MergeNote note = merge_note(fewer);
  ASSERT_TRUE(note.found);
  EXPECT_LT(note.unmerged, kTuning.merge_floor[1]);
  EXPECT_NEAR(note.least, note.unmerged, 1e-12);
  EXPECT_GE(texture_efficiency(fewer), note.least * (1 - 1e-5));  // the note rounds to 6 digits
}

TEST(MergeNeighbours, AGivenLeastEfficiencyIsKeptAndLowerMergesMore) {
  int merged = 0;
  for (const testmesh::Mesh& m : {testmesh::sphere_with_bump(), testmesh::torus(32, 16), testmesh::ball_with_arms()}) {
    ChartOptions options;
    options.non_disk = NonDisk::Atlas;
    size_t unmerged = 0, charts = std::numeric_limits<size_t>::max();
    double seam = std::numeric_limits<double>::infinity();
    for (const double least : {1.0, 0.6, 0.5, 0.4}) {
      options.min_efficiency = least;
      const ChartsResult r = parameterize_charts(m.V, m.F, options);
      ASSERT_FALSE(r.error) << message(r.error);
      expect_valid_layout(m.F, r, &m.V);
      if (least == 1.0) unmerged = r.charts.size();
      if (r.charts.size() < unmerged) {
        ++merged;
        EXPECT_GE(texture_efficiency(r), least);
      }
      EXPECT_LE(r.charts.size(), charts);
      EXPECT_LE(r.seam_length, seam);
      charts = r.charts.size();
      seam = r.seam_length;
    }
  }
  EXPECT_GT(merged, 1) << "some atlases had charts merged";
}

TEST(MergeNeighbours, LeastEfficiencyOutOfRangeIsRefusedByName) {
  const testmesh::Mesh m = testmesh::torus(16, 8);
  for (const double bad : {-0.1, 1.5, std::nan("")}) {
    ChartOptions options;
    options.min_efficiency = bad;
    const ChartsResult r = parameterize_charts(m.V, m.F, options);
    EXPECT_EQ(r.error.code, ErrorCode::InvalidOption);
    EXPECT_EQ(r.error.option, "min_efficiency") << message(r.error);
  }
}

TEST(MergeNeighbours, FreeUnionsAreKeptOnlyWhereTheyCostLessThanTheirRectangleAndDoNotCrossThemselves) {
  int free = 0;
  for (const testmesh::Mesh& m : {testmesh::sphere_with_bump(), testmesh::torus(32, 16), testmesh::ball_with_arms()}) {
    const std::vector<int> twin = opposite_half_edges(m.F);
    const std::vector<SolvedChart> charts = cut_charts(m, 1.05);
    NeighbourMerging merging(charts, m.V, m.F, twin, ChartOptions(), true);
    merging.merge_within(5);
    const std::vector<SolvedChart> after = merging.charts_after(merging.merges());
    const std::vector<int> chart = chart_of_faces(after, m.F.rows());
    EXPECT_EQ(std::count(chart.begin(), chart.end(), -1), 0) << "every face is in a chart";
    for (const SolvedChart& u : after) {
      EXPECT_EQ(u.kept.flipped + u.kept.degenerate, 0);
      if (!u.free_boundary) continue;  // the cut charts are on rectangles: a free chart is a union
      ++free;
      SolvedChart rectangle = unmapped_copy(u);  // the union as merging maps it onto its rectangle
      solve_chart(rectangle, deciding_options(ChartOptions().disk), 0);
      EXPECT_LT(texture_cost(u), texture_cost(rectangle)) << "a free union pays for itself";
      EXPECT_FALSE(crosses_itself(u));
    }
  }
  EXPECT_GT(free, 0) << "some unions are free";
}

TEST(MergeNeighbours, UnionsAreSolvedByTheLuAsTheCutsChartsAre) {
  // Unions above the core's multigrid bound (3000 unknowns) and below the charts' (30000).
  const testmesh::Mesh m = testmesh::hemisphere(60, 120);
  const std::vector<int> twin = opposite_half_edges(m.F);
  NeighbourMerging merging(cut_charts(m, 1.05), m.V, m.F, twin, ChartOptions());
  merging.merge_within(100);
  size_t largest = 0;
  for (const SolvedChart& c : merging.charts_after(merging.merges())) {
    largest = std::max(largest, size_t(c.mesh.V.rows()));
    for (const PassMetrics& pass : c.map.passes) EXPECT_EQ(pass.solver, LinearSolver::Direct) << c.mesh.V.rows() << " vertices";
  }
  EXPECT_GT(largest, size_t(SolverOptions().amg_minimum_rows));
  EXPECT_LT(largest, size_t(kTuning.chart_amg_minimum_rows));
}
