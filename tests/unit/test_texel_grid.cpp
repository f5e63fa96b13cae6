// The packing grid against a plain cell-by-cell model: where an outline first fits (lowest row,
// then column), cells taken across word boundaries, and the gutter grown around taken cells.
#include <gtest/gtest.h>

#include <random>
#include <utility>
#include <vector>

#include "atlas/pack/texel_grid.h"

using namespace lowstretch;

namespace {

using Rows = std::vector<std::vector<std::pair<int, int>>>;

// The same grid as plain cells.
struct Cells {
  int side;
  std::vector<char> taken;
  explicit Cells(int side) : side(side), taken(size_t(side * side), 0) {}
  char& at(int x, int y) { return taken[size_t(y * side + x)]; }
  void take(int x0, int y0, int x1, int y1) {
    for (int y = std::max(y0, 0); y < std::min(y1, side); ++y)
      for (int x = std::max(x0, 0); x < std::min(x1, side); ++x) at(x, y) = 1;
  }
  void grow(int by) {
    const std::vector<char> before = taken;
    for (int y = 0; y < side; ++y)
      for (int x = 0; x < side; ++x)
        for (int dy = -by; dy <= by && !at(x, y); ++dy)
          for (int dx = -by; dx <= by; ++dx) {
            const int u = x + dx, v = y + dy;
            if (u >= 0 && v >= 0 && u < side && v < side && before[size_t(v * side + u)]) {
              at(x, y) = 1;
              break;
            }
          }
  }
  bool first_fit(const Rows& rows, int last_y, int& at_x, int& at_y) {
    int width = 0;
    for (const auto& row : rows)
      for (const auto& run : row) width = std::max(width, run.second);
    for (int y = 0; y + int(rows.size()) <= side && y <= last_y; ++y)
      for (int x = 0; x + width <= side; ++x) {
        bool fits = true;
        for (size_t r = 0; r < rows.size() && fits; ++r)
          for (const auto& run : rows[r])
            for (int c = run.first; c < run.second && fits; ++c) fits = !at(x + c, y + int(r));
        if (fits) {
          at_x = x, at_y = y;
          return true;
        }
      }
    return false;
  }
};

// An outline of `height` rows, each one or two runs, some wider than a word.
Rows random_outline(std::mt19937& random, int height, int most_width) {
  Rows rows(static_cast<size_t>(height), std::vector<std::pair<int, int>>());
  std::uniform_int_distribution<int> width(1, most_width);
  for (auto& row : rows) {
    const int a = width(random) / 3, b = a + width(random);
    row.push_back({a, b});
    if (random() % 3 == 0) row.push_back({b + 2, b + 2 + width(random) / 4 + 1});
  }
  return rows;
}

}  // namespace

TEST(TexelGrid, OutlinesGoWhereAPlainCellSearchPutsThem) {
  std::mt19937 random(7);
  for (const int side : {64, 100, 200}) {
    for (const int gutter : {0, 1, 3}) {
      TexelGrid grid(side);
      Cells cells(side);
      std::uniform_int_distribution<int> at(0, side - 1), size(1, 40);
      for (int k = 0; k < 12; ++k) {  // taken boxes, grown by the gutter
        const int x = at(random), y = at(random), w = size(random), h = size(random) / 4 + 1;
        grid.take(x, y, x + w, y + h);
        cells.take(x, y, x + w, y + h);
      }
      grid.grow(gutter);
      cells.grow(gutter);
      grid.take_border(gutter);
      cells.take(0, 0, side, gutter), cells.take(0, side - gutter, side, side);
      cells.take(0, 0, gutter, side), cells.take(side - gutter, 0, side, side);
      for (int k = 0; k < 30; ++k) {  // outlines placed one after another, each taking its cells
        const Rows rows = random_outline(random, 1 + int(random() % 12), 90);
        int x = -1, y = -1, want_x = -1, want_y = -1;
        const bool fits = grid.first_fit(rows, side, x, y), want = cells.first_fit(rows, side, want_x, want_y);
        ASSERT_EQ(fits, want) << "side " << side << " gutter " << gutter << " outline " << k;
        if (!fits) continue;
        ASSERT_EQ(std::make_pair(x, y), std::make_pair(want_x, want_y)) << "side " << side << " outline " << k;
        for (size_t r = 0; r < rows.size(); ++r)
          for (const auto& run : rows[r]) {
            grid.take(x + run.first, y + int(r), x + run.second, y + int(r) + 1);
            cells.take(x + run.first, y + int(r), x + run.second, y + int(r) + 1);
          }
        grid.recount_widest(y, y + int(rows.size()));
      }
    }
  }
}

TEST(TexelGrid, RowsAboveLastYAreNotSearched) {
  TexelGrid grid(128);
  grid.take_border(0);
  grid.take(0, 0, 128, 50);  // the first 50 rows full
  grid.recount_widest(0, 50);
  const Rows box(4, {{0, 70}});
  int x = 0, y = 0;
  EXPECT_FALSE(grid.first_fit(box, 49, x, y));
  ASSERT_TRUE(grid.first_fit(box, 50, x, y));
  EXPECT_EQ(std::make_pair(x, y), std::make_pair(0, 50));
}
