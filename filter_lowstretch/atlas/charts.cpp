#include "atlas/charts.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <iterator>
#include <map>
#include <numeric>
#include <string>
#include <type_traits>
#include <utility>

#include "atlas/base/tuning.h"
#include "atlas/measure/atlas_result.h"
#include "atlas/bound/cut_invalid_charts.h"
#include "core/disk_mesh.h"
#include "atlas/pack/empty_texels.h"
#include "atlas/chart_map/chart_threads.h"
#include "atlas/measure/valid_as_stored.h"
#include "atlas/chart_map/free_charts.h"
#include "atlas/pack/lay_out_charts.h"
#include "atlas/cut/mesh_components.h"
#include "atlas/cut/sharp_patches.h"
#include "atlas/chart_map/solved_chart.h"
#include "atlas/bound/merge_neighbours.h"
#include "atlas/bound/split_until_bounded.h"
#include "core/half_edges.h"
#include "atlas/cut/split_vertex_fans.h"
#include "core/stretch.h"
#include "atlas/cut/weld_duplicates.h"
#include "atlas/cut/zero_area_parts.h"

namespace lowstretch {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

// Which vertices the faces use.
std::vector<char> used_vertices(Eigen::Index vertices, const Eigen::MatrixXi& F) {
  std::vector<char> used(static_cast<size_t>(vertices), 0);
  for (Eigen::Index f = 0; f < F.rows(); ++f)
    for (int k = 0; k < 3; ++k) used[size_t(F(f, k))] = 1;
  return used;
}

// The rows of V that are `used`.
Eigen::MatrixXd rows_where(const Eigen::MatrixXd& V, const std::vector<char>& used) {
  Eigen::MatrixXd rows(std::count(used.begin(), used.end(), 1), V.cols());
  for (Eigen::Index v = 0, r = 0; v < V.rows(); ++v)
    if (used[size_t(v)]) rows.row(r++) = V.row(v);
  return rows;
}

// The rows of V that faces use.
Eigen::MatrixXd used_rows(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F) { return rows_where(V, used_vertices(V.rows(), F)); }

// The used vertices moved into make_disk_mesh's unit box, so that huge coordinates do not
// overflow lengths and areas; `unit` converts lengths back to the input's units.
Eigen::MatrixXd unit_box_of_used(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, double& unit) {
  const std::vector<char> used = used_vertices(V.rows(), F);
  const UnitBox box = unit_box(rows_where(V, used));
  unit = box.unit();
  Eigen::MatrixXd scaled = Eigen::MatrixXd::Zero(V.rows(), 3);
  for (Eigen::Index v = 0; v < V.rows(); ++v)
    if (used[size_t(v)]) scaled.row(v) = box.map(V.row(v));
  return scaled;
}

// The least efficiency merged charts keep, given the unmerged atlas's. With fewer_seams, an
// unmerged atlas already below the floor (tiny parts or a wide gutter take the texture) is merged
// while it keeps its own efficiency, rather than not at all.
double least_efficiency(const ChartOptions& o, double unmerged) {
  if (o.min_efficiency > 0) return o.min_efficiency;
  const double floor = o.fewer_seams ? std::min(kTuning.merge_floor[1], unmerged) : kTuning.merge_floor[0];
  return std::max(floor, kTuning.merge_keeps[o.fewer_seams] * unmerged);
}

Error check_chart_options(const ChartOptions& o) {
  if (!(o.max_stretch >= 1 && o.max_stretch < 1e6))
    return {ErrorCode::InvalidOption, 0, "must be at least 1, got " + number_text(o.max_stretch), "max_stretch"};
  if (o.most_cuts_ahead < 0 || o.most_cuts_ahead > 16)
    return {ErrorCode::InvalidOption, 0, "must be from 0 to 16, got " + std::to_string(o.most_cuts_ahead), "most_cuts_ahead"};
  if (!(o.min_efficiency >= 0 && o.min_efficiency <= 1))
    return {ErrorCode::InvalidOption, 0, "must be from 0 to 1, got " + number_text(o.min_efficiency), "min_efficiency"};
  if (o.max_charts < 1) return {ErrorCode::InvalidOption, 0, "must be at least 1, got " + std::to_string(o.max_charts), "max_charts"};
  if (o.texture_size < 8 || o.texture_size > 65536)
    return {ErrorCode::InvalidOption, 0, "must be from 8 to 65536, got " + std::to_string(o.texture_size), "texture_size"};
  if (!(o.gutter >= 0.5 && o.gutter <= o.texture_size / 8.0))
    return {ErrorCode::InvalidOption, 0, "must be from 0.5 to an eighth of the texture size (" +
                                             number_text(o.texture_size / 8.0) + "), got " + number_text(o.gutter),
            "gutter"};
  return {};
}

// A disk as one chart: parameterize's map and pass history; measured later, like a layout.
ChartsResult from_disk(const Eigen::MatrixXi& F, Result disk) {
  ChartsResult result;
  result.input_is_disk = true;
  result.corner_uv.resize(F.rows(), 6);
  for (Eigen::Index f = 0; f < F.rows(); ++f)
    for (int k = 0; k < 3; ++k) result.corner_uv.block(f, 2 * k, 1, 2) = disk.uv.row(F(f, k));
  result.face_chart.assign(size_t(F.rows()), 0);
  for (const PassMetrics& p : disk.passes) result.passes.push_back({p.pass, p.l2_stretch, p.flipped, p.degenerate});
  Chart chart;
  chart.faces = int(F.rows());
  chart.chosen_pass = disk.chosen_pass;
  chart.passes = int(disk.passes.size());
  result.charts.push_back(chart);
  result.seconds_total = disk.seconds_total;
  result.notes = std::move(disk.notes);
  result.disk_passes = std::move(disk.passes);
  result.chosen_pass = disk.chosen_pass;
  result.stop_reason = disk.stop_reason;
  return result;
}

// The charts' L2^2 over their 3D area, as their maps measured it (0 without area).
double mean_l2_squared(const std::vector<SolvedChart>& charts) {
  double weighted = 0, area = 0;
  for (const SolvedChart& c : charts) {
    weighted += c.kept.area_3d * c.kept.l2_stretch * c.kept.l2_stretch;
    area += c.kept.area_3d;
  }
  return area > 0 ? weighted / area : 0;
}

// What one chart per part could reach at best, from the parts' maps while deciding (U1; the
// layout's further passes lower L2 by some percent): coverage 1 over their L2^2.
double best_possible_efficiency(const std::vector<SolvedChart>& parts) {
  const bool any_invalid = std::any_of(parts.begin(), parts.end(), [](const SolvedChart& c) { return c.kept.flipped + c.kept.degenerate > 0; });
  const double mean = mean_l2_squared(parts);
  return !any_invalid && mean > 0 ? 1 / mean : 0;
}

// Whether atlas a uses the texture better than b, or as well with fewer flipped and zero-area triangles.
bool more_efficient(const ChartsResult& a, const ChartsResult& b) {
  return texture_efficiency(a) > texture_efficiency(b) ||
         (texture_efficiency(a) == texture_efficiency(b) &&
          a.layout.flipped + a.layout.degenerate < b.layout.flipped + b.layout.degenerate);
}

// Whether the sharp edges split the parts into faces of their own (a CAD model), rather than nick
// them (a statue's creases): the patches beside each part's largest hold kTuning.faces_share of the area.
bool has_faces_of_its_own(const Eigen::MatrixXd& unit_V, const Eigen::MatrixXi& F, const std::vector<int>& component,
                          const std::vector<std::vector<int>>& patches) {
  std::vector<double> largest;
  double total = 0;
  for (const std::vector<int>& patch : patches) {
    double area = 0;
    for (const int f : patch) area += face_area_3d(unit_V, F, f);
    const size_t part = size_t(component[size_t(patch.front())]);
    if (largest.size() <= part) largest.resize(part + 1, 0);
    largest[part] = std::max(largest[part], area);
    total += area;
  }
  return total - std::accumulate(largest.begin(), largest.end(), 0.0) >= kTuning.faces_share * total;
}

// What the candidate atlases of make_atlas share: the mesh in its unit box, the options, and the
// best atlas so far with its notes and its charts.
struct AtlasSearch {
  const Eigen::MatrixXd& V;
  const Eigen::MatrixXi& F;
  const ChartOptions& options;
  ChartOptions reporting;  // options whose progress never goes back (each candidate restarts it)
  double reached = 0;
  Eigen::MatrixXd unit_V;
  double unit = 1;
  std::vector<int> component;
  std::vector<std::vector<int>> components;
  std::vector<std::vector<int>> patches;  // between the sharp edges
  bool made_of_faces = false;
  std::vector<std::string> notes;
  size_t common_notes = 0;  // notes of every candidate; those after them are the best one's
  ChartsResult result;      // the best atlas so far
  bool made = false;        // whether `result` holds an atlas yet
  // Each candidate is tiled; the charts of the best one are kept too, as they were before the
  // tiling: small charts are put into the texels it leaves empty, and every chart is packed by its
  // outline, on the best atlas only (doing so on every candidate can find a better one, but costs
  // much more time).
  std::vector<SolvedChart> kept, tried;
  // The best atlas's charts as cut, before any was mapped free: merging starts from them, and
  // frees charts at the same cut_must_pay.
  std::vector<SolvedChart> cut;
  double cut_must_pay = kTuning.free_must_pay;

