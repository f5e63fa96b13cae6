// The texture's texels as a grid of taken and free cells, for packing charts by their outlines:
// which cells a triangle touches, and where an outline first fits.
#pragma once
#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

namespace lowstretch {

// Which cells of a square grid are taken (a chart, or within the gutter of one), a bit each, 64
// cells of a row to a word (as xatlas's BitImage): a run of an outline is tested a word at a time,
// and copying the grid for another try is cheap. For each row, its longest stretch of free cells.
class TexelGrid {
 public:
  explicit TexelGrid(int side)
      : side_(side), words_(size_t(side + 63) / 64), bits_(size_t(side) * words_, 0), widest_(size_t(side), side) {}
  int side() const { return side_; }
  void take(int x0, int y0, int x1, int y1) {  // cells [x0, x1) x [y0, y1), clipped
    x0 = std::max(x0, 0), y0 = std::max(y0, 0), x1 = std::min(x1, side_), y1 = std::min(y1, side_);
    for (int y = y0; y < y1 && x0 < x1; ++y) {
      Word* row = row_of(y);
      for (int w = x0 / 64; w <= (x1 - 1) / 64; ++w) row[w] |= mask(x0 - 64 * w, x1 - 64 * w);
    }
  }
  // Takes the cells within `gutter` of the border, and recounts the longest free stretch of every row.
  void take_border(int gutter) {
    take(0, 0, side_, gutter);
    take(0, side_ - gutter, side_, side_);
    take(0, 0, gutter, side_);
    take(side_ - gutter, 0, side_, side_);
    recount_widest(0, side_);
  }
  // Takes every cell within `by` cells of a taken one (a square around each): each row ORed with
  // itself shifted up to `by` cells either way, then with the rows up to `by` above and below.
  void grow(int by) {
    std::vector<Word> before(words_), grown(bits_.size());
    for (int y = 0; y < side_; ++y) {
      Word* row = row_of(y);
      std::copy(row, row + words_, before.begin());
      for (int shift = 1; shift <= by && shift < side_; ++shift)
        for (size_t w = 0; w < words_; ++w) row[w] |= shifted(before, w, shift) | shifted(before, w, -shift);
      row[words_ - 1] &= mask(0, side_ - 64 * int(words_ - 1));  // no cell past the side
    }
    for (int y = 0; y < side_; ++y) {
      Word* out = grown.data() + size_t(y) * words_;
      for (int near = std::max(0, y - by); near <= std::min(side_ - 1, y + by); ++near)
        for (size_t w = 0; w < words_; ++w) out[w] |= row_of(near)[w];
    }
    bits_.swap(grown);
  }
  // Counts the longest free stretch of rows [y0, y1) after cells were taken there.
  void recount_widest(int y0, int y1) {
    for (int y = std::max(y0, 0); y < std::min(y1, side_); ++y) widest_[size_t(y)] = widest_free(y);
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
            const int taken = last_taken(y + r, x + run.first, x + run.second);
            if (taken < 0) continue;
            // Every place until the run starts past the taken cells from there covers one of them.
            skip = first_free(y + r, taken) - (x + run.first);
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
  using Word = uint64_t;
  Word* row_of(int y) { return bits_.data() + size_t(y) * words_; }
  const Word* row_of(int y) const { return bits_.data() + size_t(y) * words_; }
  // The bits of cells [a, b) of a word, a and b clipped to [0, 64].
  static Word mask(int a, int b) {
    a = std::max(a, 0), b = std::min(b, 64);
    if (a >= b) return 0;
    const Word upto_b = b == 64 ? ~Word(0) : (Word(1) << b) - 1;
    return upto_b & ~((Word(1) << a) - 1);
  }
  // Word w of a row moved `by` cells towards higher x (lower, if negative).
  static Word shifted(const std::vector<Word>& row, size_t w, int by) {
    const long from = long(w) * 64 - by;  // the cell that lands on the word's first bit
    const long q = from >= 0 ? from / 64 : -((63 - from) / 64), r = from - 64 * q;
    const auto word = [&](long i) { return i >= 0 && i < long(row.size()) ? row[size_t(i)] : Word(0); };
    return r == 0 ? word(q) : word(q) >> r | word(q + 1) << (64 - r);
  }
  // The last taken cell of row y in [x0, x1), or -1: the end words masked, the middle ones whole.
  int last_taken(int y, int x0, int x1) const {
    if (x0 >= x1) return -1;
    const Word* row = row_of(y);
    const int w0 = x0 / 64, w1 = (x1 - 1) / 64;
    const Word from_x0 = ~Word(0) << (x0 % 64), to_x1 = ~Word(0) >> (63 - (x1 - 1) % 64);
    const auto last_in = [](int w, Word hit) { return 64 * w + 63 - __builtin_clzll(hit); };
    if (w0 == w1) {
      const Word hit = row[w0] & from_x0 & to_x1;
      return hit ? last_in(w0, hit) : -1;
    }
    if (const Word hit = row[w1] & to_x1) return last_in(w1, hit);
    for (int w = w1 - 1; w > w0; --w)
      if (row[w]) return last_in(w, row[w]);
    const Word hit = row[w0] & from_x0;
    return hit ? last_in(w0, hit) : -1;
  }
  // The first free cell of row y from x on, or the side.
  int first_free(int y, int x) const {
    const Word* row = row_of(y);
    for (int w = x / 64; w < int(words_); ++w)
      if (const Word free = ~row[w] & mask(x - 64 * w, 64)) return std::min(side_, 64 * w + __builtin_ctzll(free));
    return side_;
  }
  // The longest stretch of free cells in row y.
  int widest_free(int y) const {
    const Word* row = row_of(y);
    int widest = 0, run = 0;
    for (int x = 0; x < side_;) {
      const int w = x / 64, bit = x % 64;
      const Word rest = row[w] >> bit;  // the cells from x to the word's end, low bit first
      const int left = std::min(64, side_ - 64 * w) - bit;
      const int free = rest == 0 ? left : std::min(left, __builtin_ctzll(rest));
      run += free, x += free;
      if (free == left) continue;
      widest = std::max(widest, run);
      run = 0;
      const Word ones = ~(row[w] >> (x % 64));
      x += ones == 0 ? 64 - x % 64 : __builtin_ctzll(ones);
    }
    return std::max(widest, run);
  }
  int side_;
  size_t words_;
  std::vector<Word> bits_;
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
