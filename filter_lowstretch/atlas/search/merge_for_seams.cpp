// Merging the best atlas's charts with their neighbours for shorter seams, step by step, each step
// laid out and measured as the unmerged atlas was.
#include <algorithm>
#include <map>
#include <memory>
#include <string>
#include <utility>

#include "atlas/bound/merge_neighbours.h"
#include "atlas/chart_map/chart_threads.h"
#include "atlas/chart_map/free_charts.h"
#include "atlas/pack/lay_out_charts.h"
#include "atlas/search/atlas_search.h"
#include "core/half_edges.h"

namespace lowstretch {

namespace {

// The least efficiency merged charts keep, given the unmerged atlas's. With fewer_seams, an
// unmerged atlas already below the floor (tiny parts or a wide gutter take the texture) is merged
// while it keeps its own efficiency, rather than not at all.
double least_efficiency(const ChartOptions& o, double unmerged) {
  if (o.min_efficiency > 0) return o.min_efficiency;
  const double floor = o.fewer_seams ? std::min(kTuning.merge_floor[1], unmerged) : kTuning.merge_floor[0];
  return std::max(floor, kTuning.merge_keeps[o.fewer_seams] * unmerged);
}

// Charts fully mapped by their faces, for steps packed by outline: every chart keeps the map it
// has alone, and the steps share most charts, so each is freed or mapped once (refined maps cost
// many solves).
using MapsByFaces = std::map<std::vector<int>, SolvedChart>;

void map_once(const AtlasSearch& s, MapsByFaces& mapped, std::vector<SolvedChart>& charts) {
  std::vector<SolvedChart> fresh;
  std::vector<size_t> at;
  for (size_t i = 0; i < charts.size(); ++i) {
    const auto found = mapped.find(charts[i].faces);
    if (found != mapped.end()) {
      charts[i] = found->second;
    } else {
      fresh.push_back(std::move(charts[i]));
      at.push_back(i);
    }
  }
  free_the_charts_that_stretch(fresh, s.options, s.cut_must_pay);
  const size_t faces = faces_in(fresh, 0, fresh.size());
  for_each_index(int(fresh.size()), [&](int i, int) {
    map_at_own_shape(fresh[size_t(i)], for_share(s.options.disk, fresh[size_t(i)].faces.size(), faces));
  }, largest_first(fresh, 0, fresh.size()));
  refine_free_outlines(fresh, s.options);
  for (size_t k = 0; k < fresh.size(); ++k) {
    mapped.emplace(fresh[k].faces, fresh[k]);
    charts[at[k]] = std::move(fresh[k]);
  }
}

// One merge step's charts laid out with s.options: packed by outline, or tiled, with small
// charts in empty texels (each choice a layout of every chart again) only where the tiling alone
// falls below `least`: they change no seam, so a step that keeps it without them can be filled
// once, if it stays the kept one. `filled`: whether it was.
LaidOutCharts lay_out_step(const AtlasSearch& s, std::vector<SolvedChart> charts, bool by_outline, double least,
                           MapsByFaces& mapped, bool& filled) {
  LaidOutCharts laid_out;
  filled = false;
  if (by_outline) {
    map_once(s, mapped, charts);
    laid_out.atlas = packed_by_outline(s, charts, least);
    laid_out.charts = std::move(charts);
    return laid_out;
  }
  free_the_charts_that_stretch(charts, s.options, s.cut_must_pay);
  laid_out = s.tile(std::move(charts));
  if (!laid_out.atlas.error && !(texture_efficiency(laid_out.atlas) >= least)) {
    fill_empty_texels(s, laid_out.charts, laid_out.atlas);
    filled = true;
  }
  return laid_out;
}

// The merge step that replaces the best atlas: how it was laid out, and its charts before any
// layout where it is laid out again.
struct KeptStep {
  bool any = false, by_outline = false, filled = false;
  std::vector<SolvedChart> charts;
};

// A search over the same mesh and best atlas that lays out with `options`.
std::unique_ptr<AtlasSearch> search_like(const AtlasSearch& s, const ChartOptions& options) {
  auto like = std::make_unique<AtlasSearch>(s.V, s.F, options);
  like->unit_V = s.unit_V;
  like->unit = s.unit;
  like->result = s.result;
  like->kept = s.kept;
  like->made = s.made;
  like->cut_must_pay = s.cut_must_pay;
  return like;
}

// Merge steps of one NeighbourMerging, each laid out on `judge` (tiled, as the unmerged atlas
// was measured, or packed by outline: free unions, which tile badly, or a least efficiency of the
// user's own). The step with the shortest seams that keeps the least efficiency is kept.
struct MergeSteps {
  AtlasSearch& judge;
  NeighbourMerging& merging;
  double least;
  bool by_outline;
  KeptStep& kept;
  bool keeps_charts;  // the kept step's charts are kept, to lay them out again or merge them further
  MapsByFaces mapped;