  AtlasSearch(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const ChartOptions& options)
      : V(V), F(F), options(options), reporting(options) {
    if (options.disk.progress)
      reporting.disk.progress = [this](double fraction, const char* stage) {
        reached = std::max(reached, fraction);
        return this->options.disk.progress(reached, stage);
      };
  }
  AtlasSearch(const AtlasSearch&) = delete;
  AtlasSearch& operator=(const AtlasSearch&) = delete;

  // The charts tiled, or packed by their outlines where the tiling cannot place them.
  ChartsResult tile(std::vector<SolvedChart> charts);
};

// The components and the unit box; an error if components share a vertex.
Error start_search(AtlasSearch& s) {
  // parameterize checked indices, coordinates, edges and orientation of the whole mesh before it
  // found the topology wrong; vertex fans are checked per component and between components.
  int count = 0;
  s.component = face_components(s.F, count);
  if (const int shared = vertices_shared_by_components(s.F, int(s.V.rows()), s.component))
    return {ErrorCode::NonManifoldVertices, shared, ""};
  s.components.resize(static_cast<size_t>(count));
  for (Eigen::Index f = 0; f < s.F.rows(); ++f) s.components[size_t(s.component[size_t(f)])].push_back(int(f));
  s.unit_V = unit_box_of_used(s.V, s.F, s.unit);
  if (s.options.disk.boundary != BoundaryShape::Square)
    s.notes.push_back("an atlas maps every chart onto a rectangle: the boundary option applies to disks only");
  s.common_notes = s.notes.size();
  s.patches = patches_between_sharp_edges(s.unit_V, s.F, kTuning.sharp_edge_degrees);
  s.made_of_faces = s.patches.size() > s.components.size() && has_faces_of_its_own(s.unit_V, s.F, s.component, s.patches);
  return {};
}

// Candidates: the charts between sharp edges (kTuning.faces_cuts), each with the charts that stretch
// mapped free at kTuning.free_faces_must_pay. Gentler cuts only while the best atlas is poor.
Error cut_along_sharp_edges(AtlasSearch& s) {
  for (const FacesCut& cut : kTuning.faces_cuts) {
    if (cut.degrees != kTuning.sharp_edge_degrees && s.made && !(texture_efficiency(s.result) < kTuning.gentler_cut_below)) continue;
    ChartOptions by_faces_options = s.reporting;
    by_faces_options.max_stretch = 1 + cut.excess_kept * (s.options.max_stretch - 1);
    std::vector<SolvedChart> by_faces_leaves, unused;
    std::vector<std::string> by_faces_notes;
    const Error e = split_until_bounded(
        s.unit_V, s.F, cut.degrees == kTuning.sharp_edge_degrees ? s.patches : patches_between_sharp_edges(s.unit_V, s.F, cut.degrees),
        by_faces_options, by_faces_leaves, unused, by_faces_notes);
    if (e.code == ErrorCode::Cancelled) return e;
    if (e) continue;
    for (const double must_pay : kTuning.free_faces_must_pay) {
      std::vector<SolvedChart> leaves_of_try = by_faces_leaves;
      free_the_charts_that_stretch(leaves_of_try, s.options, must_pay);
      ChartsResult by_faces = s.tile(std::move(leaves_of_try));
      if (by_faces.error || (s.made && !(texture_efficiency(by_faces) > texture_efficiency(s.result)))) continue;
      const std::string against = s.made ? " against " + number_text(texture_efficiency(s.result)) : "";
      s.result = std::move(by_faces);
      s.made = true;
      s.kept = std::move(s.tried);
      s.cut = by_faces_leaves;
      s.cut_must_pay = must_pay;
      s.notes.resize(s.common_notes);  // the cut's notes go with its atlas
      s.notes.insert(s.notes.end(), by_faces_notes.begin(), by_faces_notes.end());
      s.notes.push_back("charts cut along the sharp edges (a model made of faces; normals more than " +
                        number_text(cut.degrees) + " degrees apart)" +
                        std::string(cut.excess_kept < 1 ? ", to L2 stretch " + number_text(by_faces_options.max_stretch) : "") +
                        ": efficiency " + number_text(texture_efficiency(s.result)) + " (coverage / L2^2)" + against);
    }
  }
  return {};
}

// `tiled` with small charts put into the texels its tiling leaves empty (kGuestChoices), where
// that uses the texture better; `kept`: its charts. Only where the tiling was expected to leave
// room and did.
void fill_empty_texels(const AtlasSearch& s, const std::vector<SolvedChart>& kept, ChartsResult& tiled) {
  if (kept.empty() || !(tiled.coverage < 1 - kTuning.least_empty_share) ||
      expected_empty_share(kept, cell_areas(kept)) < kTuning.least_empty_share)
    return;
  const double tiled_efficiency = texture_efficiency(tiled);
  std::vector<SolvedChart> flat_seen = kept;
  see_flat_charts_along_normal(flat_seen);
  // Each choice laid out on its own (on both cores), then taken in order where it does better.
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

// Every chart placed by its outline (atlas_of with all of them as guests).
ChartsResult packed_whole(const AtlasSearch& s, std::vector<SolvedChart> charts) {
  std::vector<int> all(charts.size());
  std::iota(all.begin(), all.end(), 0);
  return atlas_of(std::move(charts), std::move(all), s.unit_V, s.F, s.unit, int(s.V.rows()), s.options);
}

// The charts packed by their outlines instead of tiled (pack_by_outline), each on its own
// rectangle or free; also with the flat ones as seen along their normal, if any is: the better
// of the two, or an error.
ChartsResult packed_by_outline(const AtlasSearch& s, std::vector<SolvedChart> charts) {
  map_all_at_own_shape(charts, s.options);  // once for both packings
  std::vector<SolvedChart> flat_seen = charts;
  see_flat_charts_along_normal(flat_seen);
  const auto free_charts = [](const std::vector<SolvedChart>& c) {
    return std::count_if(c.begin(), c.end(), [](const SolvedChart& chart) { return chart.free_boundary; });
  };
  const bool any_flat = free_charts(flat_seen) > free_charts(charts);
  // Each packing on a core of its own: a packing is one thread's work.
  ChartsResult packed, flat;
  for_each_index(any_flat ? 2 : 1, [&](int i, int) {
    if (i == 0) packed = packed_whole(s, charts);
    else flat = packed_whole(s, std::move(flat_seen));
  });
  if (any_flat && !flat.error && (packed.error || texture_efficiency(flat) > texture_efficiency(packed))) {
    flat.notes.push_back("flat charts as seen along their normal");
    packed = std::move(flat);
  }
  return packed;
}

// A cell per chart, each a few texels wide inside its gutter, cannot hold thousands of tiny charts
// (a scan's debris) on a small texture or with a wide gutter; their outlines need no such floor.
ChartsResult AtlasSearch::tile(std::vector<SolvedChart> charts) {
  tried = charts;
  ChartsResult tiled = atlas_of(std::move(charts), {}, unit_V, F, unit, int(V.rows()), options);
  if (tiled.error.code != ErrorCode::ChartsNotPacked) return tiled;
  ChartsResult packed = packed_by_outline(*this, tried);
  if (packed.error) return tiled;
  packed.notes.push_back(std::to_string(tried.size()) + " charts are too many for a cell each in the tiling: packed by their outlines");
  return packed;
}

// `laid_out` (a layout of `kept`) replaced by the same charts packed by outline where that uses
// the texture better: as they are, or each mapped free where that stretches it less. Free outlines
// pack no denser than boxes, so the freed charts are packed only if they would win at the
// coverage the boxes reached. Free charts are turned to their smallest box here only: in the
// steps before, the texture they would save lets merging go further, down to its least efficiency.
void pack_by_outline_if_better(const AtlasSearch& s, const std::vector<SolvedChart>& kept, ChartsResult& laid_out) {
  if (kept.empty() || laid_out.error) return;
  std::vector<SolvedChart> turned = kept;
  map_all_at_own_shape(turned, s.options);  // turned as mapped, and mapped once for every packing
  turn_free_charts_to_smallest_box(turned);
  ChartsResult packed = packed_by_outline(s, turned);
  std::vector<SolvedChart> freed = std::move(turned);
  const double to_beat = packed.error ? texture_efficiency(laid_out) : std::max(texture_efficiency(packed), texture_efficiency(laid_out));
  const double boxes_coverage = packed.error ? 1 : packed.coverage;
  if (free_where_it_stretches_less(freed, s.options) > 0 && boxes_coverage / mean_l2_squared(freed) > to_beat) {
    ChartsResult free = packed_whole(s, std::move(freed));
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

// Merge steps of one NeighbourMerging, each laid out: tiled with small charts in empty texels, as
// the unmerged atlas was measured, or packed by outline (free unions, which tile badly, or a least
// efficiency of the user's own). The step with the shortest seams that keeps the least efficiency
// replaces the best atlas.
struct MergeSteps {
  AtlasSearch& s;
  NeighbourMerging& merging;
  double least;
  bool by_outline;
  // Packed by outline, every chart keeps the map it has alone, and the steps share most charts:
  // each is freed or mapped fully once (refined maps cost many solves), by its faces.
  std::map<std::vector<int>, SolvedChart> mapped;

  void map_once(std::vector<SolvedChart>& charts) {
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

  // Whether the first `merges` merges keep the least efficiency.
  bool keep_least(size_t merges) {
    std::vector<SolvedChart> charts = merging.charts_after(merges);
    ChartsResult merged;
    if (by_outline) {
      map_once(charts);
      s.tried = charts;
      merged = packed_by_outline(s, charts);
    } else {
      free_the_charts_that_stretch(charts, s.options, s.cut_must_pay);
      merged = s.tile(std::move(charts));
      if (!merged.error) fill_empty_texels(s, s.tried, merged);
    }
    if (merged.error || !(texture_efficiency(merged) >= least)) return false;
    if (merged.seam_length < s.result.seam_length) {
      s.result = std::move(merged);
      s.kept = std::move(s.tried);
    }
    return true;
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
// steps; every merge within the largest growth is made, then their count is bisected.
void merge_by_count(MergeSteps& steps) {
  NeighbourMerging& merging = steps.merging;
  merging.merge_within(1 + *(std::end(kTuning.merge_growths) - 1));
  size_t good = 0, bad = merging.merges() + 1;
  if (merging.merges() == 0 || steps.keep_least(merging.merges())) return;
  for (int step = 0; step < kTuning.merge_count_bisections && bad > good + 1; ++step) {
    const size_t middle = (good + bad) / 2;
    if (steps.keep_least(middle)) good = middle;
    else bad = middle;
  }
}

// Candidates: the best atlas's charts merged with their neighbours (merge_neighbours.h), each union
// on its own rectangle; with fewer_seams or a least efficiency given, also free (natural boundary)
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
    const ChartsResult packed = packed_by_outline(s, s.kept);
    return !packed.error && texture_efficiency(packed) >= least;
  };
  if (s.result.error || s.cut.empty() || !unmerged_keeps_least()) return false;
  const ChartsResult unmerged = s.result;
  const std::vector<int> twin = opposite_half_edges(s.F);
  for (const bool free_unions : {false, true}) {
    // A least efficiency of the user's own is a trade-off chosen as fewer_seams is.
    if (free_unions && ((!s.options.fewer_seams && !users_least) || s.F.rows() > kTuning.most_free_union_faces))
      continue;
    NeighbourMerging merging(s.cut, s.unit_V, s.F, twin, s.options, free_unions);
    MergeSteps steps{s, merging, least, free_unions || users_least, {}};
    if (free_unions) merge_by_count(steps);
    else merge_along_growths(steps);
  }
  if (s.result.charts.size() >= unmerged.charts.size()) return false;
  s.notes.push_back(std::to_string(unmerged.charts.size() - s.result.charts.size()) + " charts merged for shorter seams (" +
                    number_text(unmerged.seam_length) + " -> " + number_text(s.result.seam_length) + "): efficiency " +
                    number_text(texture_efficiency(s.result)) + " (coverage / L2^2) against " + number_text(texture_efficiency(unmerged)) +
                    ", at least " + number_text(least));
  return true;
}

// Candidates: the components cut by stretch until they meet the bound, and, unless that is
// clearly better than they could be whole, one chart per component that was not cut; the
// cut atlas with charts merged for shorter seams.
Error cut_by_stretch(AtlasSearch& s) {
  std::vector<std::string> by_stretch_notes(s.notes.begin(), s.notes.begin() + long(s.common_notes));
  std::vector<SolvedChart> leaves, uncut;
  if (Error e = split_until_bounded(s.unit_V, s.F, std::move(s.components), s.reporting, leaves, uncut, by_stretch_notes))
    return e;
  std::vector<SolvedChart> unfreed = leaves;  // merging starts from them
  free_the_charts_that_stretch(leaves, s.options);
  const size_t cut_into = leaves.size();
  ChartsResult by_stretch = s.tile(std::move(leaves));
  std::vector<SolvedChart> by_stretch_kept = std::move(s.tried);
  if (!uncut.empty() && !(texture_efficiency(by_stretch) > kTuning.clearly_better * best_possible_efficiency(uncut))) {
    ChartsResult whole = s.tile(std::move(uncut));
    if (more_efficient(whole, by_stretch)) {
      by_stretch_notes.push_back("one chart per part: cut into " + std::to_string(cut_into) + " charts, the atlas had efficiency " +
                                 number_text(texture_efficiency(by_stretch)) + " (coverage / L2^2) against " +
                                 number_text(texture_efficiency(whole)));
      by_stretch = std::move(whole);
      by_stretch_kept = std::move(s.tried);
      unfreed.clear();  // parts have no neighbours to merge with
    }
  }
  if (!s.made || more_efficient(by_stretch, s.result)) {
    s.result = std::move(by_stretch);
    s.kept = std::move(by_stretch_kept);
    s.cut = std::move(unfreed);
    s.cut_must_pay = kTuning.free_must_pay;
    s.notes = std::move(by_stretch_notes);
    s.made = true;
  }
  return {};
}

// The charts' options: with fewer_seams (on meshes of at most kTuning.most_free_union_faces), as
// with refine, the maps that layouts keep are refined (kTuning.refine_steps), a fixed number of
// steps, so that every run gives the same atlas.
ChartOptions with_refined_charts(ChartOptions options, Eigen::Index faces) {
  options.disk.refine = options.disk.refine || (options.fewer_seams && faces <= kTuning.most_free_union_faces);
  options.disk.refine_iterations = kTuning.refine_steps;
  options.disk.refine_least_area = kTuning.refine_least_area;
  return options;
}

// Any mesh as charts. The candidates, in order, the best kept:
// 1. a model made of faces (a CAD part) whose parts, mapped whole, are above the bound: its
//    charts between sharp edges only (cutting such a model by stretch loses to them, and costs time);
// 2. otherwise, or if those failed: its components cut by stretch (or whole);
// 3. a model made of faces whose kept atlas still has charts above the bound: also between sharp
//    edges (parts that met the bound while deciding may stretch more in their cells);
// 4. the best of them with small charts in the texels its tiling leaves empty;
// 5. that atlas with charts merged for shorter seams, each step measured the same way;
// 6. the charts of the best of them packed by their outlines instead of tiled (free ones turned to
//    their smallest box).
ChartsResult make_atlas(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const ChartOptions& given) {
  const ChartOptions options = with_refined_charts(given, F.rows());
  std::vector<StageSeconds> stages;
  Clock::time_point start = Clock::now();
  const auto stage_done = [&](const char* stage) {
    stages.push_back({stage, seconds_since(start)});
    start = Clock::now();
  };
  AtlasSearch s(V, F, options);
  if (Error e = start_search(s)) return failed_result(e);
  stage_done("parts and sharp edges");
  const bool only_sharp_edges = s.made_of_faces && !parts_meet_the_bound(s.unit_V, s.F, s.components, options);
  if (only_sharp_edges)
    if (Error e = cut_along_sharp_edges(s)) return failed_result(e);
  if (!s.made || !(texture_efficiency(s.result) > 0))
    if (Error e = cut_by_stretch(s)) return failed_result(e);
  const bool above = std::any_of(s.result.charts.begin(), s.result.charts.end(), [](const Chart& c) { return c.above_bound; });
  if (s.made_of_faces && !only_sharp_edges && above)
    if (Error e = cut_along_sharp_edges(s)) return failed_result(e);
  stage_done("charts cut and laid out");
  fill_empty_texels(s, s.kept, s.result);
  stage_done("small charts into empty texels");
  merge_for_shorter_seams(s);
  stage_done("charts merged for shorter seams");
  pack_by_outline_if_better(s, s.kept, s.result);
  stage_done("charts packed by outline");
  s.result.notes.insert(s.result.notes.begin(), s.notes.begin(), s.notes.end());
  s.result.stage_seconds = std::move(stages);
  return std::move(s.result);
}

// The errors that a manifold copy of the mesh gets past (several components: when parts touch
// at a vertex, that is found after the components).
bool manifold_copy_helps(ErrorCode code) {
  return code == ErrorCode::NonManifoldVertices || code == ErrorCode::SeveralComponents ||
         code == ErrorCode::NonManifoldEdges || code == ErrorCode::InconsistentOrientation ||
         code == ErrorCode::RepeatedVertexInFace;
}

std::string count_text(int count, const char* one, const char* many) {
  return std::to_string(count) + " " + (count == 1 ? one : many);
}


// A triangle soup (each face with vertices of its own, as STL stores them): half or more of the
// used vertices sit on another. Welding it, not cutting it, is the way out (as parameterize says).
bool is_unwelded(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F) {
  const Eigen::MatrixXd used = used_rows(V, F);
  return used.allFinite() && 2 * vertices_on_others(used) >= used.rows();  // NaN: refused later
}

// What the manifold copy changed, one note per kind of defect.
std::vector<std::string> split_notes(const SplitFans& split) {
  struct Defect {
    int count;
    const char *one, *many, *done;
  };
  const Defect defects[] = {
      {split.non_manifold_edges, "non-manifold edge", "non-manifold edges", " (shared by more than two faces) cut open"},
      {split.misoriented_edges, "edge", "edges", " between faces of opposite orientation cut open"},
      {split.repeated_vertex_faces, "face names", "faces name", " a vertex twice (zero area): given corners of their own"},
      {split.split_vertices, "non-manifold vertex", "non-manifold vertices",
       " (where parts, holes or cut edges touch) split per fan of faces"}};
  std::vector<std::string> notes;
  for (const Defect& d : defects)
    if (d.count > 0) notes.push_back(count_text(d.count, d.one, d.many) + d.done + " for the charts; the mesh is unchanged");
  return notes;
}

// parameterize_charts; `own_copies`: V holds copies of vertices made for a manifold copy, which
// are no sign of an unwelded mesh.
ChartsResult disk_or_atlas(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const ChartOptions& options, bool own_copies);


// parameterize's map of a disk as one chart, stored and measured as MeshLab holds it.
ChartsResult disk_result(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const ChartOptions& options, Result whole,
                         const Eigen::MatrixXd& unit_V, Clock::time_point start) {
  ChartsResult result = from_disk(F, std::move(whole));
  std::vector<int> all(static_cast<size_t>(F.rows()));
  for (Eigen::Index f = 0; f < F.rows(); ++f) all[size_t(f)] = int(f);
  store(unit_V, F, int(V.rows()), {all}, options, result);
  // The layout is the kept pass, as stored: its number, timings and solver stay.
  const PassMetrics measured = result.layout;
  result.layout = result.disk_passes.at(size_t(result.chosen_pass));
  copy_measures(measured, result.layout);
  result.seconds_total = seconds_since(start);
  return result;
}

// A mesh that is not manifold or not consistently oriented: the charts are made on a manifold
// copy (split_vertex_fans.h), cut open along its bad edges and split at its bad vertices.
ChartsResult on_manifold_copy(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const ChartOptions& options,
                              const SplitFans& split, Clock::time_point start) {
  if (is_unwelded(V, F)) return failed_result({ErrorCode::UnweldedVertices, vertices_on_others(used_rows(V, F)), ""});
  ChartsResult result = disk_or_atlas(split.V, split.F, options, true);
  if (result.error) return result;
  result.vertex_stretch = join_vertex_values(split, result.vertex_stretch, int(V.rows()));
  const std::vector<std::string> notes = split_notes(split);
  result.notes.insert(result.notes.begin(), notes.begin(), notes.end());
  result.seconds_total = seconds_since(start);
  return result;
}

// Parts of zero 3D area have nothing to map: the atlas is made of the other parts.
ChartsResult without_zero_area_parts(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const ChartOptions& options,
                                     bool own_copies, const std::vector<int>& zero_area, Clock::time_point start) {
  std::vector<int> mapped;
  for (Eigen::Index f = 0, z = 0; f < F.rows(); ++f)
    if (size_t(z) < zero_area.size() && zero_area[size_t(z)] == f) ++z;
    else mapped.push_back(int(f));
  Eigen::MatrixXi mapped_F(Eigen::Index(mapped.size()), 3);
  for (size_t j = 0; j < mapped.size(); ++j) mapped_F.row(Eigen::Index(j)) = F.row(mapped[j]);
  ChartsResult result = disk_or_atlas(V, mapped_F, options, own_copies);
  if (result.error) return result;
  result = with_zero_area_faces(std::move(result), V, F, mapped, zero_area, options);
  result.seconds_total = seconds_since(start);
  return result;
}

// A disk keeps the paper's single chart, unless it has flipped or zero-area triangles as stored
// (or, for Atlas, stretches more than the bound) and an atlas uses the texture better; a valid
// map wins over an invalid one, whatever their efficiency. Any other mesh gets the atlas.
ChartsResult disk_or_atlas_of_whole(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const ChartOptions& options,
                                    Result whole, Clock::time_point start) {
  const bool is_disk = !whole.error;
  if (!is_disk && (options.non_disk == NonDisk::Reject || !cutting_into_disks_fixes(whole.error.code)))
    return failed_result(whole.error);
  ChartsResult disk;
  double unit = 1;
  const Eigen::MatrixXd unit_V = is_disk ? unit_box_of_used(V, F, unit) : Eigen::MatrixXd();
  // Specks are left to the last step, valid_as_stored.
  const auto valid = [&](const ChartsResult& r) {
    return !r.error && without_specks(unit_V, F, r.corner_uv, invalid_faces(unit_V, F, r.corner_uv)).empty();
  };
  bool disk_valid = false;
  if (is_disk) {
    disk = disk_result(V, F, options, std::move(whole), unit_V, start);
    disk_valid = valid(disk);
    const bool try_atlas = options.non_disk == NonDisk::Atlas
                               ? !disk_valid || needs_split(as_chart_pass(disk.disk_passes.at(size_t(disk.chosen_pass))), options.max_stretch)
                               : options.non_disk == NonDisk::Charts && !disk_valid;
    if (!try_atlas) return disk;
  }
  ChartsResult atlas = make_atlas(V, F, options);
  const bool atlas_valid = is_disk && valid(atlas);
  if (is_disk && (atlas.error || (disk_valid != atlas_valid ? disk_valid : !more_efficient(atlas, disk)))) {
    if (!atlas.error)
      disk.notes.push_back("the disk stays one chart: cut into " + std::to_string(atlas.charts.size()) +
                           " charts it had efficiency " + number_text(texture_efficiency(atlas)) + " (coverage / L2^2) against " +
                           number_text(texture_efficiency(disk)));
    return disk;
  }
  atlas.seconds_total = seconds_since(start);
  atlas.layout.seconds = atlas.seconds_total;
  return atlas;
}

// A mesh with duplicate vertices: the charts made with them welded (weld_duplicates.h), each
// duplicate taking the stretch of the vertex it was welded onto; an error if that fails.
ChartsResult on_welded_copy(const Eigen::MatrixXd& V, const ChartOptions& options, const WeldedFaces& welded,
                            Clock::time_point start) {
  ChartsResult result = disk_or_atlas(V, welded.F, options, true);
  if (result.error) return result;
  for (size_t v = 0; v < welded.onto.size(); ++v)
    if (welded.onto[v] != int(v) && Eigen::Index(v) < result.vertex_stretch.size())
      result.vertex_stretch(Eigen::Index(v)) = result.vertex_stretch(welded.onto[v]);
  result.notes.insert(result.notes.begin(), count_text(welded.welded, "duplicate vertex", "duplicate vertices") +
                                                " (on another vertex's position) welded for the charts; the mesh is unchanged");
  result.seconds_total = seconds_since(start);
  return result;
}

ChartsResult disk_or_atlas(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const ChartOptions& options, bool own_copies) {
  const Clock::time_point start = Clock::now();
  Result whole = parameterize(V, F, options.disk);
  if (own_copies && whole.error.code == ErrorCode::UnweldedVertices) whole.error = {ErrorCode::SeveralComponents, 0, ""};
  // Not a disk: duplicates welded first (a disk keeps its seams; a soup is refused below, as the
  // manifold copy cannot help it). Copies the manifold copy made are not duplicates.
  if (!own_copies && options.non_disk != NonDisk::Reject && whole.error && charts_would_help(whole.error.code) &&
      !is_unwelded(V, F)) {
    const WeldedFaces welded = weld_duplicate_vertices(V, F);
    // Not where welding joins more faces on an edge than two, or two running it the same way: those
    // are parts that touch, or the two sides of a double-sided sheet, each better charted alone.
    const auto bad_edges = [&](const Eigen::MatrixXi& faces) {
      const SplitFans split = split_vertex_fans(V, faces);
      return split.non_manifold_edges + split.misoriented_edges;
    };
    if (welded.welded > 0 && bad_edges(welded.F) <= bad_edges(F)) {
      ChartsResult result = on_welded_copy(V, options, welded, start);
      if (!result.error) return result;
    }
  }
  if (options.non_disk != NonDisk::Reject && manifold_copy_helps(whole.error.code)) {
    const SplitFans split = split_vertex_fans(V, F);
    if (split.new_vertices > 0) return on_manifold_copy(V, F, options, split, start);
  }
  if (options.non_disk != NonDisk::Reject && whole.error.code == ErrorCode::SeveralComponents) {
    double unit = 1;
    const std::vector<int> zero_area = faces_of_zero_area_parts(unit_box_of_used(V, F, unit), F);
    if (!zero_area.empty() && Eigen::Index(zero_area.size()) < F.rows())
      return without_zero_area_parts(V, F, options, own_copies, zero_area, start);
  }
  return disk_or_atlas_of_whole(V, F, options, std::move(whole), start);
}

}  // namespace

bool charts_would_help(ErrorCode code) { return cutting_into_disks_fixes(code) || manifold_copy_helps(code); }

ChartsResult parameterize_charts(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const ChartOptions& options) {
  if (Error e = check_chart_options(options)) return failed_result(e);
  ChartsResult result = disk_or_atlas(V, F, options, false);
  if (result.error) return result;
  double unit = 1;
  const Eigen::MatrixXd unit_V = unit_box_of_used(V, F, unit);
  double in_stages = 0;
  for (const StageSeconds& stage : result.stage_seconds) in_stages += stage.seconds;
  result.stage_seconds.insert(result.stage_seconds.begin(), {"input and whole map", std::max(0.0, result.seconds_total - in_stages)});
  const Clock::time_point start = Clock::now();
  result = valid_as_stored(unit_V, F, unit, int(V.rows()), options, std::move(result));
  result.stage_seconds.push_back({"valid as stored", seconds_since(start)});
  result.seconds_total += result.stage_seconds.back().seconds;
  return result;
}

double texture_efficiency(const ChartsResult& r) {
  return r.error ? -1 : r.coverage / (r.layout.l2_stretch * r.layout.l2_stretch);
}

double largest_chart_stretch(const ChartsResult& r) {
  double largest = 0;
  for (const Chart& c : r.charts) largest = std::max(largest, c.l2_stretch);
  return largest;
}


}  // namespace lowstretch
