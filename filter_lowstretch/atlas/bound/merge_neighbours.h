// Neighbouring charts merged (as UVAtlas's MergeSmallCharts and xatlas's mergeCharts do): the two
// whose union, mapped, costs the least texture per length of the seam it removes first, again and
// again. How far to go is the caller's: only a layout tells what a step costs the atlas, so the
// merging goes on step by step.
#pragma once
#include <Eigen/Core>
#include <map>
#include <queue>
#include <utility>
#include <vector>

#include "atlas/base/atlas_types.h"
#include "atlas/chart_map/solved_chart.h"

namespace lowstretch {

class NeighbourMerging {
 public:
  // charts: those to merge (a chart with an invalid map takes no part); twin: opposite_half_edges(F).
  // Each union is mapped onto its own rectangle; with free_unions, also free (the natural
  // boundary), which it keeps where that costs less texture and its outline does not cross itself.
  NeighbourMerging(std::vector<SolvedChart> charts, const Eigen::MatrixXd& unit_V, const Eigen::MatrixXi& F,
                   const std::vector<int>& twin, const ChartOptions& options, bool free_unions = false);
  // Merges on while the charts' texture cost stays within `growth` times their cost before any merge.
  void merge_within(double growth);
  size_t merges() const { return merged_.size(); }
  // The charts' texture cost after the first `merges` merges over their cost before any.
  double growth(size_t merges) const { return merges == 0 ? 1 : growth_[merges - 1]; }
  // The seam between the charts after the first `merges` merges, in unit-box lengths: a lower bound
  // of the atlas's seam then (a union cut open to a disk adds seam inside it).
  double seam_between_after(size_t merges) const { return seam_before_ - (merges == 0 ? 0 : seam_removed_[merges - 1]); }
  // The charts after the first `merges` merges, in the order of the pieces.
  std::vector<SolvedChart> charts_after(size_t merges) const;

 private:
  // A union to try: two pieces, the seam between them, the union once mapped.
  struct Candidate {
    int a = 0, b = 0;
    double seam = 0;
    bool mapped = false, valid = false;
    SolvedChart joined;
  };
  using Entry = std::pair<double, size_t>;  // cost per seam length (or its estimate), candidate
  void map(Candidate& c, const Options& options, std::vector<int>& local_of);
  double extra_cost(const Candidate& c) const;
  void join(Candidate& c);

  const Eigen::MatrixXd& unit_V_;
  const Eigen::MatrixXi& F_;
  Options deciding_;
  bool free_unions_ = false;
  std::vector<SolvedChart> pieces_;     // the charts, then the union each merge made
  size_t charts_ = 0;
  std::vector<std::pair<int, int>> merged_;  // merge k joined these two into piece charts_ + k
  std::vector<double> growth_;
  std::vector<double> seam_removed_;  // by the first k + 1 merges
  std::vector<std::vector<int>> sorted_faces_;
  std::vector<char> alive_;
  std::vector<std::map<int, double>> seam_with_;  // per piece: its neighbours and the seam with each
  std::vector<Candidate> candidates_;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue_;
  std::vector<std::vector<int>> local_of_;  // make_chart_mesh's scratch, per worker
  double before_ = 0, cost_ = 0, seam_before_ = 0;
  size_t faces_ = 0, mapped_faces_ = 0;  // of the charts; of the unions mapped so far
  double most_mapped_faces_ = 0;         // merging stops there (kTuning.merge_work)
};

}  // namespace lowstretch
