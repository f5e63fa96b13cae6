#include "atlas/pack/rectangle_layout.h"

#include "atlas/base/tuning.h"

#include <algorithm>
#include <numeric>
#include <utility>

namespace lowstretch {

namespace {

// How far a cell of width / height `cell` is from a chart's preferred aspect (either way round,
// charts may turn a quarter): 1 when it fits.
double mismatch(double cell, double preferred) {
  const double r = std::max(cell / preferred, preferred / cell), turned = std::max(cell * preferred, 1 / (cell * preferred));
  return std::min(r, turned);
}

// What a cell `m` times off its chart's shape costs, per unit of the chart's area, as a factor on
// L2^2 over coverage: stretching a chart m times one way gives L2^2 (m + 1/m) / 2; beyond
// kTuning.most_cell_mismatch the chart keeps that stretch and fills only part of its cell.
double cost(double m) {
  const double most = kTuning.most_cell_mismatch;
  if (m <= most) return 0.5 * (m + 1 / m);
  return 0.5 * (most + 1 / most) * m / most;
}

// How a row decides to take one more cell.
enum class Growth { WorstCellBetter, MeanCostLower };

// A row of cells (areas already scaled to the unit square) laid along a side of length `side`:
// items [first, end) of order. Its worst mismatch, or its cost per unit area.
double row_measure(Growth growth, const std::vector<int>& order, size_t first, size_t end, const std::vector<double>& share,
                   const std::vector<double>& preferred, double row_area, double side) {
  const double thickness = row_area / side;
  double worst = 1, weighted = 0;
  for (size_t k = first; k < end; ++k) {
    const int i = order[k];
    const double m = mismatch(share[size_t(i)] / (thickness * thickness), preferred[size_t(i)]);
    worst = std::max(worst, m);
    weighted += share[size_t(i)] * cost(m);
  }
  return growth == Growth::WorstCellBetter ? worst : weighted / row_area;
}

// The squarified treemap with one way of growing rows; rows run along the shorter side of the
// space left, or along the longer one.
std::vector<Eigen::AlignedBox2d> slice(const std::vector<int>& order, const std::vector<double>& shares,
                                       const std::vector<double>& preferred, Growth growth, bool along_longer) {
  std::vector<Eigen::AlignedBox2d> cells(shares.size());
  const auto share = [&](int i) { return shares[size_t(i)]; };
  Eigen::AlignedBox2d left(Eigen::Vector2d(0, 0), Eigen::Vector2d(1, 1));  // the space not yet filled
  for (size_t first = 0; first < order.size();) {
    const Eigen::Vector2d size = left.sizes();
    const int along = (size.x() <= size.y()) != along_longer ? 0 : 1;
    const double side = size[along];
    // Grow the row while that makes it better.
    size_t end = first + 1;
    double row = share(order[first]);
    while (end < order.size()) {
      const double grown = row + share(order[end]);
      if (row_measure(growth, order, first, end + 1, shares, preferred, grown, side) >
          row_measure(growth, order, first, end, shares, preferred, row, side))
        break;
      row = grown;
      ++end;
    }
    // The last row takes all the space left, so that rounding never leaves a gap.
    const double thickness = end == order.size() ? size[1 - along] : std::min(size[1 - along], row / side);
    double position = left.min()[along];
    for (size_t k = first; k < end; ++k) {
      Eigen::AlignedBox2d cell = left;
      cell.min()[along] = position;
      position = k + 1 == end ? left.max()[along] : position + side * share(order[k]) / row;
      cell.max()[along] = position;
      cell.max()[1 - along] = left.min()[1 - along] + thickness;
      cells[size_t(order[k])] = cell;
    }
    left.min()[1 - along] += thickness;
    first = end;
  }
  return cells;
}

}  // namespace

std::vector<Eigen::AlignedBox2d> slice_unit_square(const std::vector<double>& areas, const std::vector<double>& preferred) {
  if (areas.empty()) return {};
  std::vector<int> order(areas.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return areas[size_t(a)] > areas[size_t(b)]; });
  const double total = std::accumulate(areas.begin(), areas.end(), 0.0);
  std::vector<double> shares;
  for (double a : areas) shares.push_back(a / total);
  // A few ways of cutting rows; the one with the least area in cells its charts fill only in part
  // (their texel density is lower), then the one whose cells cost least (the first on a tie).
  std::vector<Eigen::AlignedBox2d> best;
  std::pair<double, double> best_cost;
  for (const Growth growth : {Growth::WorstCellBetter, Growth::MeanCostLower})
    for (const bool along_longer : {false, true}) {
      std::vector<Eigen::AlignedBox2d> cells = slice(order, shares, preferred, growth, along_longer);
      std::pair<double, double> c(0, 0);
      for (size_t i = 0; i < cells.size(); ++i) {
        const double m = mismatch(cells[i].sizes().x() / cells[i].sizes().y(), preferred[i]);
        if (m > kTuning.most_cell_mismatch * 1.02) c.first += shares[i];  // the layout's tolerance: 2% off the shape
        c.second += shares[i] * cost(m);
      }
      if (best.empty() || c < best_cost) {
        best = std::move(cells);
        best_cost = c;
      }
    }
  return best;
}

}  // namespace lowstretch
