#include "atlas/pack/empty_texels.h"

#include <algorithm>
#include <array>
#include <cassert>
#include <cstdint>
#include <cstring>
#include <cmath>
#include <limits>
#include <numeric>

#include "atlas/base/tuning.h"
#include "atlas/chart_map/chart_threads.h"
#include "core/stretch.h"

namespace lowstretch {

namespace {

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
        for (const int r : order) {
          for (const auto& run : rows[size_t(r)]) {
            const int free = run_[index(x + run.first, y + r)];
            if (free >= run.second - run.first) continue;
            skip = free < 0 ? -free : free + 1;  // past the taken cells, or past the one that ends the free ones
            break;
          }
          if (skip) break;
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

void take_triangle(TexelGrid& grid, const Eigen::Vector2d p[3]) {
  for_each_touched_row(p, grid.side(), [&grid](int y, int x0, int x1) { grid.take(x0, y, x1, y + 1); });
}

// A guest at one quarter turn and texel density: its corners in cells from its box's corner
// (3 per real face), and the cells its triangles touch as runs per row.
struct Outline {
  std::vector<Eigen::Vector2d> corners;
  std::vector<std::vector<std::pair<int, int>>> rows;
};

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

// The cell area that charts not filling their box are expected to leave empty.
double expected_empty_area(const std::vector<SolvedChart>& charts, const std::vector<double>& own_area) {
  double empty = 0;
  for (size_t i = 0; i < charts.size(); ++i)
    if (charts[i].leaves_box_empty()) empty += own_area[i] * (1 - charts[i].fill());
  return empty;
}

// The texel grid of the layout: [0,1]^2 -> grid cells, as store() moves the layout inside the gutter.
struct GridFrame {
  int side = 0;       // cells per side
  int gutter = 0;     // in cells
  double offset = 0, scale = 1;
};

// The texture's grid, at most kTuning.most_grid_side cells a side.
GridFrame grid_frame(const ChartOptions& options) {
  GridFrame frame;
  frame.side = std::min(options.texture_size, kTuning.most_grid_side);
  const double texel = double(options.texture_size) / frame.side;  // texels per grid cell
  frame.gutter = int(std::ceil(options.gutter / texel));
  frame.offset = options.gutter / texel;
  frame.scale = (options.texture_size - 2 * options.gutter) / texel;
  return frame;
}

// Takes the border's gutter, and counts the free runs of every row.
void take_border(const GridFrame& frame, TexelGrid& grid) {
  const int side = frame.side, gutter = frame.gutter;
  grid.take(0, 0, side, gutter);
  grid.take(0, side - gutter, side, side);
  grid.take(0, 0, gutter, side);
  grid.take(side - gutter, 0, side, side);
  grid.count_runs(0, side);
}

// Takes the cells of the tiled charts (not the guests), grown by the gutter, and the border's
// gutter; returns their texel density, in grid cells^2 per unit of 3D area.
double take_tiled_charts(const std::vector<SolvedChart>& charts, const std::vector<char>& is_guest,
                         const Eigen::MatrixXd& corner_uv, const GridFrame& frame, TexelGrid& grid) {
  double uv_area = 0, area_3d = 0;
  for (size_t c = 0; c < charts.size(); ++c) {
    if (is_guest[c]) continue;
    area_3d += charts[c].kept.area_3d;
    for (const int f : charts[c].faces) {
      Eigen::Vector2d p[3];
      for (int k = 0; k < 3; ++k) p[k] = frame.offset + frame.scale * corner_uv.block(f, 2 * k, 1, 2).transpose().array();
      uv_area += std::abs(signed_uv_area(p[0], p[1], p[2]));
      take_triangle(grid, p);
    }
  }
  // From here a taken cell is one a guest may not use.
  grid.grow(frame.gutter);
  take_border(frame, grid);
  return area_3d > 0 ? uv_area / area_3d : 0;
}

// Which turning of a chart is placed: the one whose lowest free place has the lowest bottom, or
// the lowest top (then the leftmost).
enum class Lowest { Bottom, Top };

// The charts' outlines at one texel density, each turning drawn when first asked for, or all
// at once (draw_all): every try of a density places the same charts, turned either way (Lowest).
class Outlines {
 public:
  // density: grid cells^2 per unit of 3D area; side: the grid's cells a side.
  Outlines(const std::vector<SolvedChart>& charts, double density, int side)
      : charts_(charts),
        size_(charts.size(), Eigen::Vector2d::Zero()),
        turnings_(charts.size(), 4),
        drawn_(charts.size()),
        is_drawn_(charts.size()) {
    for (size_t c = 0; c < charts.size(); ++c) {
      // A box looks the same half a turn round; an outline may fit into other room. (Once here:
      // fill() sums the chart's UV area, and every try asks for each chart's turnings.)
      if (charts[c].fill() >= kTuning.least_guest_fill) turnings_[c] = 2;
      const double own = charts[c].uv_area();
      if (density > 0 && own > 0 && charts[c].box.sizes().minCoeff() > 0)
        size_[c] = charts[c].box.sizes() * std::sqrt(density * charts[c].kept.area_3d / own);
      // A sliver longer than the texture (or a degenerate map) has no room.
      if (!(size_[c].minCoeff() > 0 && size_[c].maxCoeff() <= side)) size_[c].setZero();
    }
  }
  // Whether chart c could fit on the grid at all (its outline is drawn only then).
  bool has_room(int c) const { return size_[size_t(c)].minCoeff() > 0; }
  int turnings(int c) const { return turnings_[size_t(c)]; }
  // Every turning of every chart with room, on both cores: then `at` only reads, from any thread.
  void draw_all() {
    for_each_index(int(charts_.size()), [this](int c, int) {
      for (int turns = 0; has_room(c) && turns < turnings(c); ++turns) at(c, turns);
    });
  }
  const Outline& at(int c, int turns) {
    if (!is_drawn_[size_t(c)][size_t(turns)]) {
      drawn_[size_t(c)][size_t(turns)] = outline_of(charts_[size_t(c)], size_[size_t(c)], turns);
      is_drawn_[size_t(c)][size_t(turns)] = true;
    }
    return drawn_[size_t(c)][size_t(turns)];
  }

 private:
  const std::vector<SolvedChart>& charts_;
  std::vector<Eigen::Vector2d> size_;
  std::vector<int> turnings_;
  std::vector<std::array<Outline, 4>> drawn_;
  std::vector<std::array<bool, 4>> is_drawn_;
};

// The free place of chart c's outline over its turnings: the lowest (`lowest`), then the leftmost.
const Outline* find_place(const TexelGrid& grid, int c, Outlines& outlines, int side, Lowest lowest,
                          int& best_x, int& best_y) {
  const Outline* best = nullptr;
  int best_key = 0;
  for (int turns = 0; turns < outlines.turnings(c); ++turns) {
    const Outline& outline = outlines.at(c, turns);
    const int above = lowest == Lowest::Top ? int(outline.rows.size()) : 0;  // from the bottom to the key
    const int last_y = best ? best_key - above : side;
    int x = 0, y = 0;
    if (last_y < 0 || !grid.first_fit(outline.rows, last_y, x, y)) continue;
    if (!best || std::make_pair(y + above, x) < std::make_pair(best_key, best_x))
      best_x = x, best_y = y, best_key = y + above, best = &outline;
  }
  return best;
}

// Takes the place's cells (grown by the gutter) and moves the chart's corners there.
void place_guest(const SolvedChart& chart, int g, const Outline& best, int x, int y, const GridFrame& frame,
                 TexelGrid& grid, Eigen::MatrixXd& corner_uv, std::vector<int>& face_chart) {
  const int gutter = frame.gutter;
  for (size_t r = 0; r < best.rows.size(); ++r)
    for (const auto& run : best.rows[r])
      grid.take(x + run.first - gutter, y + int(r) - gutter, x + run.second + gutter, y + int(r) + 1 + gutter);
  int x0 = grid.side(), x1 = 0;
  for (const auto& row : best.rows)
    for (const auto& run : row) x0 = std::min(x0, run.first), x1 = std::max(x1, run.second);
  grid.count_runs(y - gutter, y + int(best.rows.size()) + gutter, x + x0 - gutter, x + x1 + gutter);
  const Eigen::Vector2d origin(x, y);
  for (size_t j = 0; j < chart.faces.size(); ++j) {
    const int f = chart.faces[j];
    face_chart[size_t(f)] = g;
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector2d in_cells = origin + best.corners[3 * j + size_t(k)];
      corner_uv.block(f, 2 * k, 1, 2) = ((in_cells.array() - frame.offset) / frame.scale).matrix().transpose();
    }
  }
}

}  // namespace

double expected_empty_share(const std::vector<SolvedChart>& charts, const std::vector<double>& own_area) {
  const double total = std::accumulate(own_area.begin(), own_area.end(), 0.0);
  return total > 0 ? expected_empty_area(charts, own_area) / total : 0;
}

std::vector<int> charts_to_put_in_empty_texels(const std::vector<SolvedChart>& charts, const std::vector<double>& own_area,
                                               const GuestChoice& choice) {
  const double empty = expected_empty_area(charts, own_area);
  std::vector<int> candidates;
  for (size_t i = 0; i < charts.size(); ++i)
    if (choice.any_shape || (!charts[i].leaves_box_empty() && charts[i].fill() >= kTuning.least_guest_fill)) candidates.push_back(int(i));
  std::stable_sort(candidates.begin(), candidates.end(), [&](int a, int b) { return own_area[size_t(a)] < own_area[size_t(b)]; });
  std::vector<int> guests;
  double taken = 0;  // texels of the guests' own triangles
  for (const int i : candidates) {
    taken += own_area[size_t(i)] * std::min(1.0, charts[size_t(i)].fill());
    if (taken > choice.share_of_empty * empty) break;
    guests.push_back(i);
  }
  return guests;
}

namespace {

// Places the charts of `order` at the outlines' density where each first fits; those that find
// no room are returned, or, if `stop_at_first`, only the first of them.
std::vector<int> place_in_order(const std::vector<SolvedChart>& charts, const std::vector<int>& order, Outlines& outlines,
                                const GridFrame& frame, Lowest lowest, bool stop_at_first, TexelGrid& grid,
                                Eigen::MatrixXd& corner_uv, std::vector<int>& face_chart) {
  std::vector<int> unplaced;
  for (const int g : order) {
    const SolvedChart& chart = charts[size_t(g)];
    const Outline* best = nullptr;
    int x = 0, y = 0;
    if (outlines.has_room(g)) best = find_place(grid, g, outlines, frame.side, lowest, x, y);
    if (!best) {
      unplaced.push_back(g);
      if (stop_at_first) break;
      continue;
    }
    place_guest(chart, g, *best, x, y, frame, grid, corner_uv, face_chart);
  }
  return unplaced;
}

// Largest first: small charts fill the room large ones leave.
std::vector<int> larger_first(const std::vector<SolvedChart>& charts, std::vector<int> order) {
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return charts[size_t(a)].kept.area_3d > charts[size_t(b)].kept.area_3d; });
  return order;
}

}  // namespace