  // Whether the first `merges` merges keep the least efficiency.
  bool keep_least(size_t merges) {
    std::vector<SolvedChart> charts = merging.charts_after(merges);
    bool filled = false;
    LaidOutCharts merged = lay_out_step(judge, keeps_charts ? charts : std::move(charts), by_outline, least, mapped, filled);
    if (merged.atlas.error || !(texture_efficiency(merged.atlas) >= least)) return false;
    if (merged.atlas.seam_length < judge.result.seam_length) {
      judge.keep(std::move(merged));
      kept = {true, by_outline, filled, keeps_charts ? std::move(charts) : std::vector<SolvedChart>()};
    }
    return true;
  }

  // Whether the first `merges` merges leave seams no shorter than the best atlas's: such a step
  // cannot replace it, so it needs no layout.
  bool cannot_shorten(size_t merges) const {
    return judge.unit * merging.seam_between_after(merges) >= judge.result.seam_length;
  }
};

// Rectangle unions, further and further (kTuning.merge_growths, past kTuning.merge_misses steps
// that fall too far, then halving the first step that went too far after the last good one).
void merge_along_growths(MergeSteps& steps) {
  NeighbourMerging& merging = steps.merging;
  size_t good = 0, bad = 0;  // bad: the first step that failed after the last good one, if any
  int misses = 0;
  for (const double growth : kTuning.merge_growths) {
    merging.merge_within(1 + growth);
    if (merging.merges() == good || merging.merges() == bad) continue;
    if (!steps.keep_least(merging.merges())) {
      if (bad == 0) bad = merging.merges();
      if (++misses > kTuning.merge_misses) break;
      continue;
    }
    good = merging.merges();
    bad = 0;
    misses = 0;
  }
  for (int halving = 0; halving < kTuning.merge_halvings && bad > good + 1; ++halving) {
    const size_t middle = (good + bad) / 2;
    if (steps.keep_least(middle)) good = middle;
    else bad = middle;
  }
}

// Free unions: a free union can cost less than its two pieces, so growth does not order the
// steps; every merge within the largest growth is made, then their count is bisected, above the
// steps that cannot shorten the best atlas's seams (those the rectangle unions left).
void merge_by_count(MergeSteps& steps) {
  NeighbourMerging& merging = steps.merging;
  merging.merge_within(1 + *(std::end(kTuning.merge_growths) - 1));
  const size_t all = merging.merges();
  if (all == 0 || steps.cannot_shorten(all) || steps.keep_least(all)) return;
  size_t good = 0, bad = all;
  while (good + 1 < bad && steps.cannot_shorten(good + 1)) ++good;
  for (int step = 0; step < kTuning.merge_count_bisections && bad > good + 1; ++step) {
    const size_t middle = (good + bad) / 2;
    if (steps.cannot_shorten(middle) || steps.keep_least(middle)) good = middle;
    else bad = middle;
  }
}

}  // namespace

// Each union on its own rectangle; with fewer_seams or a least efficiency given, also free (natural boundary)
// where that costs less, packed by outline. The one with the shortest seams that keeps the least
// efficiency replaces the best atlas. Whether one did.
bool merge_for_shorter_seams(AtlasSearch& s) {
  const double least = least_efficiency(s.options, texture_efficiency(s.result));
  // A least efficiency of the user's own is kept by the atlas as it is finally laid out, packed by
  // outline where that beats the tiling: every step is packed so, and an unmerged atlas whose
  // tiling is below it still merges if its outline packing keeps it.
  const bool users_least = s.options.min_efficiency > 0;
  const auto unmerged_keeps_least = [&] {
    if (texture_efficiency(s.result) >= least) return true;
    if (!users_least) return false;
    const ChartsResult packed = packed_by_outline(s, s.kept, least);
    return !packed.error && texture_efficiency(packed) >= least;
  };
  if (s.result.error || s.cut.empty() || !unmerged_keeps_least()) return false;
  const ChartsResult unmerged = s.result;
  const std::vector<int> twin = opposite_half_edges(s.F);
  // Refined maps are judged at fewer steps on a search of their own; the kept step alone is laid
  // out again at the full steps, which only lower its stretch.
  ChartOptions judging = s.options;
  judging.disk.refine_iterations = std::min(judging.disk.refine_iterations, kTuning.judging_refine_steps);
  const bool judged_apart = s.options.disk.refine && judging.disk.refine_iterations < s.options.disk.refine_iterations;
  std::unique_ptr<AtlasSearch> apart;
  if (judged_apart) apart = search_like(s, judging);
  AtlasSearch& judge = judged_apart ? *apart : s;
  // A least efficiency of the user's own is a trade-off chosen as fewer_seams is.
  const bool free_unions_too = (s.options.fewer_seams || users_least) && s.F.rows() <= kTuning.most_free_union_faces;
  KeptStep kept;
  for (const bool free_unions : {false, true}) {
    if (free_unions && !free_unions_too) continue;
    // Free unions merge on from the rectangle unions' kept step: the merges it made are not mapped
    // and laid out again.
    const std::vector<SolvedChart>& start = free_unions && kept.any ? kept.charts : s.cut;
    NeighbourMerging merging(start, s.unit_V, s.F, twin, s.options, free_unions);
    MergeSteps steps{judge, merging, least, free_unions || users_least, kept, judged_apart || (free_unions_too && !free_unions), {}};
    if (free_unions) merge_by_count(steps);
    else merge_along_growths(steps);
  }
  if (!kept.any) return false;
  if (judged_apart) {
    // Refined further, the step's charts can pack a little worse by outline and fall below the
    // least efficiency: then the step as judged is kept, which keeps it.
    MapsByFaces mapped;
    bool filled = false;
    LaidOutCharts laid_out = lay_out_step(s, std::move(kept.charts), kept.by_outline, least, mapped, filled);
    if (!laid_out.atlas.error && texture_efficiency(laid_out.atlas) >= least) {
      s.keep(std::move(laid_out));
      kept.filled = filled;
    } else {
      s.keep({std::move(judge.result), std::move(judge.kept)});
    }
  }
  if (!kept.by_outline && !kept.filled) fill_empty_texels(s, s.kept, s.result);
  if (s.result.charts.size() >= unmerged.charts.size()) return false;
  s.notes.push_back(std::to_string(unmerged.charts.size() - s.result.charts.size()) + " charts merged for shorter seams (" +
                    number_text(unmerged.seam_length) + " -> " + number_text(s.result.seam_length) + "): efficiency " +
                    number_text(texture_efficiency(s.result)) + " (coverage / L2^2) against " + number_text(texture_efficiency(unmerged)) +
                    ", at least " + number_text(least));
  return true;
}

}  // namespace lowstretch
