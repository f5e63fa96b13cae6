#include "atlas/pack/chart_outlines.h"

#include <algorithm>
#include <cstring>

#include "atlas/pack/texel_grid.h"

namespace lowstretch {

Outline outline_of(const SolvedChart& chart, const Eigen::Vector2d& size, int turns) {
  const Eigen::Vector2d cells = turns % 2 ? Eigen::Vector2d(size.y(), size.x()) : size;
  Outline outline;
  outline.corners.reserve(3 * chart.faces.size());
  for (size_t j = 0; j < chart.faces.size(); ++j)
    for (int k = 0; k < 3; ++k) {
      Eigen::Vector2d q = ((chart.map.uv.row(chart.mesh.F(Eigen::Index(j), k)).transpose() - chart.box.min()).array() /
                           chart.box.sizes().array()).matrix();
      for (int t = 0; t < turns; ++t) q = Eigen::Vector2d(1 - q.y(), q.x());  // quarter turns counter-clockwise, as the tiling's
      outline.corners.push_back(q.cwiseProduct(cells));
    }
  const int w = int(std::floor(cells.x())) + 1, h = int(std::floor(cells.y())) + 1;
  std::vector<char> taken(size_t(w) * size_t(h), 0);  // w x h, row after row
  for (size_t j = 0; j < chart.faces.size(); ++j)
    for_each_touched_row(&outline.corners[3 * j], h, [&](int y, int x0, int x1) {
      x0 = std::max(x0, 0), x1 = std::min(x1, w);
      if (x0 < x1) std::fill(taken.begin() + long(y) * w + x0, taken.begin() + long(y) * w + x1, 1);
    });
  outline.rows.resize(size_t(h));
  for (int y = 0; y < h; ++y) {
    const char* row = taken.data() + size_t(y) * size_t(w);
    for (const char* at = row; (at = static_cast<const char*>(std::memchr(at, 1, size_t(row + w - at)))) != nullptr;) {
      const char* end = static_cast<const char*>(std::memchr(at, 0, size_t(row + w - at)));
      if (!end) end = row + w;
      outline.rows[size_t(y)].push_back({int(at - row), int(end - row)});
      if (end == row + w) break;
      at = end;
    }
  }
  return outline;
}

}  // namespace lowstretch
