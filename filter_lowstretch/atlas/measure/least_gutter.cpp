#include "atlas/measure/least_gutter.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>
#include <unordered_map>
#include <utility>

namespace lowstretch {

namespace {

struct Edge {
  Eigen::Vector2d a, b;
  int chart;
};

double point_to_segment(const Eigen::Vector2d& p, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  const Eigen::Vector2d ab = b - a;
  const double length2 = ab.squaredNorm();
  const double t = length2 > 0 ? std::min(1.0, std::max(0.0, (p - a).dot(ab) / length2)) : 0;
  return (p - (a + t * ab)).norm();
}

double cross(const Eigen::Vector2d& u, const Eigen::Vector2d& v) { return u.x() * v.y() - u.y() * v.x(); }

// Zero where they cross, else the least distance from an end to the other segment.
double segment_distance(const Edge& e, const Edge& f) {
  const double d1 = cross(e.b - e.a, f.a - e.a), d2 = cross(e.b - e.a, f.b - e.a);
  const double d3 = cross(f.b - f.a, e.a - f.a), d4 = cross(f.b - f.a, e.b - f.a);
  if (((d1 < 0 && d2 > 0) || (d1 > 0 && d2 < 0)) && ((d3 < 0 && d4 > 0) || (d3 > 0 && d4 < 0))) return 0;
  return std::min({point_to_segment(e.a, f.a, f.b), point_to_segment(e.b, f.a, f.b), point_to_segment(f.a, e.a, e.b),
                   point_to_segment(f.b, e.a, e.b)});
}

// The charts' boundary edges: an edge inside a chart is a side of two faces with the same two
// texture coordinates (one each way); a boundary edge is a side of one.
std::vector<Edge> boundary_edges(const Eigen::MatrixXd& corner_uv, const std::vector<int>& face_chart) {
  using Key = std::tuple<int, double, double, double, double>;  // chart, lower end, higher end
  std::vector<Key> sides;
  for (Eigen::Index f = 0; f < corner_uv.rows(); ++f) {
    const Eigen::Vector2d p[3] = {corner_uv.block(f, 0, 1, 2).transpose(), corner_uv.block(f, 2, 1, 2).transpose(),
                                  corner_uv.block(f, 4, 1, 2).transpose()};
    if (cross(p[1] - p[0], p[2] - p[0]) == 0) continue;
    for (int k = 0; k < 3; ++k) {
      Eigen::Vector2d a = p[k], b = p[(k + 1) % 3];
      if (std::make_pair(b.x(), b.y()) < std::make_pair(a.x(), a.y())) std::swap(a, b);
      sides.emplace_back(face_chart[size_t(f)], a.x(), a.y(), b.x(), b.y());
    }
  }
  std::sort(sides.begin(), sides.end());
  std::vector<Edge> edges;
  for (size_t i = 0; i < sides.size();) {
    size_t j = i;
    while (j < sides.size() && sides[j] == sides[i]) ++j;
    if (j - i == 1)
      edges.push_back({{std::get<1>(sides[i]), std::get<2>(sides[i])}, {std::get<3>(sides[i]), std::get<4>(sides[i])},
                       std::get<0>(sides[i])});
    i = j;
  }
  return edges;
}

}  // namespace

double least_gutter(const Eigen::MatrixXd& corner_uv, const std::vector<int>& face_chart, double within) {
  const std::vector<Edge> edges = boundary_edges(corner_uv, face_chart);
  double least = std::numeric_limits<double>::infinity();
  for (const Edge& e : edges)
    for (const Eigen::Vector2d& p : {e.a, e.b}) least = std::min({least, p.minCoeff(), 1 - p.maxCoeff()});
  if (!(within > 0)) return least;
  // Each edge sampled every within / 2 into cells of 2 within: two edges nearer than `within` have
  // samples at most 2 within apart, in the same or neighbouring cells.
  const double cell = 2 * within;
  const auto key = [cell](const Eigen::Vector2d& p) {
    return (long long)std::floor(p.x() / cell) * 4000037LL + (long long)std::floor(p.y() / cell);
  };
  std::unordered_map<long long, std::vector<int>> in_cell;
  for (int i = 0; i < int(edges.size()); ++i) {
    const Edge& e = edges[size_t(i)];
    const int samples = 1 + int(std::ceil((e.b - e.a).norm() / (within / 2)));
    long long last = 0;
    for (int s = 0; s <= samples; ++s) {
      const long long k = key(e.a + (e.b - e.a) * (double(s) / samples));
      if (s > 0 && k == last) continue;
      std::vector<int>& list = in_cell[k];
      if (list.empty() || list.back() != i) list.push_back(i);
      last = k;
    }
  }
  for (const auto& entry : in_cell)
    for (long long dx = -1; dx <= 1; ++dx)
      for (long long dy = -1; dy <= 1; ++dy) {
        const auto other = in_cell.find(entry.first + dx * 4000037LL + dy);
        if (other == in_cell.end()) continue;
        for (const int i : entry.second)
          for (const int j : other->second)
            if (edges[size_t(i)].chart != edges[size_t(j)].chart) least = std::min(least, segment_distance(edges[size_t(i)], edges[size_t(j)]));
      }
  return least;
}

}  // namespace lowstretch
