// Charts drawn as the texels their triangles touch, at one texel density and quarter turn: what
// the outline packer places.
#pragma once
#include <Eigen/Core>
#include <array>
#include <cmath>
#include <utility>
#include <vector>

#include "atlas/base/tuning.h"
#include "atlas/chart_map/chart_threads.h"
#include "atlas/chart_map/solved_chart.h"

namespace lowstretch {

// A guest at one quarter turn and texel density: its corners in cells from its box's corner
// (3 per real face), and the cells its triangles touch as runs per row.
struct Outline {
  std::vector<Eigen::Vector2d> corners;
  std::vector<std::vector<std::pair<int, int>>> rows;
};

Outline outline_of(const SolvedChart& chart, const Eigen::Vector2d& size, int turns);

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
  // Every turning of every chart with room, on the thread pool: then `at` only reads, from any thread.
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

}  // namespace lowstretch
