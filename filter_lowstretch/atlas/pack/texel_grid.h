// The texture's texels as a grid of taken and free cells, for packing charts by their outlines:
// which cells a triangle touches, and where an outline first fits.
#pragma once
#include <Eigen/Core>
#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

namespace lowstretch {

// Which cells of a square grid are taken (a chart, or within the gutter of one), and for each
// cell how many free cells follow it in its row: a box fits where every row it spans has room.
class TexelGrid {
 public:
  explicit TexelGrid(int side)
      : side_(side), taken_(size_t(side) * size_t(side), 0), run_(taken_.size(), 0), widest_(size_t(side), 0) {
    assert(side <= std::numeric_limits<Run>::max());
  }
  int side() const { return side_; }
  void take(int x0, int y0, int x1, int y1) {  // cells [x0, x1) x [y0, y1), clipped
    x0 = std::max(x0, 0), y0 = std::max(y0, 0), x1 = std::min(x1, side_), y1 = std::min(y1, side_);
    for (int y = y0; y < y1 && x0 < x1; ++y) std::fill(taken_.begin() + long(index(x0, y)), taken_.begin() + long(index(x1, y)), 1);
  }
  // Takes the cells within `gutter` of the border, and counts the free runs of every row.
  void take_border(int gutter) {
    take(0, 0, side_, gutter);
    take(0, side_ - gutter, side_, side_);
    take(0, 0, gutter, side_);
    take(side_ - gutter, 0, side_, side_);
    count_runs(0, side_);
  }
  // Takes every cell within `by` cells of a taken one (a square around each): each row ORed with
  // its neighbours `by` cells either way, then with the rows `by` above and below (whole rows at
  // a time, which the compiler vectorizes; a column at a time strides through memory).
  void grow(int by) {
    const size_t n = size_t(side_);
    std::vector<char> row(n);
    for (size_t y = 0; y < n; ++y) {
      char* __restrict cells = taken_.data() + y * n;
      const char* __restrict before = row.data();
      std::copy(cells, cells + n, row.begin());
      for (size_t shift = 1; shift <= size_t(by) && shift < n; ++shift) {
        for (size_t x = 0; x + shift < n; ++x) cells[x] |= before[x + shift];
        for (size_t x = shift; x < n; ++x) cells[x] |= before[x - shift];
      }
    }
    std::vector<char> grown(taken_.size());
    for (size_t y = 0; y < n; ++y) {
      char* out = grown.data() + y * n;
      const size_t first = y >= size_t(by) ? y - size_t(by) : 0, last = std::min(n - 1, y + size_t(by));
      std::copy(taken_.data() + first * n, taken_.data() + (first + 1) * n, out);
      for (size_t near = first + 1; near <= last; ++near) {
        const char* cells = taken_.data() + near * n;
        for (size_t x = 0; x < n; ++x) out[x] |= cells[x];
      }
    }
    taken_.swap(grown);
  }
  // Free cells: how many free cells start there; taken ones: minus how many taken cells do, so
  // that a search skips a taken stretch at once.
  void count_runs(int y0, int y1) { count_runs(y0, y1, 0, side_); }
  // The same where only cells of columns [x0, x1) changed: a cell's count follows from its own
  // and the next one's, so the counts right of x1 stay, and left of x0 they stay from the first
  // that comes out as before.
  void count_runs(int y0, int y1, int x0, int x1) {
    x0 = std::max(x0, 0), x1 = std::min(x1, side_);
    for (int y = std::max(y0, 0); y < std::min(y1, side_); ++y) {
      const char* cells = taken_.data() + index(0, y);
      Run* runs = run_.data() + index(0, y);
      const int next = x1 < side_ ? runs[x1] : 0;
      int free = std::max(next, 0), taken = std::max(-next, 0);
      for (int x = x1; x-- > 0;) {
        const bool is_taken = cells[x] != 0;
        free = is_taken ? 0 : free + 1;
        taken = is_taken ? taken + 1 : 0;
        const Run run = Run(is_taken ? -taken : free);
        if (x < x0 && runs[x] == run) break;
        runs[x] = run;
      }
      widest_[size_t(y)] = std::max<int>(0, *std::max_element(runs, runs + side_));
    }
  }
  // The first place (lowest row, then column; rows up to last_y) where an outline's cells are all
  // free; false if none. rows[r]: the outline's runs of cells [begin, end) in its row r.
  bool first_fit(const std::vector<std::vector<std::pair<int, int>>>& rows, int last_y, int& at_x, int& at_y) const {
    const int height = int(rows.size());
    int width = 0;
    std::vector<int> widest_run(rows.size(), 0), order;  // rows with runs, widest run first: they fail soonest
    for (int r = 0; r < height; ++r) {
      for (const auto& run : rows[size_t(r)]) {
        width = std::max(width, run.second);
        widest_run[size_t(r)] = std::max(widest_run[size_t(r)], run.second - run.first);
      }
      if (widest_run[size_t(r)] > 0) order.push_back(r);
    }
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return widest_run[size_t(a)] > widest_run[size_t(b)]; });
    for (int y = 0; y + height <= side_ && y <= last_y; ++y) {
      // Rows whose widest free stretch is too narrow rule out this y at once (most rows of a tiling).
      if (std::any_of(order.begin(), order.end(), [&](int r) { return widest_[size_t(y + r)] < widest_run[size_t(r)]; })) continue;
      for (int x = 0; x + width <= side_;) {
        int skip = 0;
        for (size_t k = 0; k < order.size() && !skip; ++k) {
          const int r = order[k];
          for (const auto& run : rows[size_t(r)]) {
            const int free = run_[index(x + run.first, y + r)];
            if (free >= run.second - run.first) continue;
            skip = free < 0 ? -free : free + 1;  // past the taken cells, or past the one that ends the free ones
            break;
          }
          // The row that failed is tried first from here: nearby places mostly fail there too
          // (every order finds the same place, as every skip passes only places that fail).
          if (skip && k > 0) std::swap(order[k], order[0]);
        }
        if (skip == 0) {
          at_x = x, at_y = y;
          return true;
        }
        x += skip;
      }
    }
    return false;
  }

 private:
  size_t index(int x, int y) const { return size_t(y) * size_t(side_) + size_t(x); }
  using Run = int16_t;  // a grid side is at most kTuning.most_grid_side: half the memory of int
  int side_;
  std::vector<char> taken_;
  std::vector<Run> run_;
  std::vector<int> widest_;  // per row: its longest stretch of free cells
};

// The cells that the triangle touches, as take(y, x0, x1) for each row y in [0, rows) it meets:
// the cells [x0, x1) under the x-extent of the triangle's part in that row (a convex piece, so
// every cell under its extent meets it).
template <class Take>
void for_each_touched_row(const Eigen::Vector2d p[3], int rows, Take take) {
  const double low = std::min({p[0].y(), p[1].y(), p[2].y()}), high = std::max({p[0].y(), p[1].y(), p[2].y()});
  for (int y = std::max(int(std::floor(low)), 0); y <= std::min(int(std::floor(high)), rows - 1); ++y) {
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
    if (x0 <= x1) take(y, int(std::floor(x0)), int(std::floor(x1)) + 1);
  }
}

inline void take_triangle(TexelGrid& grid, const Eigen::Vector2d p[3]) {
  for_each_touched_row(p, grid.side(), [&grid](int y, int x0, int x1) { grid.take(x0, y, x1, y + 1); });
}

}  // namespace lowstretch
