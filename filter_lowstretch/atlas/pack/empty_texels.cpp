#include "atlas/pack/empty_texels.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>

#include "atlas/base/tuning.h"
#include "atlas/chart_map/chart_threads.h"
#include "atlas/pack/chart_outlines.h"
#include "atlas/pack/texel_grid.h"
#include "core/stretch.h"

namespace lowstretch {

namespace {

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
  grid.take_border(frame.gutter);
  return area_3d > 0 ? uv_area / area_3d : 0;
}

// Which turning of a chart is placed: the one whose lowest free place has the lowest bottom, or
// the lowest top (then the leftmost).
enum class Lowest { Bottom, Top };

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
  grid.recount_widest(y - gutter, y + int(best.rows.size()) + gutter);
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

// Longest box side sum first, at one texel density (the order xatlas packs in): a ring or a long
// strip, large for its area, is placed while there is room for it, and smaller charts then fill
// its hole or run beside it.
std::vector<int> longer_box_first(const std::vector<SolvedChart>& charts, std::vector<int> order) {
  std::vector<double> sides(charts.size(), 0);
  for (const int i : order) {
    const SolvedChart& c = charts[size_t(i)];
    const double own = c.uv_area();
    if (own > 0) sides[size_t(i)] = c.box.sizes().sum() * std::sqrt(c.kept.area_3d / own);
  }
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return sides[size_t(a)] > sides[size_t(b)]; });
  return order;
}

// The densest layout the grid holds, to a ratio of 2^(1/2^bisections), or 0 if none: at `full`
// the charts would cover every cell. `fits(density)` lays the charts out; the last call that
// returned true is at the density returned.
template <class Fits>
double densest_that_fits(const Fits& fits, double full, double start) {
  const double step = std::pow(2.0, std::ldexp(1.0, -kTuning.packing_bisections));
  double low = 0, high = 0;  // all fit at low, not at high
  if (start > 0 && start < full) {
    // Near a density that held nearly these charts (a repair's next round): steps up or down
    // from it, each the square of the last, until the fit changes.
    const bool up = fits(start);
    double near = start, ratio = step;
    for (int tries = 0; tries < kTuning.packing_bisections + kTuning.most_packing_halvings && !(low > 0); ++tries, ratio *= ratio) {
      const double next = up ? std::min(near * ratio, full) : near / ratio;
      if (fits(next) != up) low = up ? near : next, high = up ? next : near;
      else if (up && next == full) low = high = full;
      near = next;
    }
  }
  if (!(low > 0)) {  // halving from full until all fit
    high = full, low = high / 2;
    for (int halving = 0; !fits(low); ++halving) {
      if (halving == kTuning.most_packing_halvings) return 0;
      high = low;
      low /= 2;
    }
  }
  while (high / low > step * (1 + 1e-9)) {
    const double middle = std::sqrt(low * high);
    if (fits(middle)) low = middle;
    else high = middle;
  }
  return low;
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

namespace {

// One density's tries of a layout by outline: each order (larger first; longest box first, only
// where the first leaves a chart without room), each with either way of choosing a turning (each
// fills some layouts better than the others), the two turnings at once on the thread pool; the
// first try that fits is kept.
struct OutlineTries {
  const std::vector<SolvedChart>& charts;
  GridFrame frame;
  TexelGrid empty;
  std::array<std::vector<int>, 2> orders;
  double area_3d = 0;

  OutlineTries(const std::vector<SolvedChart>& charts, const ChartOptions& options)
      : charts(charts), frame(grid_frame(options)), empty(frame.side) {
    empty.take_border(frame.gutter);
    std::vector<int> all(charts.size());
    std::iota(all.begin(), all.end(), 0);
    orders = {{larger_first(charts, all), longer_box_first(charts, all)}};
    for (const SolvedChart& c : charts) area_3d += c.kept.area_3d;
  }
  bool any_room() const { return area_3d > 0 && frame.side - 2.0 * frame.gutter > 0; }
  // The density at which the charts would cover every cell inside the border's gutter.
  double full_density() const {
    const double inside = frame.side - 2.0 * frame.gutter;
    return inside * inside / area_3d;
  }
  // Where every chart is laid out at `density`, the share of the texture they cover.
  double coverage_at(double density) const { return density * area_3d / (frame.scale * frame.scale); }

  // Whether all charts fit at density `at`: if so, `corner_uv` and `face_chart` with their corners
  // and charts written are moved into `fitted_uv` and `fitted_chart`.
  bool fit(double at, const Eigen::MatrixXd& corner_uv, const std::vector<int>& face_chart, Eigen::MatrixXd& fitted_uv,
           std::vector<int>& fitted_chart) const {
    Outlines outlines(charts, at, frame.side);
    outlines.draw_all();
    for (const std::vector<int>& order : orders) {
      struct Try {
        Eigen::MatrixXd corner_uv;
        std::vector<int> face_chart;
        bool fits = false;
      };
      std::array<Try, 2> tries{{{corner_uv, face_chart}, {corner_uv, face_chart}}};
      for_each_index(2, [&](int i, int) {
        TexelGrid grid = empty;
        Try& t = tries[size_t(i)];
        t.fits = place_in_order(charts, order, outlines, frame, i == 0 ? Lowest::Bottom : Lowest::Top, true, grid, t.corner_uv,
                                t.face_chart).empty();
      });
      for (Try& t : tries)
        if (t.fits) {
          fitted_uv = std::move(t.corner_uv);
          fitted_chart = std::move(t.face_chart);
          return true;
        }
    }
    return false;
  }
};

}  // namespace

bool pack_by_outline(const std::vector<SolvedChart>& charts, const ChartOptions& options, Eigen::MatrixXd& corner_uv,
                     std::vector<int>& face_chart, double& density) {
  const OutlineTries tries(charts, options);
  if (!tries.any_room()) return false;
  Eigen::MatrixXd best_uv;
  std::vector<int> best_chart;
  const auto fits = [&](double at) { return tries.fit(at, corner_uv, face_chart, best_uv, best_chart); };
  const double found = densest_that_fits(fits, tries.full_density(), density);
  if (!(found > 0)) return false;
  density = found;
  corner_uv = std::move(best_uv);
  face_chart = std::move(best_chart);
  return true;
}

bool may_cover_by_outline(const std::vector<SolvedChart>& charts, const ChartOptions& options, double coverage) {
  const OutlineTries tries(charts, options);
  if (!tries.any_room()) return false;
  if (!(coverage > 0)) return true;
  const double at = coverage / tries.coverage_at(1);
  if (at >= tries.full_density()) return false;  // more cells than there are
  int faces = 0;
  for (const SolvedChart& c : charts)
    for (const int f : c.faces) faces = std::max(faces, f + 1);
  Eigen::MatrixXd fitted_uv;
  std::vector<int> fitted_chart;
  return tries.fit(at, Eigen::MatrixXd::Zero(faces, 6), std::vector<int>(size_t(faces), 0), fitted_uv, fitted_chart);
}

}  // namespace lowstretch
