// The layouts a candidate atlas gets: tiled (falling back to packing by outline when the cells
// cannot hold its charts), small charts in the texels left empty, every chart packed by outline.
#include <algorithm>
#include <array>
#include <numeric>
#include <string>
#include <type_traits>
#include <utility>

#include "atlas/chart_map/chart_threads.h"
#include "atlas/chart_map/free_charts.h"
#include "atlas/measure/atlas_result.h"
#include "atlas/pack/empty_texels.h"
#include "atlas/pack/lay_out_charts.h"
#include "atlas/search/atlas_search.h"

namespace lowstretch {

namespace {

// The charts' mean of l2_squared(chart) over their 3D area (0 without area).
template <class L2Squared>
double mean_over_area(const std::vector<SolvedChart>& charts, L2Squared l2_squared) {
  double weighted = 0, area = 0;
  for (const SolvedChart& c : charts) {
    weighted += c.kept.area_3d * l2_squared(c);
    area += c.kept.area_3d;
  }
  return area > 0 ? weighted / area : 0;
}

// The charts' mean L2^2 as low as free_where_it_stretches_less could make it: each chart it may
// free at L2 stretch 1 (no map stretches less), the others as they are.
double least_l2_squared_if_freed(const std::vector<SolvedChart>& charts) {
  return mean_over_area(charts, [](const SolvedChart& c) { return may_free_for_less_stretch(c) ? 1 : c.kept.l2_stretch * c.kept.l2_stretch; });
}

}  // namespace

double mean_l2_squared(const std::vector<SolvedChart>& charts) {
  return mean_over_area(charts, [](const SolvedChart& c) { return c.kept.l2_stretch * c.kept.l2_stretch; });
}

void fill_empty_texels(const AtlasSearch& s, const std::vector<SolvedChart>& kept, ChartsResult& tiled) {
  if (kept.empty() || !(tiled.coverage < 1 - kTuning.least_empty_share) ||
      expected_empty_share(kept, cell_areas(kept)) < kTuning.least_empty_share)
    return;
  const double tiled_efficiency = texture_efficiency(tiled);
  std::vector<SolvedChart> flat_seen = kept;
  see_flat_charts_along_normal(flat_seen);
  // Each choice laid out on its own (on the thread pool), then taken in order where it does better.
  constexpr size_t choices = std::extent<decltype(kGuestChoices)>::value;
  std::array<ChartsResult, choices> nested;
  std::array<bool, choices> tried{};
  for_each_index(int(choices), [&](int i, int) {
    const GuestChoice& choice = kGuestChoices[i];
    const std::vector<SolvedChart>& charts = choice.flat_seen_along_normal ? flat_seen : kept;
    const std::vector<int> guests = charts_to_put_in_empty_texels(charts, cell_areas(charts), choice);
    if (guests.empty()) return;
    nested[size_t(i)] = atlas_of(charts, guests, s.unit_V, s.F, s.unit, int(s.V.rows()), s.options);
    tried[size_t(i)] = true;
  });
  for (size_t i = 0; i < choices; ++i) {
    if (!tried[i] || nested[i].error || !(texture_efficiency(nested[i]) > texture_efficiency(tiled))) continue;
    nested[i].notes.push_back(std::string("with small charts in empty texels") +
                              (kGuestChoices[i].flat_seen_along_normal ? " and flat charts as seen along their normal" : "") +
                              " the atlas has efficiency " + number_text(texture_efficiency(nested[i])) +
                              " (coverage / L2^2) against " + number_text(tiled_efficiency));
    tiled = std::move(nested[i]);
  }
}

namespace {

// Every chart placed by its outline (atlas_of with all of them as guests).
ChartsResult packed_whole(const AtlasSearch& s, std::vector<SolvedChart> charts) {
  std::vector<int> all(charts.size());
  std::iota(all.begin(), all.end(), 0);
  return atlas_of(std::move(charts), std::move(all), s.unit_V, s.F, s.unit, int(s.V.rows()), s.options);
}

// The coverage at which charts of their L2 stretch as mapped reach `efficiency`.
double coverage_for(const std::vector<SolvedChart>& charts, double efficiency) { return efficiency * mean_l2_squared(charts); }

// packed_whole, made only where the charts fit at the density that reaches the least efficiency
// with their L2 stretch as mapped (a layout measures the same stretch); a packing below it is of
// no use to the caller, and the search for the densest layout takes many more tries.
ChartsResult packed_whole_if_it_may_reach(const AtlasSearch& s, std::vector<SolvedChart> charts, double least_efficiency) {
  const double coverage = coverage_for(charts, least_efficiency);
  if (least_efficiency > 0 && !may_cover_by_outline(charts, s.options, coverage)) {
    ChartsResult below;
    below.error = {ErrorCode::ChartsNotPacked, static_cast<long long>(charts.size()), ""};
    return below;
  }
  return packed_whole(s, std::move(charts));
}

}  // namespace

ChartsResult packed_by_outline(const AtlasSearch& s, std::vector<SolvedChart> charts, double least_efficiency) {
  map_all_at_own_shape(charts, s.options);  // once for both packings
  std::vector<SolvedChart> flat_seen = charts;
  see_flat_charts_along_normal(flat_seen);
  const auto free_charts = [](const std::vector<SolvedChart>& c) {
    return std::count_if(c.begin(), c.end(), [](const SolvedChart& chart) { return chart.free_boundary; });
  };
  const bool any_flat = free_charts(flat_seen) > free_charts(charts);
  // The packings at once, on the thread pool: a packing is one thread's work.
  ChartsResult packed, flat;
  for_each_index(any_flat ? 2 : 1, [&](int i, int) {
    if (i == 0) packed = packed_whole_if_it_may_reach(s, charts, least_efficiency);
    else flat = packed_whole_if_it_may_reach(s, std::move(flat_seen), least_efficiency);
  });
  if (any_flat && !flat.error && (packed.error || texture_efficiency(flat) > texture_efficiency(packed))) {
    flat.notes.push_back("flat charts as seen along their normal");
    packed = std::move(flat);
  }
  return packed;
}

// A cell per chart, each a few texels wide inside its gutter, cannot hold thousands of tiny charts
// (a scan's debris) on a small texture or with a wide gutter; their outlines need no such floor.
LaidOutCharts AtlasSearch::tile(std::vector<SolvedChart> charts) const {
  LaidOutCharts tiled;
  tiled.atlas = atlas_of(charts, {}, unit_V, F, unit, int(V.rows()), options);
  tiled.charts = std::move(charts);
  if (tiled.atlas.error.code != ErrorCode::ChartsNotPacked) return tiled;
  ChartsResult packed = packed_by_outline(*this, tiled.charts);
  if (packed.error) return tiled;
  packed.notes.push_back(std::to_string(tiled.charts.size()) + " charts are too many for a cell each in the tiling: packed by their outlines");
  tiled.atlas = std::move(packed);
  return tiled;
}

// Free outlines pack less densely than boxes, so charts are freed only if they could win at
// kTuning.most_free_outline_coverage of the coverage the boxes reached (or were asked for, where
// they were given up below the tiling) with the least stretch freeing could leave,
// and packed only if they would with the stretch it left. Free charts are
// turned to their smallest box here only: in the steps before, the texture they would save lets
// merging go further, down to its least efficiency.
void pack_by_outline_if_better(const AtlasSearch& s, const std::vector<SolvedChart>& kept, ChartsResult& laid_out) {
  if (kept.empty() || laid_out.error) return;
  std::vector<SolvedChart> turned = kept;
  map_all_at_own_shape(turned, s.options);  // turned as mapped, and mapped once for every packing
  turn_free_charts_to_smallest_box(turned);
  ChartsResult packed = packed_by_outline(s, turned, texture_efficiency(laid_out));
  std::vector<SolvedChart> freed = std::move(turned);
  const double to_beat = packed.error ? texture_efficiency(laid_out) : std::max(texture_efficiency(packed), texture_efficiency(laid_out));
  // Boxes given up below the tiling reach less than the coverage their probe asked for.
  const double boxes_coverage =
      packed.error ? coverage_for(freed, texture_efficiency(laid_out)) : packed.coverage;
  const double free_coverage = kTuning.most_free_outline_coverage * boxes_coverage;
  const auto free_may_win = [&](double l2_squared) { return free_coverage / l2_squared > to_beat; };
  if (free_may_win(least_l2_squared_if_freed(freed)) && free_where_it_stretches_less(freed, s.options) > 0 &&
      free_may_win(mean_l2_squared(freed))) {
    ChartsResult free = packed_whole_if_it_may_reach(s, std::move(freed), to_beat);
    if (!free.error && (packed.error || texture_efficiency(free) > texture_efficiency(packed))) {
      free.notes.push_back("charts mapped free where that stretches them less");
      packed = std::move(free);
    }
  }
  if (packed.error || !(texture_efficiency(packed) > texture_efficiency(laid_out))) return;
  packed.notes.push_back("every chart packed by its outline: efficiency " + number_text(texture_efficiency(packed)) +
                         " (coverage / L2^2) against " + number_text(texture_efficiency(laid_out)) + " tiled");
  laid_out = std::move(packed);
}

}  // namespace lowstretch
