#include "core/boundary_loops.h"

#include "core/half_edges.h"

namespace lowstretch {

std::vector<std::vector<int>> boundary_loops(const Eigen::MatrixXi& F, const std::vector<int>& twin, int vertex_count) {
  // On a manifold each boundary vertex has exactly one outgoing boundary half-edge.
  std::vector<int> next(size_t(vertex_count), -1);
  for (int h = 0; h < int(twin.size()); ++h)
    if (twin[size_t(h)] < 0) next[size_t(half_edge_tail(F, h))] = half_edge_head(F, h);
  std::vector<char> visited(size_t(vertex_count), 0);
  std::vector<std::vector<int>> loops;
  for (int i = 0; i < vertex_count; ++i) {
    if (next[size_t(i)] < 0 || visited[size_t(i)]) continue;
    loops.emplace_back();
    for (int v = i; v >= 0 && !visited[size_t(v)]; v = next[size_t(v)]) {
      visited[size_t(v)] = 1;
      loops.back().push_back(v);
    }
  }
  return loops;
}

size_t longest_loop(const Eigen::MatrixXd& V, const std::vector<std::vector<int>>& loops) {
  size_t best = 0;
  double best_length = -1;
  for (size_t l = 0; l < loops.size(); ++l) {
    double length = 0;
    for (size_t i = 0; i < loops[l].size(); ++i)
      length += (V.row(loops[l][i]) - V.row(loops[l][(i + 1) % loops[l].size()])).norm();
    if (length > best_length) {
      best_length = length;
      best = l;
    }
  }
  return best;
}

}  // namespace lowstretch