std::vector<int> put_in_empty_texels(const std::vector<SolvedChart>& charts, const std::vector<int>& guests,
                                     const ChartOptions& options, Eigen::MatrixXd& corner_uv, std::vector<int>& face_chart) {
  const GridFrame frame = grid_frame(options);
  std::vector<char> is_guest(charts.size(), 0);
  for (const int i : guests) is_guest[size_t(i)] = 1;
  TexelGrid grid(frame.side);
  Outlines outlines(charts, take_tiled_charts(charts, is_guest, corner_uv, frame, grid), grid.side());
  return place_in_order(charts, larger_first(charts, guests), outlines, frame, Lowest::Bottom, false, grid, corner_uv, face_chart);
}

bool pack_by_outline(const std::vector<SolvedChart>& charts, const ChartOptions& options, Eigen::MatrixXd& corner_uv,
                     std::vector<int>& face_chart) {
  const GridFrame frame = grid_frame(options);
  TexelGrid empty(frame.side);
  take_border(frame, empty);
  std::vector<int> all(charts.size());
  std::iota(all.begin(), all.end(), 0);
  const std::vector<int> order = larger_first(charts, all);
  double area_3d = 0;
  for (const SolvedChart& c : charts) area_3d += c.kept.area_3d;
  const double inside = frame.side - 2.0 * frame.gutter;
  if (!(area_3d > 0) || !(inside > 0)) return false;
  Eigen::MatrixXd best_uv;
  std::vector<int> best_chart;
  // Either way of choosing a turning: each fills some layouts better than the other. Both are
  // tried at once, each on a core; the lowest bottom is kept where both fit.
  struct Try {
    Eigen::MatrixXd corner_uv;
    std::vector<int> face_chart;
    bool fits = false;
  };
  const auto fits = [&](double density) {
    Outlines outlines(charts, density, frame.side);
    outlines.draw_all();
    std::array<Try, 2> tries{{{corner_uv, face_chart}, {corner_uv, face_chart}}};
    for_each_index(2, [&](int i, int) {
      TexelGrid grid = empty;
      Try& t = tries[size_t(i)];
      t.fits = place_in_order(charts, order, outlines, frame, i == 0 ? Lowest::Bottom : Lowest::Top, true, grid, t.corner_uv,
                              t.face_chart).empty();
    });
    for (Try& t : tries)
      if (t.fits) {
        best_uv = std::move(t.corner_uv);
        best_chart = std::move(t.face_chart);
        return true;
      }
    return false;
  };
  // The densest layout the grid holds, found by bisection: at `high` the charts would cover every
  // cell; halving the density until all fit, then narrowing down.
  double high = inside * inside / area_3d, low = high / 2;
  for (int halving = 0; !fits(low); ++halving) {
    if (halving == kTuning.most_packing_halvings) return false;
    high = low;
    low /= 2;
  }
  for (int step = 0; step < kTuning.packing_bisections; ++step) {
    const double middle = std::sqrt(low * high);
    if (fits(middle)) low = middle;
    else high = middle;
  }
  corner_uv = std::move(best_uv);
  face_chart = std::move(best_chart);
  return true;
}

}  // namespace lowstretch
