#include "empty_texels.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "stretch.h"

namespace lowstretch {

namespace {

// A guest takes at most this share of the texels the tiling is expected to leave empty: holes and
// free outlines leave ragged room, which boxes fill only in part.
const double kGuestsShareOfEmpty = 0.5;
// A chart whose real faces cover this share of its box is seen as its box.
const double kLeastGuestFill = 0.9;
// The grid is the texture's texels up to this many per side, coarser beyond (a 65536^2 grid
// would take 4 GiB).
const int kMostGridSide = 2048;

// Which cells of a square grid are taken (a chart, or within the gutter of one), and for each
// cell how many free cells follow it in its row: a box fits where every row it spans has room.
class TexelGrid {
 public:
  explicit TexelGrid(int side) : side_(side), taken_(size_t(side) * size_t(side), 0), run_(taken_.size(), 0) {}
  int side() const { return side_; }
  void take(int x0, int y0, int x1, int y1) {  // cells [x0, x1) x [y0, y1), clipped
    x0 = std::max(x0, 0), y0 = std::max(y0, 0), x1 = std::min(x1, side_), y1 = std::min(y1, side_);
    for (int y = y0; y < y1; ++y)
      for (int x = x0; x < x1; ++x) taken_[index(x, y)] = 1;
  }
  // Takes every cell within `by` cells of a taken one (rows, then columns: a square around each).
  void grow(int by) {
    const auto grow_lines = [&](size_t line_step, size_t cell_step) {
      std::vector<char> near(static_cast<size_t>(side_), 0);
      for (int line = 0; line < side_; ++line) {
        char* cells = taken_.data() + size_t(line) * line_step;
        for (int i = 0, last = -by - 1; i < side_; ++i) {
          if (cells[size_t(i) * cell_step]) last = i;
          near[size_t(i)] = i - last <= by;
        }
        for (int i = side_ - 1, next = side_ + by; i >= 0; --i) {
          if (cells[size_t(i) * cell_step]) next = i;
          cells[size_t(i) * cell_step] = near[size_t(i)] || next - i <= by;
        }
      }
    };
    grow_lines(size_t(side_), 1);  // rows
    grow_lines(1, size_t(side_));  // columns
  }
  // Free cells: how many free cells start there; taken ones: minus how many taken cells do, so
  // that a search skips a taken stretch at once.
  void count_runs(int y0, int y1) {
    for (int y = std::max(y0, 0); y < std::min(y1, side_); ++y) {
      int free = 0, taken = 0;
      for (int x = side_; x-- > 0;) {
        const bool is_taken = taken_[index(x, y)] != 0;
        free = is_taken ? 0 : free + 1;
        taken = is_taken ? taken + 1 : 0;
        run_[index(x, y)] = is_taken ? -taken : free;
      }
    }
  }
  // The first place (lowest row, then column) where a w x h box of free cells fits; false if none.
  bool first_fit(int w, int h, int& at_x, int& at_y) const {
    for (int y = 0; y + h <= side_; ++y)
      for (int x = 0; x + w <= side_;) {
        int blocked = -1;
        for (int k = 0; k < h && blocked < 0; ++k)
          if (run_[index(x, y + k)] < w) blocked = k;
        if (blocked < 0) {
          at_x = x, at_y = y;
          return true;
        }
        const int run = run_[index(x, y + blocked)];
        x += run < 0 ? -run : run + 1;  // past the taken cells, or to the taken cell that ends the free ones
      }
    return false;
  }

 private:
  size_t index(int x, int y) const { return size_t(y) * size_t(side_) + size_t(x); }
  int side_;
  std::vector<char> taken_;
  std::vector<int> run_;
};

// Takes every cell that the triangle touches: row by row, the cells under the x-extent of the
// triangle's part in that row (a convex piece, so every cell under its extent meets it).
void take_triangle(TexelGrid& grid, const Eigen::Vector2d p[3]) {
  const double low = std::min({p[0].y(), p[1].y(), p[2].y()}), high = std::max({p[0].y(), p[1].y(), p[2].y()});
  for (int y = std::max(int(std::floor(low)), 0); y <= std::min(int(std::floor(high)), grid.side() - 1); ++y) {
    const double y0 = std::max(double(y), low), y1 = std::min(double(y + 1), high);
    double x0 = std::numeric_limits<double>::infinity(), x1 = -x0;
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector2d& a = p[k];
      const Eigen::Vector2d& b = p[(k + 1) % 3];
      if (a.y() >= y0 && a.y() <= y1) x0 = std::min(x0, a.x()), x1 = std::max(x1, a.x());
      for (const double line : {y0, y1})
        if ((a.y() - line) * (b.y() - line) < 0) {
          const double x = a.x() + (b.x() - a.x()) * (line - a.y()) / (b.y() - a.y());
          x0 = std::min(x0, x), x1 = std::max(x1, x);
        }
    }
    if (x0 <= x1) grid.take(int(std::floor(x0)), y, int(std::floor(x1)) + 1, y + 1);
  }
}

}  // namespace

