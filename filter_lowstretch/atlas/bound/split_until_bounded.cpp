#include "atlas/bound/split_until_bounded.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <numeric>
#include <utility>

#include "atlas/base/tuning.h"
#include "atlas/bound/deciding_map.h"
#include "atlas/chart_map/chart_threads.h"
#include "core/half_edges.h"

namespace lowstretch {

namespace {

const double kInf = std::numeric_limits<double>::infinity();

// How many more times the largest part of a chart is cut before any part is mapped (the tuning
// of cuts ahead says why).
int cuts_ahead(const ChartPass& p, size_t faces, const ChartOptions& options) {
  const bool few_invalid = double(p.flipped + p.degenerate) <= kTuning.few_invalid * double(faces);
  const double l2 = p.flipped + p.degenerate == 0 ? p.l2_stretch : few_invalid ? p.l2_of_valid : 0;
  if (!std::isfinite(l2) || !(l2 > 0)) return 0;
  return std::min(options.most_cuts_ahead, std::max(0, int(std::floor(std::log2(l2 / options.max_stretch)))));
}

// A chart's cut: its parts, then the parts of its largest part cut ahead, and so on; parent: -1
// for a part of the chart itself, else the index of the piece it was cut from. Every piece but
// those cut ahead has its mesh built.
struct Cut {
  std::vector<SolvedChart> pieces;
  std::vector<int> parent;
  int ahead() const {  // pieces cut ahead
    return int(std::count_if(pieces.begin(), pieces.end(), [](const SolvedChart& p) { return p.cut_ahead; }));
  }
};

// Empty if the chart cannot be cut into parts that are disks with holes (a part whose faces meet
// at a single vertex); a cut ahead that leaves such a part is not made.
Cut cut_with_cuts_ahead(const Eigen::MatrixXd& unit_V, const Eigen::MatrixXi& F, const std::vector<int>& twin,
                        const SolvedChart& chart, int ahead, const SplitOptions& split, std::vector<int>& local_of) {
  Cut cut;
  std::vector<size_t> level_start = {0};  // pieces [level_start[k], level_start[k + 1]) are level k's
  const auto add_parts = [&](const std::vector<int>& faces, int parent) {
    std::vector<std::vector<int>> parts = split_chart(unit_V, F, twin, faces, split);
    if (parts.size() < 2) return false;
    for (std::vector<int>& part : parts) {
      cut.pieces.emplace_back();
      cut.pieces.back().faces = std::move(part);
      cut.parent.push_back(parent);
    }
    return true;
  };
  if (!add_parts(chart.faces, -1)) return {};
  size_t cut_faces = chart.faces.size();
  for (int cuts = 0; cuts < ahead; ++cuts) {
    const size_t first = level_start.back();
    size_t largest = first;
    for (size_t j = first; j < cut.pieces.size(); ++j)
      if (cut.pieces[j].faces.size() > cut.pieces[largest].faces.size()) largest = j;
    const size_t faces = cut.pieces[largest].faces.size();
    if (int(faces) < kTuning.least_cut_ahead || double(faces) < kTuning.least_body_share * double(cut_faces)) break;
    level_start.push_back(cut.pieces.size());
    if (!add_parts(cut.pieces[largest].faces, int(largest))) {
      level_start.pop_back();
      break;
    }
    cut.pieces[largest].cut_ahead = true;
    cut_faces = faces;
  }
  // The meshes, built only now: a piece cut ahead never needs one. A part that is no disk with
  // holes undoes the cut ahead it came from, as if that had not been made.
  std::vector<char> built(cut.pieces.size(), 0);
  for (size_t j = 0; j < cut.pieces.size();) {
    SolvedChart& piece = cut.pieces[j];
    if (built[j] || piece.cut_ahead || !make_chart_mesh(unit_V, F, piece.faces, local_of, piece.mesh)) {
      built[j] = !piece.cut_ahead;
      ++j;
      continue;
    }
    const size_t level = size_t(std::upper_bound(level_start.begin(), level_start.end(), j) - level_start.begin()) - 1;
    if (level == 0) return {};
    const size_t from = size_t(cut.parent[j]);
    cut.pieces.resize(level_start[level]);
    cut.parent.resize(level_start[level]);
    level_start.resize(level);
    cut.pieces[from].cut_ahead = false;
    j = from;  // its mesh next
  }
  return cut;
}

// The chart's own parts only, without the cuts ahead (which would pass the chart limit): the part
// that was cut ahead gets its mesh; if it is no disk with holes, the chart is not cut at all.
void keep_only_the_first_cut(const Eigen::MatrixXd& unit_V, const Eigen::MatrixXi& F, Cut& cut, std::vector<int>& local_of) {
  while (!cut.parent.empty() && cut.parent.back() >= 0) {
    cut.pieces.pop_back();
    cut.parent.pop_back();
  }
  bool built = true;
  for (SolvedChart& piece : cut.pieces)
    if (piece.cut_ahead) {
      piece.cut_ahead = false;
      built = built && !make_chart_mesh(unit_V, F, piece.faces, local_of, piece.mesh);
    }
  if (!built) cut = Cut();
}

// The charts cut from one another: node 0.. are the components, a node's parts come after it.
struct ChartTree {
  std::vector<SolvedChart> nodes;
  std::vector<std::vector<int>> parts;  // per node, empty for a leaf
};

// Undoes the cuts that did not pay: bottom up, a chart whose parts (all its leaves) together
// cost at least as much texture (texture_cost) as it does alone becomes a leaf again, so that its
// seams go. A cut that pays only after further cuts is kept: the leaves are compared, not the
// first parts. A chart cut ahead has no map: `map_cut_ahead` maps it when its leaves cost more
// than the bound's stretch would (its cut may not have paid); otherwise, or if it cannot be
// mapped, it stays cut.
void undo_cuts_that_did_not_pay(ChartTree& tree, double max_stretch, const std::function<bool(SolvedChart&)>& map_cut_ahead) {
  const size_t n = tree.nodes.size();
  std::vector<double> weighted(n, 0.0);  // over each node's leaves: their texture_cost (the leaves cover its area)
  std::vector<double> area(n, 0.0);      // and sum A
  for (size_t i = n; i-- > 0;) {
    SolvedChart& node = tree.nodes[i];
    for (int p : tree.parts[i]) {
      weighted[i] += weighted[size_t(p)];
      area[i] += area[size_t(p)];
    }
    if (node.cut_ahead && weighted[i] > max_stretch * max_stretch * area[i] && map_cut_ahead(node)) node.cut_ahead = false;
    const ChartPass& alone = node.kept;
    const bool valid = alone.flipped + alone.degenerate == 0 && !node.cut_ahead;  // no map: stays cut
    const double own = valid ? texture_cost(node) : kInf;
    if (!tree.parts[i].empty()) {
      if (!(own <= weighted[i]) || !valid) continue;  // an invalid chart stays cut
      tree.parts[i].clear();
      node.kept_whole = "its parts stretched more";
    }
    weighted[i] = own;
    area[i] = alone.area_3d;
  }
}

// Whether a chart the bound cuts stays whole for its size (AtlasTuning::smallest_chart).
bool too_small_to_cut(const SolvedChart& chart, double max_stretch) {
  const int faces = int(chart.faces.size());
  if (faces >= 2 * kTuning.smallest_chart) return false;
  if (faces >= 2 && !(chart.kept.l2_stretch <= kTuning.tiny_cut_above * max_stretch)) return false;
  return faces < kTuning.smallest_cut_chart || chart.kept.l2_stretch <= kTuning.small_cut_above * max_stretch;
}

// One split_until_bounded: the mesh, the tree of charts and their cuts, and the chart count.
struct Splitting {
  const Eigen::MatrixXd& unit_V;
  const Eigen::MatrixXi& F;
  const ChartOptions& options;
  const SplitOptions& split;
  std::vector<int> twin;                      // opposite_half_edges(F)
  std::vector<std::vector<int>> local_of;     // make_chart_mesh's scratch, per worker
  ChartTree tree;
  int charts = 0;
  bool limit_reached = false;
};

// The charts of nodes [first, end) that the bound cuts, in order; one too small to cut is kept whole.
Error charts_to_cut(Splitting& s, size_t first, size_t end, std::vector<int>& to_cut) {
  for (size_t i = first; i < end; ++i) {
    SolvedChart& chart = s.tree.nodes[i];
    if (chart.cut_ahead) continue;
    if (chart.map.error) return chart.map.error;
    if (!bound_cuts(chart, s.options.max_stretch)) continue;
    if (too_small_to_cut(chart, s.options.max_stretch)) chart.kept_whole = "too few faces to cut";
    else to_cut.push_back(int(i));
  }
  return {};
}

// Their cuts, made on the thread pool, largest first: a chart's parts depend on it alone, and the
// cuts of a large mesh are slow on one thread.
std::vector<Cut> cut_in_parallel(Splitting& s, const std::vector<int>& to_cut) {
  std::vector<Cut> cuts(to_cut.size());
  std::vector<int> order(to_cut.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    return s.tree.nodes[size_t(to_cut[size_t(a)])].faces.size() > s.tree.nodes[size_t(to_cut[size_t(b)])].faces.size();
  });
  for_each_index(int(to_cut.size()), [&](int k, int worker) {
    if (s.local_of[size_t(worker)].empty()) s.local_of[size_t(worker)].assign(size_t(s.unit_V.rows()), -1);
    const SolvedChart& chart = s.tree.nodes[size_t(to_cut[size_t(k)])];
    cuts[size_t(k)] = cut_with_cuts_ahead(s.unit_V, s.F, s.twin, chart, cuts_ahead(chart.kept, chart.faces.size(), s.options),
                                          s.split, s.local_of[size_t(worker)]);
  }, order);
  return cuts;
}

// The charts of nodes [first, end) too large to map while deciding (kTuning.most_faces_to_decide):
// marked as cut ahead (no map), to be cut as they are.
std::vector<int> cut_without_map(Splitting& s, size_t first, size_t end) {
  std::vector<int> unmapped;
  for (size_t i = first; i < end; ++i) {
    SolvedChart& chart = s.tree.nodes[i];
    if (chart.cut_ahead || int(chart.faces.size()) <= kTuning.most_faces_to_decide) continue;
    chart.cut_ahead = true;
    unmapped.push_back(int(i));
  }
  return unmapped;
}

// A chart cut without a map that was left whole after all (no cut into disks, or the chart
// limit) is mapped.
void map_if_left_whole(Splitting& s, const Options& deciding, SolvedChart& chart, const std::vector<int>& parts) {
  if (!parts.empty()) return;
  chart.cut_ahead = false;
  map_to_decide(chart, deciding, s.options.max_stretch);
}

// The pieces of the cuts into the tree, in order, within the chart limit.
void add_pieces(Splitting& s, const std::vector<int>& to_cut, std::vector<Cut>& cuts) {
  for (size_t k = 0; k < to_cut.size(); ++k) {
    const size_t i = size_t(to_cut[k]);
    if (s.charts >= s.options.max_charts) {
      s.tree.nodes[i].kept_whole = "the chart limit is reached";
      s.limit_reached = true;
      continue;
    }
    Cut& cut = cuts[k];
    if (s.charts + int(cut.pieces.size()) - cut.ahead() - 1 > s.options.max_charts)
      keep_only_the_first_cut(s.unit_V, s.F, cut, s.local_of[0]);
    if (cut.pieces.empty()) s.tree.nodes[i].kept_whole = "no cut into disks was found";
    s.charts += std::max(0, int(cut.pieces.size()) - cut.ahead() - 1);
    const size_t base = s.tree.nodes.size();
    for (size_t j = 0; j < cut.pieces.size(); ++j) {
      s.tree.parts[cut.parent[j] < 0 ? i : base + size_t(cut.parent[j])].push_back(int(s.tree.nodes.size()));
      s.tree.nodes.push_back(std::move(cut.pieces[j]));
      s.tree.parts.emplace_back();
    }
  }
}

// The leaves of the tree, depth first, parts in order; and the roots whole if any was cut.
void collect_charts(ChartTree& tree, size_t roots, std::vector<SolvedChart>& leaves, std::vector<SolvedChart>& uncut) {
  // One chart per part is a candidate only where every part has a map.
  bool cut = false, all_mapped = true;
  for (size_t root = 0; root < roots; ++root) {
    cut = cut || !tree.parts[root].empty();
    all_mapped = all_mapped && !tree.nodes[root].cut_ahead;
  }
  cut = cut && all_mapped;
  for (size_t root = 0; root < roots && cut; ++root) {
    uncut.push_back(tree.nodes[root]);
    if (!tree.parts[root].empty()) uncut.back().kept_whole = "one chart per part stretched less";
  }
  std::vector<int> stack;
  for (size_t root = roots; root-- > 0;) stack.push_back(int(root));
  while (!stack.empty()) {
    const int i = stack.back();
    stack.pop_back();
    if (tree.parts[size_t(i)].empty()) leaves.push_back(std::move(tree.nodes[size_t(i)]));
    for (size_t k = tree.parts[size_t(i)].size(); k-- > 0;) stack.push_back(tree.parts[size_t(i)][k]);
  }
}

}  // namespace

