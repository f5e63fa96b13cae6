#include "atlas/search/make_atlas.h"

#include <algorithm>
#include <numeric>
#include <string>
#include <utility>

#include "atlas/base/used_vertices.h"
#include "atlas/bound/split_until_bounded.h"
#include "atlas/chart_map/free_charts.h"
#include "atlas/cut/mesh_components.h"
#include "atlas/cut/sharp_patches.h"
#include "atlas/measure/atlas_result.h"
#include "atlas/search/atlas_search.h"
#include "core/stretch.h"

namespace lowstretch {

namespace {

// What one chart per part could reach at best, from the parts' maps while deciding (U1; the
// layout's further passes lower L2 by some percent): coverage 1 over their L2^2.
double best_possible_efficiency(const std::vector<SolvedChart>& parts) {
  const bool any_invalid = std::any_of(parts.begin(), parts.end(), [](const SolvedChart& c) { return c.kept.flipped + c.kept.degenerate > 0; });
  const double mean = mean_l2_squared(parts);
  return !any_invalid && mean > 0 ? 1 / mean : 0;
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

// Where charts are cut (split_chart.h): at the cheapest seam near the level set, or at the level
// set itself between sharp edges and with fewer_seams, where on the bench table's meshes the
// cheapest seams gave atlases that used the texture worse (CAD parts) or kept longer seams.
SplitOptions split_options(const ChartOptions& options, bool between_sharp_edges) {
  SplitOptions split;
  if (between_sharp_edges || options.fewer_seams) split.seam_band = 0;
  return split;
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
        by_faces_options, by_faces_leaves, unused, by_faces_notes, split_options(s.options, true));
    if (e.code == ErrorCode::Cancelled) return e;
    if (e) continue;
    for (const double must_pay : kTuning.free_faces_must_pay) {
      std::vector<SolvedChart> leaves_of_try = by_faces_leaves;
      free_the_charts_that_stretch(leaves_of_try, s.options, must_pay);
      LaidOutCharts by_faces = s.tile(std::move(leaves_of_try));
      if (by_faces.atlas.error || (s.made && !(texture_efficiency(by_faces.atlas) > texture_efficiency(s.result)))) continue;
      const std::string against = s.made ? " against " + number_text(texture_efficiency(s.result)) : "";
      s.keep(std::move(by_faces));
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

// Candidates: the components cut by stretch until they meet the bound, and, unless that is
// clearly better than they could be whole, one chart per component that was not cut; the
// cut atlas with charts merged for shorter seams.
Error cut_by_stretch(AtlasSearch& s) {
  std::vector<std::string> by_stretch_notes(s.notes.begin(), s.notes.begin() + long(s.common_notes));
  std::vector<SolvedChart> leaves, uncut;
  if (Error e = split_until_bounded(s.unit_V, s.F, std::move(s.components), s.reporting, leaves, uncut, by_stretch_notes,
                                    split_options(s.options, false)))
    return e;
  std::vector<SolvedChart> unfreed = leaves;  // merging starts from them
  free_the_charts_that_stretch(leaves, s.options);
  const size_t cut_into = leaves.size();
  LaidOutCharts by_stretch = s.tile(std::move(leaves));
  if (!uncut.empty() && !(texture_efficiency(by_stretch.atlas) > kTuning.clearly_better * best_possible_efficiency(uncut))) {
    LaidOutCharts whole = s.tile(std::move(uncut));
    if (more_efficient(whole.atlas, by_stretch.atlas)) {
      by_stretch_notes.push_back("one chart per part: cut into " + std::to_string(cut_into) + " charts, the atlas had efficiency " +
                                 number_text(texture_efficiency(by_stretch.atlas)) + " (coverage / L2^2) against " +
                                 number_text(texture_efficiency(whole.atlas)));
      by_stretch = std::move(whole);
      unfreed.clear();  // parts have no neighbours to merge with
    }
  }
  if (!s.made || more_efficient(by_stretch.atlas, s.result)) {
    s.keep(std::move(by_stretch));
    s.cut = std::move(unfreed);
    s.cut_must_pay = kTuning.free_must_pay;
    s.notes = std::move(by_stretch_notes);
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

}  // namespace

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

bool more_efficient(const ChartsResult& a, const ChartsResult& b) {
  return texture_efficiency(a) > texture_efficiency(b) ||
         (texture_efficiency(a) == texture_efficiency(b) &&
          a.layout.flipped + a.layout.degenerate < b.layout.flipped + b.layout.degenerate);
}

}  // namespace lowstretch
