#include "rectangle_layout.h"

#include <algorithm>
#include <numeric>

namespace lowstretch {

namespace {

// The worst width / height of a row of cells of these areas (already scaled to the unit square)
// laid along a side of length `side`.
double worst_aspect(double row_area, double smallest, double largest, double side) {
  const double thickness = row_area / side;
  const auto aspect = [&](double a) {
    const double along = a / thickness;
    return std::max(along / thickness, thickness / along);
  };
  return std::max(aspect(smallest), aspect(largest));
}

}  // namespace

std::vector<Eigen::AlignedBox2d> slice_unit_square(const std::vector<double>& areas) {
  std::vector<Eigen::AlignedBox2d> cells(areas.size());
  if (areas.empty()) return cells;
  std::vector<int> order(areas.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return areas[size_t(a)] > areas[size_t(b)]; });
  const double total = std::accumulate(areas.begin(), areas.end(), 0.0);
  const auto share = [&](int i) { return areas[size_t(i)] / total; };

  Eigen::AlignedBox2d left(Eigen::Vector2d(0, 0), Eigen::Vector2d(1, 1));  // the space not yet filled
  for (size_t first = 0; first < order.size();) {
    const Eigen::Vector2d size = left.sizes();
    const int along = size.x() <= size.y() ? 0 : 1;  // the row runs along the shorter side
    const double side = size[along];
    // Grow the row while its worst cell gets squarer (items are sorted: the first is largest).
    size_t end = first + 1;
    double row = share(order[first]);
    while (end < order.size()) {
      const double grown = row + share(order[end]);
      if (worst_aspect(grown, share(order[end]), share(order[first]), side) >
          worst_aspect(row, share(order[end - 1]), share(order[first]), side))
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
