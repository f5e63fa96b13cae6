#include "atlas/measure/free_squares.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "atlas/base/tuning.h"
#include "atlas/pack/texel_grid.h"

namespace lowstretch {

std::vector<Eigen::Vector2d> free_squares(const Eigen::MatrixXd& corner_uv, const std::vector<char>& stays, size_t count,
                                          double side, const ChartOptions& options) {
  const int cells = std::min(options.texture_size, kTuning.most_grid_side);
  const int gutter = int(std::ceil(options.gutter * cells / options.texture_size));  // in cells
  const int square = int(std::ceil(side * cells));
  if (count == 0 || !(side > 0) || square + 2 * gutter > cells) return {};
  TexelGrid grid(cells);
  for (Eigen::Index f = 0; f < corner_uv.rows(); ++f) {
    if (!stays[size_t(f)]) continue;
    Eigen::Vector2d p[3];
    for (int k = 0; k < 3; ++k) p[k] = cells * corner_uv.block(f, 2 * k, 1, 2).transpose();
    take_triangle(grid, p);
  }
  grid.grow(gutter);  // from here a taken cell is one a square may not use
  grid.take_border(gutter);
  const std::vector<std::vector<std::pair<int, int>>> rows(size_t(square), {{0, square}});
  std::vector<Eigen::Vector2d> corners;
  for (size_t s = 0; s < count; ++s) {
    int x = 0, y = 0;
    if (!grid.first_fit(rows, cells, x, y)) return {};
    // The square's own cells and its gutter: the next square keeps the gutter from it.
    grid.take(x - gutter, y - gutter, x + square + gutter, y + square + gutter);
    grid.recount_widest(y - gutter, y + square + gutter);
    corners.emplace_back(double(x) / cells, double(y) / cells);
  }
  return corners;
}

}  // namespace lowstretch
