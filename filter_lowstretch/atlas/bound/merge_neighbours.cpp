#include "atlas/bound/merge_neighbours.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "atlas/base/tuning.h"
#include "atlas/bound/deciding_map.h"
#include "atlas/chart_map/chart_threads.h"
#include "atlas/chart_map/free_charts.h"

namespace lowstretch {

namespace {

bool has_valid_map(const SolvedChart& c) {
  return !c.map.error && c.kept.flipped + c.kept.degenerate == 0 && std::isfinite(texture_cost(c));
}

}  // namespace

NeighbourMerging::NeighbourMerging(std::vector<SolvedChart> charts, const Eigen::MatrixXd& unit_V, const Eigen::MatrixXi& F,
                                   const std::vector<int>& twin, const ChartOptions& options, bool free_unions)
    : unit_V_(unit_V), F_(F), deciding_(deciding_options(options.disk)), free_unions_(free_unions), charts_(charts.size()),
      local_of_(size_t(kMostThreads)) {
  std::vector<int> piece(size_t(F.rows()), -1);
  for (size_t c = 0; c < charts.size(); ++c) {
    sorted_faces_.push_back(charts[c].faces);
    std::sort(sorted_faces_.back().begin(), sorted_faces_.back().end());
    alive_.push_back(has_valid_map(charts[c]));
    if (!alive_.back()) continue;
    before_ += texture_cost(charts[c]);
    for (const int f : charts[c].faces) piece[size_t(f)] = int(c);
    faces_ += charts[c].faces.size();
  }
  cost_ = before_;
  // A least efficiency of the user's own is a trade-off chosen as fewer_seams is: it may merge as far.
  const bool further = options.fewer_seams || options.min_efficiency > 0;
  most_mapped_faces_ = std::max(kTuning.merge_work[further] * double(faces_), kTuning.least_merge_work[further]);
  pieces_ = std::move(charts);
  seam_with_.resize(pieces_.size());
  for (size_t h = 0; h < twin.size(); ++h) {
    const int t = twin[h];
    if (t < int(h)) continue;
    const int p = piece[h / 3], q = piece[size_t(t / 3)];
    if (p < 0 || q < 0 || p == q) continue;
    const int f = int(h / 3), k = int(h % 3);
    const double length = (unit_V.row(F(f, k)) - unit_V.row(F(f, (k + 1) % 3))).norm();
    seam_with_[size_t(p)][q] += length;
    seam_with_[size_t(q)][p] += length;
    seam_before_ += length;
  }
  // Unmapped candidates wait with an estimate: the smaller chart's cost per seam with the other
  // (a small chart with a long seam goes first, as in UVAtlas and xatlas).
  for (size_t p = 0; p < seam_with_.size(); ++p)
    for (const auto& n : seam_with_[p])
      if (int(p) < n.first) {
        candidates_.push_back({int(p), n.first, n.second, false, false, {}});
        queue_.emplace(extra_cost(candidates_.back()) / n.second, candidates_.size() - 1);
      }
}

void NeighbourMerging::map(Candidate& c, const Options& options, std::vector<int>& local_of) {
  const std::vector<int>& fa = sorted_faces_[size_t(c.a)];
  const std::vector<int>& fb = sorted_faces_[size_t(c.b)];
  c.joined.faces.resize(fa.size() + fb.size());
  std::merge(fa.begin(), fa.end(), fb.begin(), fb.end(), c.joined.faces.begin());
  c.mapped = true;
  if (local_of.empty()) local_of.assign(size_t(unit_V_.rows()), -1);
  if (make_chart_mesh(unit_V_, F_, c.joined.faces, local_of, c.joined.mesh)) return;
  solve_chart(c.joined, options, 0);  // onto its own rectangle: a square rarely pays for a second solve
  c.joined.deciding_map = true;
  c.valid = has_valid_map(c.joined);
  if (!free_unions_) return;
  SolvedChart free = unmapped_copy(c.joined);
  solve_onto(free, options, 0, true);
  free.deciding_map = true;
  if (!has_valid_map(free) || (c.valid && !(texture_cost(free) < texture_cost(c.joined)))) return;
  if (crosses_itself(free)) return;
  c.joined = std::move(free);
  c.valid = true;
}

// The texture the union costs more than its two pieces; unmapped, the smaller piece's cost.
double NeighbourMerging::extra_cost(const Candidate& c) const {
  const double a = texture_cost(pieces_[size_t(c.a)]), b = texture_cost(pieces_[size_t(c.b)]);
  return c.mapped ? texture_cost(c.joined) - a - b : std::min(a, b);
}

void NeighbourMerging::join(Candidate& c) {
  cost_ += extra_cost(c);
  const int joined = int(pieces_.size());
  alive_[size_t(c.a)] = alive_[size_t(c.b)] = 0;
  alive_.push_back(1);
  sorted_faces_.push_back(c.joined.faces);
  pieces_.push_back(std::move(c.joined));
  merged_.emplace_back(c.a, c.b);
  growth_.push_back(cost_ / before_);
  seam_removed_.push_back((seam_removed_.empty() ? 0 : seam_removed_.back()) + c.seam);
  std::map<int, double> seams;
  for (const int side : {c.a, c.b})
    for (const auto& n : seam_with_[size_t(side)]) {
      if (n.first == c.a || n.first == c.b) continue;
      seams[n.first] += n.second;
      seam_with_[size_t(n.first)].erase(side);
    }
  for (const auto& n : seams) {
    seam_with_[size_t(n.first)][joined] = n.second;
    candidates_.push_back({n.first, joined, n.second, false, false, {}});
    queue_.emplace(extra_cost(candidates_.back()) / n.second, candidates_.size() - 1);
  }
  seam_with_.push_back(std::move(seams));
}

void NeighbourMerging::merge_within(double growth) {
  // Lazily: a candidate is mapped when it comes to the top, and goes back with its true cost;
  // one at the top with its true cost is the cheapest. Ties by candidate: the same input, the same charts.
  while (!queue_.empty() && before_ > 0) {
    const size_t k = queue_.top().second;
    Candidate& c = candidates_[k];
    if (!alive_[size_t(c.a)] || !alive_[size_t(c.b)] || (c.mapped && !c.valid)) {
      queue_.pop();
      c.joined = SolvedChart();  // frees its map
      continue;
    }
    if (!c.mapped) {  // it and the unmapped ones after it, a few at a time on the thread pool
      if (double(mapped_faces_) > most_mapped_faces_) return;
      std::vector<size_t> batch;
      while (!queue_.empty() && batch.size() < size_t(kTuning.merges_mapped_together)) {
        const Candidate& next = candidates_[queue_.top().second];
        if (next.mapped && alive_[size_t(next.a)] && alive_[size_t(next.b)]) break;
        if (!next.mapped && alive_[size_t(next.a)] && alive_[size_t(next.b)]) batch.push_back(queue_.top().second);
        queue_.pop();
      }
      // Each union on one thread unless it is most of the batch.
      std::vector<size_t> union_faces;
      for (const size_t j : batch)
        union_faces.push_back(sorted_faces_[size_t(candidates_[j].a)].size() + sorted_faces_[size_t(candidates_[j].b)].size());
      const size_t batch_faces = std::accumulate(union_faces.begin(), union_faces.end(), size_t(0));
      for_each_index(int(batch.size()), [&](int j, int worker) {
        map(candidates_[batch[size_t(j)]], for_share(deciding_, union_faces[size_t(j)], batch_faces), local_of_[size_t(worker)]);
      });
      for (const size_t j : batch) mapped_faces_ += candidates_[j].joined.faces.size();  // here, not on the workers
      for (const size_t j : batch)
        if (candidates_[j].valid) queue_.emplace(extra_cost(candidates_[j]) / candidates_[j].seam, j);
      continue;
    }
    if ((cost_ + extra_cost(c)) / before_ > growth) return;
    queue_.pop();
    join(c);
  }
}

std::vector<SolvedChart> NeighbourMerging::charts_after(size_t merges) const {
  std::vector<char> alive(charts_ + merges, 1);
  for (size_t k = 0; k < merges; ++k) alive[size_t(merged_[k].first)] = alive[size_t(merged_[k].second)] = 0;
  std::vector<SolvedChart> charts;
  for (size_t p = 0; p < alive.size(); ++p)
    if (alive[p]) {
      charts.push_back(pieces_[p]);
      if (p >= charts_) charts.back().kept_whole = "merged for shorter seams, within the least efficiency";
    }
  return charts;
}

}  // namespace lowstretch
