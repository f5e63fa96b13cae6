#include "atlas/chart_map/boundary_crossing.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "core/half_edges.h"

namespace lowstretch {

namespace {

// Twice the signed area of (a, b, c): its sign says on which side of ab the point c lies.
double orient(const Eigen::RowVector2d& a, const Eigen::RowVector2d& b, const Eigen::RowVector2d& c) {
  return (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
}

bool boxes_meet(const Eigen::RowVector2d& a, const Eigen::RowVector2d& b, const Eigen::RowVector2d& c,
                const Eigen::RowVector2d& d) {
  return std::max(a.x(), b.x()) >= std::min(c.x(), d.x()) && std::max(c.x(), d.x()) >= std::min(a.x(), b.x()) &&
         std::max(a.y(), b.y()) >= std::min(c.y(), d.y()) && std::max(c.y(), d.y()) >= std::min(a.y(), b.y());
}

// Segments ab and cd touch or cross (collinear ones count if their boxes meet).
bool segments_meet(const Eigen::RowVector2d& a, const Eigen::RowVector2d& b, const Eigen::RowVector2d& c,
                   const Eigen::RowVector2d& d) {
  if (!boxes_meet(a, b, c, d)) return false;
  const double o1 = orient(a, b, c), o2 = orient(a, b, d), o3 = orient(c, d, a), o4 = orient(c, d, b);
  return o1 * o2 <= 0 && o3 * o4 <= 0;
}

}  // namespace

bool uv_boundary_crosses_itself(const Eigen::MatrixXi& F, const Eigen::MatrixXd& uv, int most_edges) {
  if (!uv.allFinite()) return true;  // no map to trust (and the sweep below needs ordered numbers)
  // A fan that winds past a full turn at a boundary vertex overlaps itself there, though no two of
  // its boundary edges cross (the two that overlap share that vertex).
  std::vector<double> turn(size_t(uv.rows()), 0);
  for (Eigen::Index f = 0; f < F.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      const Eigen::RowVector2d p = uv.row(F(f, k)), q = uv.row(F(f, (k + 1) % 3)), r = uv.row(F(f, (k + 2) % 3));
      turn[size_t(F(f, k))] += std::atan2(std::abs(orient(p, q, r)), (q - p).dot(r - p));
    }
  if (std::any_of(turn.begin(), turn.end(), [](double t) { return t > 2 * M_PI + 1e-6; })) return true;
  const std::vector<int> twin = opposite_half_edges(F);
  std::vector<std::array<int, 2>> edges;
  for (int h = 0; h < int(twin.size()); ++h)
    if (twin[size_t(h)] < 0) edges.push_back({half_edge_tail(F, h), half_edge_head(F, h)});
  if (int(edges.size()) > most_edges) return true;
  // Swept along u: only edges whose u-ranges overlap can meet.
  const auto low_u = [&](const std::array<int, 2>& e) { return std::min(uv(e[0], 0), uv(e[1], 0)); };
  std::sort(edges.begin(), edges.end(), [&](const std::array<int, 2>& e, const std::array<int, 2>& f) { return low_u(e) < low_u(f); });
  for (size_t i = 0; i < edges.size(); ++i) {
    const double high_u = std::max(uv(edges[i][0], 0), uv(edges[i][1], 0));
    for (size_t j = i + 1; j < edges.size() && low_u(edges[j]) <= high_u; ++j) {
      const int a = edges[i][0], b = edges[i][1], c = edges[j][0], d = edges[j][1];
      if (a == c || a == d || b == c || b == d) continue;  // neighbours along the boundary
      if (segments_meet(uv.row(a), uv.row(b), uv.row(c), uv.row(d))) return true;
    }
  }
  return false;
}

}  // namespace lowstretch
