#include "atlas/chart_map/free_charts.h"

#include <algorithm>
#include <utility>

#include "atlas/base/tuning.h"
#include "atlas/chart_map/boundary_crossing.h"
#include "atlas/chart_map/chart_threads.h"
#include "atlas/chart_map/plane_projection.h"
#include "atlas/chart_map/smallest_box.h"

namespace lowstretch {

namespace {

// The chart's own shape seen along its normal, as a free map (one pass, already the map).
void map_as_seen_along_normal(SolvedChart& chart) {
  chart.free_boundary = true;
  chart.deciding_map = false;
  chart.map = Result();
  chart.map.uv = project_onto_own_plane(chart.mesh.V, chart.mesh.F.topRows(Eigen::Index(chart.faces.size())));
  chart.kept = measure_real_faces(chart.mesh, chart.map.uv);
  chart.passes = {chart.kept};
  PassMetrics only;
  only.l2_stretch = chart.kept.l2_stretch;
  only.flipped = chart.kept.flipped;
  only.degenerate = chart.kept.degenerate;
  chart.map.passes = {only};
  chart.fit_box();
}

// Maps the chart free, with the natural boundary and (unless natural_only) as seen along its
// normal, and keeps the map that scores highest above `to_beat`, if it has no flipped or zero-area
// triangle and its outline does not cross itself. Whether one was kept.
template <class Score>
bool keep_best_free_map(SolvedChart& chart, const Options& solve, double to_beat, Score score, bool natural_only = false) {
  bool kept = false;
  for (const bool seen_along_normal : {false, true}) {
    if (seen_along_normal && natural_only) break;
    SolvedChart free = unmapped_copy(chart);
    if (seen_along_normal) map_as_seen_along_normal(free);
    else solve_onto(free, solve, 0, true);
    if (free.map.error || free.kept.flipped + free.kept.degenerate > 0) continue;
    const double scored = score(free);
    if (!(scored > to_beat) || crosses_itself(free)) continue;
    to_beat = scored;
    chart = std::move(free);
    kept = true;
  }
  return kept;
}

// A free chart turned in its plane so that its box is smallest.
void turn_to_smallest_box(SolvedChart& chart) {
  if (!chart.free_boundary || chart.map.error) return;
  chart.map.uv = turned_to_smallest_box(chart.map.uv, chart.mesh.F.topRows(Eigen::Index(chart.faces.size())));
  chart.fit_box();
}

// What a chart's map makes of its box: fill / L2^2 (a rectangle with a closed hole fills less than 1).
double box_use(const SolvedChart& c) {
  return c.kept.flipped + c.kept.degenerate > 0 ? 0 : c.fill() / (c.kept.l2_stretch * c.kept.l2_stretch);
}

}  // namespace

SolvedChart unmapped_copy(const SolvedChart& chart) {
  SolvedChart copy;
  copy.mesh = chart.mesh;
  copy.faces = chart.faces;
  copy.kept_whole = chart.kept_whole;
  return copy;
}

bool crosses_itself(const SolvedChart& free) {
  return uv_boundary_crosses_itself(free.mesh.F.topRows(Eigen::Index(free.faces.size())), free.map.uv);
}

void free_the_charts_that_stretch(std::vector<SolvedChart>& charts, const ChartOptions& options, double must_pay) {
  std::vector<int> above;
  // A free map covers at most its box at L2 at least 1: it can pay only below 1 / must_pay.
  for (size_t i = 0; i < charts.size(); ++i)
    if (!(box_use(charts[i]) * must_pay > 1)) above.push_back(int(i));
  size_t above_faces = 0;
  for (const int i : above) above_faces += charts[size_t(i)].faces.size();
  for_each_index(int(above.size()), [&](int k, int) {
    SolvedChart& chart = charts[size_t(above[size_t(k)])];
    keep_best_free_map(chart, for_share(options.disk, chart.faces.size(), above_faces), must_pay * box_use(chart), box_use);
  });
}

int free_where_it_stretches_less(std::vector<SolvedChart>& charts, const ChartOptions& options) {
  size_t faces = 0;
  for (const SolvedChart& c : charts) faces += c.faces.size();
  std::vector<char> freed(charts.size(), 0);
  for_each_index(int(charts.size()), [&](int k, int) {
    SolvedChart& chart = charts[size_t(k)];
    if (!may_free_for_less_stretch(chart)) return;
    const auto less_stretch = [](const SolvedChart& c) { return -c.kept.l2_stretch; };
    Options solve = for_share(options.disk, chart.faces.size(), faces);
    solve.refine_moves_boundary = true;  // where refined: less stretch still (refine_free_outlines)
    freed[size_t(k)] = keep_best_free_map(chart, solve, less_stretch(chart), less_stretch);
    turn_to_smallest_box(chart);
  });
  return int(std::count(freed.begin(), freed.end(), 1));
}

bool may_free_for_less_stretch(const SolvedChart& chart) { return !chart.free_boundary && chart.kept.l2_stretch > kTuning.free_above; }

void refine_free_outlines(std::vector<SolvedChart>& charts, const ChartOptions& options) {
  if (!options.disk.refine) return;
  size_t faces = 0;
  for (const SolvedChart& c : charts)
    if (c.free_boundary) faces += c.faces.size();
  for_each_index(int(charts.size()), [&](int k, int) {
    SolvedChart& chart = charts[size_t(k)];
    if (!chart.free_boundary || chart.map.error) return;
    Options moving = for_share(options.disk, chart.faces.size(), faces);
    moving.refine_moves_boundary = true;
    keep_best_free_map(chart, moving, box_use(chart), box_use, true);
  });
}

void see_flat_charts_along_normal(std::vector<SolvedChart>& charts) {
  for_each_index(int(charts.size()), [&](int k, int) {
    SolvedChart& chart = charts[size_t(k)];
    if (chart.free_boundary) return;
    SolvedChart seen = unmapped_copy(chart);
    map_as_seen_along_normal(seen);
    if (seen.kept.flipped + seen.kept.degenerate > 0 || !(seen.kept.l2_stretch <= kTuning.flat_below) ||
        !(seen.kept.l2_stretch < chart.kept.l2_stretch))
      return;
    if (crosses_itself(seen)) return;
    chart = std::move(seen);
  });
}

void turn_free_charts_to_smallest_box(std::vector<SolvedChart>& charts) {
  for_each_index(int(charts.size()), [&](int k, int) { turn_to_smallest_box(charts[size_t(k)]); });
}

}  // namespace lowstretch