bool parts_meet_the_bound(const Eigen::MatrixXd& unit_V, const Eigen::MatrixXi& F, const std::vector<std::vector<int>>& parts,
                          const ChartOptions& options) {
  std::vector<SolvedChart> charts(parts.size());
  std::vector<int> local_of(size_t(unit_V.rows()), -1);
  size_t faces = 0;
  for (size_t i = 0; i < parts.size(); ++i) {
    charts[i].faces = parts[i];
    if (make_chart_mesh(unit_V, F, parts[i], local_of, charts[i].mesh)) return false;
    faces += parts[i].size();
  }
  const Options deciding = deciding_options(options.disk);
  for_each_index(int(charts.size()), [&](int i, int) {
    SolvedChart& chart = charts[size_t(i)];
    map_to_decide(chart, for_share(deciding, chart.faces.size(), faces), options.max_stretch);
  }, largest_first(charts, 0, charts.size()));
  return std::none_of(charts.begin(), charts.end(),
                      [&](const SolvedChart& c) { return c.map.error || bound_cuts(c, options.max_stretch); });
}

Error split_until_bounded(const Eigen::MatrixXd& unit_V, const Eigen::MatrixXi& F, std::vector<std::vector<int>> components,
                          const ChartOptions& options, std::vector<SolvedChart>& leaves, std::vector<SolvedChart>& uncut,
                          std::vector<std::string>& notes, const SplitOptions& split) {
  Splitting s{unit_V, F, options, split, opposite_half_edges(F), std::vector<std::vector<int>>(kMostThreads), ChartTree(), 0, false};
  s.local_of[0].assign(size_t(unit_V.rows()), -1);
  for (std::vector<int>& faces : components) {
    s.tree.nodes.emplace_back();
    if (Error e = make_chart_mesh(unit_V, F, faces, s.local_of[0], s.tree.nodes.back().mesh)) return e;
    s.tree.nodes.back().faces = std::move(faces);
  }
  s.tree.parts.resize(s.tree.nodes.size());
  s.charts = int(s.tree.nodes.size());
  const Options deciding = deciding_options(options.disk);
  // Round after round: the new charts mapped on the thread pool, then those the bound cuts cut.
  for (size_t first = 0, end = s.tree.nodes.size(); first < end; first = end, end = s.tree.nodes.size()) {
    const std::vector<int> unmapped = cut_without_map(s, first, end);
    const size_t round_faces = faces_in(s.tree.nodes, first, end);
    for_each_index(int(end - first), [&](int i, int) {
      SolvedChart& chart = s.tree.nodes[first + size_t(i)];
      if (!chart.cut_ahead) map_to_decide(chart, for_share(deciding, chart.faces.size(), round_faces), options.max_stretch);
    }, largest_first(s.tree.nodes, first, end));
    std::vector<int> to_cut;
    if (Error e = charts_to_cut(s, first, end, to_cut)) return e;
    to_cut.insert(to_cut.end(), unmapped.begin(), unmapped.end());
    std::vector<Cut> cuts = cut_in_parallel(s, to_cut);
    add_pieces(s, to_cut, cuts);
    for (const int i : unmapped) map_if_left_whole(s, deciding, s.tree.nodes[size_t(i)], s.tree.parts[size_t(i)]);
    if (options.disk.progress && !options.disk.progress(0.9 * (1 - std::pow(0.5, double(end))), "charts"))
      return {ErrorCode::Cancelled, 0, ""};
  }
  undo_cuts_that_did_not_pay(s.tree, options.max_stretch, [&](SolvedChart& chart) {
    if (make_chart_mesh(unit_V, F, chart.faces, s.local_of[0], chart.mesh)) return false;
    map_to_decide(chart, deciding, options.max_stretch);
    return !chart.map.error;
  });
  collect_charts(s.tree, components.size(), leaves, uncut);
  if (s.limit_reached)
    notes.push_back("the chart limit (" + std::to_string(options.max_charts) + ") stopped the splitting");
  return {};
}

}  // namespace lowstretch
