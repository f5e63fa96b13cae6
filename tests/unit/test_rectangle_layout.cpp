// The charts' cells (atlas/pack/rectangle_layout.h): they tile the unit square, each with its chart's
// share of the area, and a tiling that gives every chart its own shape is found when one exists.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "atlas/base/tuning.h"
#include "atlas/pack/rectangle_layout.h"

using namespace lowstretch;

namespace {

// How far a cell is from a chart's shape, either way round (1: it fits).
double mismatch(const Eigen::AlignedBox2d& cell, double preferred) {
  const double aspect = cell.sizes().x() / cell.sizes().y();
  return std::min(std::max(aspect / preferred, preferred / aspect), std::max(aspect * preferred, 1 / (aspect * preferred)));
}

void expect_tiling(const std::vector<double>& areas, const std::vector<Eigen::AlignedBox2d>& cells) {
  ASSERT_EQ(cells.size(), areas.size());
  double total = 0, covered = 0;
  for (double a : areas) total += a;
  for (size_t i = 0; i < cells.size(); ++i) {
    EXPECT_GE(cells[i].min().minCoeff(), -1e-12);
    EXPECT_LE(cells[i].max().maxCoeff(), 1 + 1e-12);
    EXPECT_NEAR(cells[i].volume(), areas[i] / total, 1e-12) << i;
    covered += cells[i].volume();
    for (size_t j = 0; j < i; ++j) {
      const Eigen::Vector2d overlap = cells[i].max().cwiseMin(cells[j].max()) - cells[i].min().cwiseMax(cells[j].min());
      EXPECT_LE(overlap.cwiseMax(0.0).prod(), 1e-15) << i << " " << j;
    }
  }
  EXPECT_NEAR(covered, 1.0, 1e-12);
}

}  // namespace

TEST(RectangleLayout, CellsTileTheSquareByShare) {
  std::vector<double> areas, preferred;
  for (int i = 0; i < 40; ++i) {
    areas.push_back(1 + (i * 37 % 11) + (i % 3 == 0 ? 20 : 0));
    preferred.push_back(0.3 + 0.1 * (i * 13 % 29));
  }
  expect_tiling(areas, slice_unit_square(areas, preferred));
}

TEST(RectangleLayout, FourSquaresMakeAGrid) {
  const std::vector<double> areas(4, 1.0), preferred(4, 1.0);
  const std::vector<Eigen::AlignedBox2d> cells = slice_unit_square(areas, preferred);
  expect_tiling(areas, cells);
  for (const Eigen::AlignedBox2d& c : cells) EXPECT_NEAR(mismatch(c, 1), 1, 1e-9);
}

// Rows along the shorter side alone put two of these charts in cells 3.84 and 3.125 times off
// their shape, so that they fill only part of them; rows along the longer side keep every chart
// within kTuning.most_cell_mismatch.
TEST(RectangleLayout, EveryChartFitsItsCellWhenAnotherTilingAllowsIt) {
  const std::vector<double> areas = {3, 1, 3, 1}, preferred = {0.5, 1, 4, 4};
  const std::vector<Eigen::AlignedBox2d> cells = slice_unit_square(areas, preferred);
  expect_tiling(areas, cells);
  for (size_t i = 0; i < cells.size(); ++i) EXPECT_LE(mismatch(cells[i], preferred[i]), kTuning.most_cell_mismatch + 1e-9) << i;
}
