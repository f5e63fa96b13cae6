#include "atlas/cut/split_chart.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <numeric>
#include <queue>
#include <unordered_map>

#include "atlas/cut/cheapest_seam.h"

namespace lowstretch {

namespace {

// The chart as a graph of its faces: neighbours across edges, with the edge's seam cost.
struct FaceGraph {
  std::vector<Eigen::Vector3d> centroid, normal;
  std::vector<double> area;
  std::vector<std::array<int, 3>> corner;     // the face's vertices (rows of V)
  std::vector<std::array<int, 3>> neighbour;  // local face, -1 across the chart's border
  std::vector<std::array<double, 3>> cost;    // seam cost of that edge
};

FaceGraph face_graph(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const std::vector<int>& twin,
                     const std::vector<int>& faces, double crease_discount) {
  FaceGraph g;
  std::unordered_map<int, int> local;
  local.reserve(faces.size() * 2);
  for (size_t i = 0; i < faces.size(); ++i) local[faces[i]] = int(i);
  for (int f : faces) {
    const Eigen::Vector3d a = V.row(F(f, 0)), b = V.row(F(f, 1)), c = V.row(F(f, 2));
    const Eigen::Vector3d n = (b - a).cross(c - a);
    g.corner.push_back({F(f, 0), F(f, 1), F(f, 2)});
    g.centroid.push_back((a + b + c) / 3);
    g.area.push_back(0.5 * n.norm());
    g.normal.push_back(n.norm() > 0 ? Eigen::Vector3d(n.normalized()) : Eigen::Vector3d::Zero());
  }
  g.neighbour.resize(faces.size());
  g.cost.resize(faces.size());
  for (size_t i = 0; i < faces.size(); ++i)
    for (int k = 0; k < 3; ++k) {
      const int t = twin[size_t(3 * faces[i] + k)];
      const auto found = t >= 0 ? local.find(t / 3) : local.end();
      g.neighbour[i][size_t(k)] = found == local.end() ? -1 : found->second;
      const double length = (V.row(F(faces[i], (k + 1) % 3)) - V.row(F(faces[i], k))).norm();
      const double cosine = found == local.end() ? 1.0 : g.normal[i].dot(g.normal[size_t(found->second)]);
      // 1 on flat ground, crease_discount at a right angle and beyond
      g.cost[i][size_t(k)] = length * (1 - (1 - crease_discount) * std::min(1.0, 1 - cosine));
    }
  return g;
}

// Geodesic distance over the face graph (centroid to centroid) from one face.
std::vector<double> distances_from(const FaceGraph& g, int source) {
  std::vector<double> d(g.area.size(), std::numeric_limits<double>::infinity());
  using Entry = std::pair<double, int>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
  d[size_t(source)] = 0;
  queue.push({0, source});
  while (!queue.empty()) {
    const Entry e = queue.top();
    queue.pop();
    if (e.first > d[size_t(e.second)]) continue;
    for (int n : g.neighbour[size_t(e.second)]) {
      if (n < 0) continue;
      const double through = e.first + (g.centroid[size_t(e.second)] - g.centroid[size_t(n)]).norm();
      if (through < d[size_t(n)]) {
        d[size_t(n)] = through;
        queue.push({through, n});
      }
    }
  }
  return d;
}

int farthest(const std::vector<double>& d) {
  int best = 0;
  for (size_t i = 0; i < d.size(); ++i)
    if (std::isfinite(d[i]) && d[i] > d[size_t(best)]) best = int(i);
  return best;
}

// Edge-connected pieces of faces on one side; piece[i] numbered in order of first face.
std::vector<int> pieces_by_side(const FaceGraph& g, const std::vector<char>& side, int& count) {
  std::vector<int> piece(side.size(), -1);
  count = 0;
  std::vector<int> stack;
  for (size_t start = 0; start < side.size(); ++start) {
    if (piece[start] >= 0) continue;
    piece[start] = count;
    stack.assign(1, int(start));
    while (!stack.empty()) {
      const int f = stack.back();
      stack.pop_back();
      for (int n : g.neighbour[size_t(f)])
        if (n >= 0 && piece[size_t(n)] < 0 && side[size_t(n)] == side[size_t(f)]) {
          piece[size_t(n)] = count;
          stack.push_back(n);
        }
    }
    ++count;
  }
  return piece;
}

// The threshold rank t (faces of rank < t on one side) whose seam is cheapest for the area it
// cuts off: cost / sqrt(smaller area), with the smaller side at least `smallest` of the area.
int cheapest_cut(const FaceGraph& g, const std::vector<int>& rank, const std::vector<int>& by_rank, double smallest) {
  const size_t n = rank.size();
  std::vector<double> cut(n + 1, 0.0), area_below(n + 1, 0.0);
  for (size_t i = 0; i < n; ++i)
    for (int k = 0; k < 3; ++k) {
      const int j = g.neighbour[i][size_t(k)];
      if (j < 0 || rank[i] > rank[size_t(j)]) continue;  // each edge once, from its lower rank
      cut[size_t(rank[i]) + 1] += g.cost[i][size_t(k)];  // crossed by thresholds rank[i] < t <= rank[j]
      cut[size_t(rank[size_t(j)]) + 1] -= g.cost[i][size_t(k)];
    }
  for (size_t t = 1; t <= n; ++t) {
    cut[t] += cut[t - 1];
    area_below[t] = area_below[t - 1] + g.area[size_t(by_rank[t - 1])];
  }
  const double total = area_below[n];
  int best = -1;
  double best_score = std::numeric_limits<double>::infinity();
  for (size_t t = 1; t < n; ++t) {
    const double smaller = std::min(area_below[t], total - area_below[t]);
    if (!(smaller >= smallest * total) || !(smaller > 0)) continue;
    const double score = cut[t] / std::sqrt(smaller);
    if (score < best_score) {
      best_score = score;
      best = int(t);
    }
  }
  return best;
}

// The sides of the level set below rank t, its faces within options.seam_band of it free to take
// the side of the cheapest seam; the level set itself where that would leave a side under
// options.smallest_part of the area.
// extent: the distance between the two faces farthest apart.
std::vector<char> side_of_cheapest_seam(const FaceGraph& g, const std::vector<double>& from_a, const std::vector<double>& from_b,
                                        double extent, const std::vector<int>& rank, const std::vector<int>& by_rank, int t,
                                        const SplitOptions& options) {
  const size_t n = from_a.size();
  std::vector<char> level_set(n);
  for (size_t i = 0; i < n; ++i) level_set[i] = rank[i] < t;
  if (!(options.seam_band > 0)) return level_set;
  const auto key = [&](size_t i) { return from_a[i] - from_b[i]; };
  const double level = 0.5 * (key(size_t(by_rank[size_t(t - 1)])) + key(size_t(by_rank[size_t(t)])));
  const double band = options.seam_band * extent;
  std::vector<signed char> fixed(n);
  for (size_t i = 0; i < n; ++i) fixed[i] = key(i) < level - band ? 1 : key(i) > level + band ? 0 : -1;
  std::vector<char> side = cheapest_seam(g.corner, g.neighbour, g.cost, fixed);
  double below = 0, total = 0;
  for (size_t i = 0; i < n; ++i) below += side[i] ? g.area[i] : 0, total += g.area[i];
  return std::min(below, total - below) >= options.smallest_part * total ? side : level_set;
}

}  // namespace

std::vector<std::vector<int>> split_chart(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const std::vector<int>& twin,
                                          const std::vector<int>& faces, const SplitOptions& options) {
  if (faces.size() < 4) return {faces};
  const FaceGraph g = face_graph(V, F, twin, faces, options.crease_discount);
  const size_t n = faces.size();

  // Across the longest extent: the face farthest from the first, and the one farthest from it.
  const int a = farthest(distances_from(g, 0));
  const std::vector<double> from_a = distances_from(g, a);
  const int b = farthest(from_a);
  const std::vector<double> from_b = distances_from(g, b);
  std::vector<int> by_rank(n);
  std::iota(by_rank.begin(), by_rank.end(), 0);
  std::stable_sort(by_rank.begin(), by_rank.end(),
                   [&](int i, int j) { return from_a[size_t(i)] - from_b[size_t(i)] < from_a[size_t(j)] - from_b[size_t(j)]; });
  std::vector<int> rank(n);
  for (size_t r = 0; r < n; ++r) rank[size_t(by_rank[r])] = int(r);
  const int t = cheapest_cut(g, rank, by_rank, options.smallest_part);
  if (t < 0) return {faces};
  std::vector<char> side = side_of_cheapest_seam(g, from_a, from_b, from_a[size_t(b)], rank, by_rank, t, options);

  // No sliver along the seam: a face with two or three neighbours across it changes side.
  for (int sweep = 0; sweep < 3; ++sweep)
    for (size_t i = 0; i < n; ++i) {
      int across = 0;
      for (int j : g.neighbour[i]) across += j >= 0 && side[size_t(j)] != side[i];
      if (across >= 2) side[i] = !side[i];
    }
  // No crumbs: pieces under 1% of the area join the other side (which surrounds them).
  const double total = std::accumulate(g.area.begin(), g.area.end(), 0.0);
  int count = 0;
  std::vector<int> piece = pieces_by_side(g, side, count);
  std::vector<double> piece_area(static_cast<size_t>(count), 0.0);
  for (size_t i = 0; i < n; ++i) piece_area[size_t(piece[i])] += g.area[i];
  for (size_t i = 0; i < n; ++i)
    if (piece_area[size_t(piece[i])] < 0.01 * total) side[i] = !side[i];
  piece = pieces_by_side(g, side, count);
  if (count < 2) return {faces};
  std::vector<std::vector<int>> parts(static_cast<size_t>(count));
  for (size_t i = 0; i < n; ++i) parts[size_t(piece[i])].push_back(faces[i]);
  return parts;
}

}  // namespace lowstretch
