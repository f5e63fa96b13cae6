#include "core/square_corners.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "core/boundary_map.h"

namespace lowstretch {

namespace {

// A run of loop positions first, first+1, ..., first+count-1 (mod n) that must hold a corner.
struct Arc {
  int first, count;
};

// The two open arcs cut off by every interior edge that joins two boundary vertices.
std::vector<Arc> arcs_needing_a_corner(const DiskMesh& disk) {
  const int n = int(disk.boundary.size());
  std::vector<int> position(size_t(disk.V.rows()), -1);
  for (int i = 0; i < n; ++i) position[size_t(disk.boundary[size_t(i)])] = i;
  std::vector<Arc> arcs;
  for (Eigen::Index e = 0; e < disk.edges.rows(); ++e) {
    if (disk.edge_on_boundary[size_t(e)]) continue;
    int a = position[size_t(disk.edges(e, 0))], b = position[size_t(disk.edges(e, 1))];
    if (a < 0 || b < 0) continue;
    if (a > b) std::swap(a, b);
    arcs.push_back({a + 1, b - a - 1});
    arcs.push_back({(b + 1) % n, n - (b - a) - 1});
  }
  return arcs;
}

bool holds_a_corner(const Arc& arc, const std::array<int, 4>& corners, int n) {
  for (int c : corners)
    if ((c - arc.first + n) % n < arc.count) return true;
  return false;
}

// Arcs come in pairs, one pair per edge: the edge collapses when either arc has no corner.
int collapsed_chords(const std::vector<Arc>& arcs, const std::array<int, 4>& corners, int n) {
  int collapsed = 0;
  for (size_t i = 0; i + 1 < arcs.size(); i += 2)
    collapsed += !holds_a_corner(arcs[i], corners, n) || !holds_a_corner(arcs[i + 1], corners, n);
  return collapsed;
}

}  // namespace

namespace {

// The loop positions nearest to the quarter arc lengths, strictly increasing.
std::array<int, 4> quarter_corners(const std::vector<double>& arc, int n) {
  const double perimeter = arc[size_t(n)];
  std::array<int, 4> corners{};
  for (int k = 0; k < 4; ++k) {
    const double target = k * perimeter / 4;
    const auto it = std::lower_bound(arc.begin(), arc.end() - 1, target);
    int best = int(it - arc.begin());
    if (best > 0 && (best == n || target - arc[size_t(best) - 1] < arc[size_t(best)] - target)) --best;
    corners[size_t(k)] = std::min(best, n - 1);
  }
  for (int k = 1; k < 4; ++k)  // keep them strictly increasing on short loops
    corners[size_t(k)] = std::max(corners[size_t(k)], corners[size_t(k) - 1] + 1);
  return corners;
}

// With corner c0 at loop position s: places c1..c3 on the loop unrolled from s so that no arc
// lies strictly between consecutive corners, minimizing the sum of squared differences of the
// sides from a quarter of the perimeter (dynamic programming over positions). Lowers best_cost
// and sets best when it finds a cheaper placement.
void best_corners_from(int s, const std::vector<double>& arc, const std::vector<Arc>& arcs, double& best_cost,
                       std::array<int, 4>& best) {
  const int n = int(arc.size()) - 1;
  const double perimeter = arc[size_t(n)], quarter = perimeter / 4;
  const double inf = std::numeric_limits<double>::infinity();
  const auto unrolled_arc = [&](int q) {  // arc length from s to unrolled position q in [0, n]
    const int i = (s + q) % n;
    double a = arc[size_t(i)] - arc[size_t(s)];
    if (a < 0 || (q == n)) a += perimeter;
    return a;
  };
  // must_start_after[q]: the largest first position of an arc that ends before q, so the
  // previous corner must sit at or after it.
  std::vector<int> must_start_after(size_t(n) + 1, 0);
  for (const Arc& a : arcs) {
    const int first = (a.first - s + n) % n;
    if (first == 0 || first + a.count > n) continue;  // holds position 0, i.e. corner c0
    const size_t after_last = size_t(first + a.count);
    must_start_after[after_last] = std::max(must_start_after[after_last], first);
  }
  for (int q = 1; q <= n; ++q)
    must_start_after[size_t(q)] = std::max(must_start_after[size_t(q)], must_start_after[size_t(q) - 1]);
  // cost[k][q]: best sum of squared side-length errors with corner k at q.
  std::vector<std::vector<double>> cost(4, std::vector<double>(size_t(n) + 1, inf));
  std::vector<std::vector<int>> from(4, std::vector<int>(size_t(n) + 1, -1));
  cost[0][0] = 0;
  for (int k = 1; k <= 4; ++k) {
    const int layer = k % 4;
    for (int q = (k == 4 ? n : 1); q <= (k == 4 ? n : n - 1); ++q)
      for (int p = must_start_after[size_t(q)]; p < q; ++p) {
        const double c = cost[size_t(k - 1)][size_t(p)];
        if (c == inf) continue;
        const double side = unrolled_arc(q) - unrolled_arc(p) - quarter;
        const double total = c + side * side;
        if (k == 4 && total < best_cost) {
          best_cost = total;
          const int q3 = p, q2 = from[3][size_t(q3)], q1 = from[2][size_t(q2)];
          best = {s, (s + q1) % n, (s + q2) % n, (s + q3) % n};
        } else if (k < 4 && total < cost[size_t(layer)][size_t(q)]) {
          cost[size_t(layer)][size_t(q)] = total;
          from[size_t(layer)][size_t(q)] = p;
        }
      }
  }
}

}  // namespace

SquareCorners choose_square_corners(const DiskMesh& disk, const std::array<int, 4>* preferred) {
  const int n = int(disk.boundary.size());
  SquareCorners result;
  if (n < 4) {  // a lone triangle: three corners of the square
    result.corners = {0, 1, std::min(2, n - 1), std::min(2, n - 1)};
    return result;
  }
  const std::vector<double> arc = boundary_arc_lengths(disk);
  const std::vector<Arc> arcs = arcs_needing_a_corner(disk);
  if (preferred) {
    result.corners = *preferred;
    const bool distinct = std::adjacent_find(result.corners.begin(), result.corners.end()) == result.corners.end();
    if (distinct && collapsed_chords(arcs, result.corners, n) == 0) return result;
  }
  result.corners = quarter_corners(arc, n);
  if (collapsed_chords(arcs, result.corners, n) == 0) return result;
  // The search costs about 3 n^2 steps per position of the shortest arc: past this many
  // boundary vertices, kink the sides instead of searching.
  const int largest_searched_loop = 10000;
  // Name the corner inside the shortest arc c0 and try positions of it spread over the arc.
  const Arc shortest = *std::min_element(arcs.begin(), arcs.end(),
                                         [](const Arc& a, const Arc& b) { return a.count < b.count; });
  double best_cost = std::numeric_limits<double>::infinity();
  std::array<int, 4> best{};
  const int tries = std::min(shortest.count, 32);
  for (int j = 0; j < tries && n <= largest_searched_loop; ++j)
    best_corners_from((shortest.first + int((long long)j * shortest.count / tries)) % n, arc, arcs, best_cost, best);
  if (best_cost == std::numeric_limits<double>::infinity()) {  // more separate ears than corners: kink the sides
    result.collapsed_chords = collapsed_chords(arcs, result.corners, n);
    for (const Arc& a : arcs)
      if (!holds_a_corner(a, result.corners, n)) {
        result.kinks.push_back((a.first + a.count / 2) % n);
        if (a.count == 1) result.ear_tips.push_back(a.first);
      }
    return result;
  }
  std::sort(best.begin(), best.end());
  result.corners = best;
  result.moved = true;
  return result;
}

}  // namespace lowstretch