std::vector<int> charts_to_put_in_empty_texels(const std::vector<SolvedChart>& charts, const std::vector<double>& own_area) {
  double empty = 0, total = 0;
  std::vector<int> boxes;
  for (size_t i = 0; i < charts.size(); ++i) {
    const SolvedChart& c = charts[i];
    total += own_area[i];
    if (c.free_boundary || c.mesh.closed_holes > 0) empty += own_area[i] * (1 - c.fill());
    else if (c.fill() >= kLeastGuestFill) boxes.push_back(int(i));
  }
  if (!(empty >= kLeastEmptyShare * total)) return {};
  std::stable_sort(boxes.begin(), boxes.end(), [&](int a, int b) { return own_area[size_t(a)] < own_area[size_t(b)]; });
  std::vector<int> guests;
  double taken = 0;
  for (const int i : boxes) {
    taken += own_area[size_t(i)];
    if (taken > kGuestsShareOfEmpty * empty) break;
    guests.push_back(i);
  }
  return guests;
}

std::vector<int> put_in_empty_texels(const std::vector<SolvedChart>& charts, const std::vector<int>& guests,
                                     const ChartOptions& options, Eigen::MatrixXd& corner_uv, std::vector<int>& face_chart) {
  const int side = std::min(options.texture_size, kMostGridSide);
  const double texel = double(options.texture_size) / side;  // texels per grid cell
  const int gutter = int(std::ceil(options.gutter / texel));
  // Layout [0,1]^2 -> grid cells, as store() moves the layout inside the gutter.
  const double offset = options.gutter / texel, scale = (options.texture_size - 2 * options.gutter) / texel;
  std::vector<char> is_guest(charts.size(), 0);
  for (const int i : guests) is_guest[size_t(i)] = 1;

  TexelGrid grid(side);
  double uv_area = 0, area_3d = 0;  // of the tiled charts, for their texel density
  for (size_t c = 0; c < charts.size(); ++c) {
    if (is_guest[c]) continue;
    area_3d += charts[c].kept.area_3d;
    for (const int f : charts[c].faces) {
      Eigen::Vector2d p[3];
      for (int k = 0; k < 3; ++k) p[k] = offset + scale * corner_uv.block(f, 2 * k, 1, 2).transpose().array();
      uv_area += std::abs(signed_uv_area(p[0], p[1], p[2]));
      take_triangle(grid, p);
    }
  }
  // Grown by the gutter; the border's gutter too. From here a taken cell is one a guest may not use.
  grid.grow(gutter);
  grid.take(0, 0, side, gutter);
  grid.take(0, side - gutter, side, side);
  grid.take(0, 0, gutter, side);
  grid.take(side - gutter, 0, side, side);
  grid.count_runs(0, side);
  const double density = area_3d > 0 ? uv_area / area_3d : 0;  // grid cells^2 per unit of 3D area

  std::vector<int> unplaced;
  std::vector<int> order = guests;  // largest first: small boxes fill the room large ones leave
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    return charts[size_t(a)].kept.area_3d > charts[size_t(b)].kept.area_3d;
  });
  for (const int g : order) {
    const SolvedChart& chart = charts[size_t(g)];
    const double own = chart.uv_area();
    if (!(density > 0) || !(own > 0) || !(chart.box.sizes().minCoeff() > 0)) {
      unplaced.push_back(g);
      continue;
    }
    const Eigen::Vector2d size = chart.box.sizes() * std::sqrt(density * chart.kept.area_3d / own);  // in cells
    int best_x = 0, best_y = 0;
    bool found = false, turned = false;
    for (const bool turn : {false, true}) {
      const int w = int(std::floor(turn ? size.y() : size.x())) + 1, h = int(std::floor(turn ? size.x() : size.y())) + 1;
      int x = 0, y = 0;
      if (!grid.first_fit(w, h, x, y)) continue;
      if (!found || std::make_pair(y, x) < std::make_pair(best_y, best_x)) best_x = x, best_y = y, turned = turn, found = true;
    }
    if (!found) {
      unplaced.push_back(g);
      continue;
    }
    const Eigen::Vector2d cells = turned ? Eigen::Vector2d(size.y(), size.x()) : size;
    const int w = int(std::floor(cells.x())) + 1, h = int(std::floor(cells.y())) + 1;
    grid.take(best_x - gutter, best_y - gutter, best_x + w + gutter, best_y + h + gutter);
    grid.count_runs(best_y - gutter, best_y + h + gutter);
    const Eigen::Vector2d origin(best_x, best_y);
    for (size_t j = 0; j < chart.faces.size(); ++j) {
      const int f = chart.faces[j];
      face_chart[size_t(f)] = g;
      for (int k = 0; k < 3; ++k) {
        Eigen::Vector2d q = ((chart.map.uv.row(chart.mesh.F(Eigen::Index(j), k)).transpose() - chart.box.min()).array() /
                             chart.box.sizes().array()).matrix();
        if (turned) q = Eigen::Vector2d(1 - q.y(), q.x());  // a quarter turn counter-clockwise, as in the tiling
        const Eigen::Vector2d in_cells = origin + q.cwiseProduct(cells);
        corner_uv.block(f, 2 * k, 1, 2) = ((in_cells.array() - offset) / scale).matrix().transpose();
      }
    }
  }
  return unplaced;
}

}  // namespace lowstretch
