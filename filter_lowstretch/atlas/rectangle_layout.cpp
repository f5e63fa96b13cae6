#include "rectangle_layout.h"

#include <algorithm>
#include <numeric>

namespace lowstretch {

namespace {

// How far a cell of width / height `cell` is from a chart's preferred aspect (either way round,
// charts may turn a quarter): 1 when it fits.
double mismatch(double cell, double preferred) {
  const double r = std::max(cell / preferred, preferred / cell), turned = std::max(cell * preferred, 1 / (cell * preferred));
  return std::min(r, turned);
}

// The worst mismatch in a row of cells (areas already scaled to the unit square) laid along a
// side of length `side`: items [first, end) of order.
double worst_mismatch(const std::vector<int>& order, size_t first, size_t end, const std::vector<double>& share,
                      const std::vector<double>& preferred, double row_area, double side) {
  const double thickness = row_area / side;
  double worst = 1;
  for (size_t k = first; k < end; ++k) {
    const int i = order[k];
    worst = std::max(worst, mismatch(share[size_t(i)] / (thickness * thickness), preferred[size_t(i)]));
  }
  return worst;
}

}  // namespace

std::vector<Eigen::AlignedBox2d> slice_unit_square(const std::vector<double>& areas, const std::vector<double>& preferred) {
  std::vector<Eigen::AlignedBox2d> cells(areas.size());
  if (areas.empty()) return cells;
  std::vector<int> order(areas.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return areas[size_t(a)] > areas[size_t(b)]; });
  const double total = std::accumulate(areas.begin(), areas.end(), 0.0);
  std::vector<double> shares;
  for (double a : areas) shares.push_back(a / total);
  const auto share = [&](int i) { return shares[size_t(i)]; };

  Eigen::AlignedBox2d left(Eigen::Vector2d(0, 0), Eigen::Vector2d(1, 1));  // the space not yet filled
  for (size_t first = 0; first < order.size();) {
    const Eigen::Vector2d size = left.sizes();
    const int along = size.x() <= size.y() ? 0 : 1;  // the row runs along the shorter side
    const double side = size[along];
    // Grow the row while its worst cell gets closer to its chart's shape.
    size_t end = first + 1;
    double row = share(order[first]);
    while (end < order.size()) {
      const double grown = row + share(order[end]);
      if (worst_mismatch(order, first, end + 1, shares, preferred, grown, side) >
          worst_mismatch(order, first, end, shares, preferred, row, side))
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

}  // namespace lowstretch
