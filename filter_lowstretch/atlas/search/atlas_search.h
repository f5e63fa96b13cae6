// What the candidates of make_atlas share (AtlasSearch), and the layouts and merges every candidate
// goes through. Internal to atlas/search/.
#pragma once
#include <Eigen/Core>
#include <string>
#include <utility>
#include <vector>

#include "atlas/base/atlas_types.h"
#include "atlas/base/tuning.h"
#include "atlas/chart_map/solved_chart.h"

namespace lowstretch {

// A candidate atlas: its layout, and its charts as they were before it (what later layouts of the
// same charts start from).
struct LaidOutCharts {
  ChartsResult atlas;
  std::vector<SolvedChart> charts;
};

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
  std::vector<SolvedChart> kept;
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
  LaidOutCharts tile(std::vector<SolvedChart> charts) const;
  // The candidate becomes the best atlas.
  void keep(LaidOutCharts candidate) {
    result = std::move(candidate.atlas);
    kept = std::move(candidate.charts);
    made = true;
  }
};

// The charts' L2^2 over their 3D area, as their maps measured it (0 without area).
double mean_l2_squared(const std::vector<SolvedChart>& charts);

// `tiled` with small charts put into the texels its tiling leaves empty (kGuestChoices), where
// that uses the texture better; `kept`: its charts. Only where the tiling was expected to leave
// room and did.
void fill_empty_texels(const AtlasSearch& s, const std::vector<SolvedChart>& kept, ChartsResult& tiled);

// The charts packed by their outlines instead of tiled (pack_by_outline), each on its own
// rectangle or free; also with the flat ones as seen along their normal, if any is: the better
// of the two, or an error. Only packings that may reach `least_efficiency` are made (an error
// where none may).
ChartsResult packed_by_outline(const AtlasSearch& s, std::vector<SolvedChart> charts, double least_efficiency = 0);

// `laid_out` (a layout of `kept`) replaced by the same charts packed by outline where that uses
// the texture better: as they are, or each mapped free where that stretches it less.
void pack_by_outline_if_better(const AtlasSearch& s, const std::vector<SolvedChart>& kept, ChartsResult& laid_out);

// Candidates: the best atlas's charts merged with their neighbours (merge_neighbours.h). The one
// with the shortest seams that keeps the least efficiency replaces the best atlas. Whether one did.
bool merge_for_shorter_seams(AtlasSearch& s);

}  // namespace lowstretch
