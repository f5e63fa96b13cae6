#include "atlas/cut/cut_graph.h"

#include <algorithm>
#include <functional>
#include <limits>
#include <numeric>
#include <queue>
#include <utility>

#include "core/half_edges.h"
#include "core/union_find.h"

namespace lowstretch {

namespace {

const double kInf = std::numeric_limits<double>::infinity();

struct ShortestPaths {
  std::vector<double> distance;
  std::vector<int> via;  // per vertex, the half-edge that reached it (-1 for the sources)
};

// Dijkstra over the half-edges of a closed array (every edge has both half-edges); edges that
// touch `free_vertex` cost nothing (it stands for the whole boundary).
ShortestPaths shortest_paths(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, int source, int free_vertex) {
  const int n = int(V.rows());
  std::vector<std::vector<int>> out(static_cast<size_t>(n));  // outgoing half-edges
  for (int h = 0; h < int(3 * F.rows()); ++h) out[size_t(half_edge_tail(F, h))].push_back(h);
  ShortestPaths p{std::vector<double>(size_t(n), kInf), std::vector<int>(size_t(n), -1)};
  using Item = std::pair<double, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
  p.distance[size_t(source)] = 0;
  queue.push({0, source});
  while (!queue.empty()) {
    const Item item = queue.top();
    queue.pop();
    if (item.first > p.distance[size_t(item.second)]) continue;
    for (int h : out[size_t(item.second)]) {
      const int a = half_edge_tail(F, h), b = half_edge_head(F, h);
      const double length = (a == free_vertex || b == free_vertex) ? 0 : (V.row(a) - V.row(b)).norm();
      if (item.first + length < p.distance[size_t(b)]) {
        p.distance[size_t(b)] = item.first + length;
        p.via[size_t(b)] = h;
        queue.push({p.distance[size_t(b)], b});
      }
    }
  }
  return p;
}

int farthest(const ShortestPaths& p) {
  int best = 0;
  for (int i = 0; i < int(p.distance.size()); ++i)
    if (p.distance[size_t(i)] < kInf && p.distance[size_t(i)] > p.distance[size_t(best)]) best = i;
  return best;
}

std::vector<std::array<int, 2>> path_between_far_vertices(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F) {
  const int a = farthest(shortest_paths(V, F, F(0, 0), -1));
  const ShortestPaths from_a = shortest_paths(V, F, a, -1);
  int b = farthest(from_a);
  std::vector<std::array<int, 2>> path;
  for (int v = b; from_a.via[size_t(v)] >= 0; v = half_edge_tail(F, from_a.via[size_t(v)]))
    path.push_back({half_edge_tail(F, from_a.via[size_t(v)]), v});
  // A single cut edge would leave both its ends whole, and the two sides would join again.
  if (path.size() == 1) {
    for (int h = 0; h < int(3 * F.rows()); ++h)
      if (half_edge_tail(F, h) == b && half_edge_head(F, h) != path[0][0]) {
        path.push_back({b, half_edge_head(F, h)});
        break;
      }
  }
  return path;
}

}  // namespace

std::vector<std::array<int, 2>> cut_graph(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F,
                                          const std::vector<int>& boundary) {
  // Close the boundary with a fan around one extra vertex, the root: loops through it are paths
  // from boundary to boundary once its edges are dropped.
  Eigen::MatrixXd W = V;
  Eigen::MatrixXi G = F;
  const int root = boundary.empty() ? F(0, 0) : int(V.rows());
  if (!boundary.empty()) {
    W.conservativeResize(W.rows() + 1, 3);
    W.row(root).setZero();
    G.conservativeResize(G.rows() + Eigen::Index(boundary.size()), 3);
    for (size_t i = 0; i < boundary.size(); ++i)
      G.row(F.rows() + Eigen::Index(i)) << boundary[(i + 1) % boundary.size()], boundary[i], root;
  }
  const long long euler = W.rows() - 3 * G.rows() / 2 + G.rows();  // closed: E = 3F / 2
  if (euler == 2) {
    if (boundary.empty()) return path_between_far_vertices(V, F);
    return {};
  }

  const std::vector<int> twin = opposite_half_edges(G);
  const ShortestPaths tree = shortest_paths(W, G, root, boundary.empty() ? -1 : root);
  std::vector<char> in_tree(twin.size(), 0);
  for (int h : tree.via)
    if (h >= 0) in_tree[size_t(h)] = in_tree[size_t(twin[size_t(h)])] = 1;

  // The dual spanning tree takes the edges whose loops are longest first, so that the 2g edges
  // left over close the shortest loops.
  std::vector<int> candidates;
  for (int h = 0; h < int(twin.size()); ++h)
    if (h < twin[size_t(h)] && !in_tree[size_t(h)]) candidates.push_back(h);
  auto loop_length = [&](int h) {
    const int a = half_edge_tail(G, h), b = half_edge_head(G, h);
    const double own = (a == root || b == root) && !boundary.empty() ? 0 : (W.row(a) - W.row(b)).norm();
    return tree.distance[size_t(a)] + tree.distance[size_t(b)] + own;
  };
  std::vector<double> length(candidates.size());
  for (size_t i = 0; i < candidates.size(); ++i) length[i] = loop_length(candidates[i]);
  std::vector<size_t> order(candidates.size());
  std::iota(order.begin(), order.end(), size_t(0));
  std::stable_sort(order.begin(), order.end(), [&](size_t x, size_t y) { return length[x] > length[y]; });
  UnionFind faces(int(G.rows()));

  std::vector<char> cut(twin.size(), 0);
  auto mark = [&](int h) { cut[size_t(h)] = cut[size_t(twin[size_t(h)])] = 1; };
  for (size_t i : order) {
    const int h = candidates[i];
    if (faces.unite(h / 3, twin[size_t(h)] / 3)) continue;
    mark(h);  // left over: its loop goes into the cut graph
    for (int v : {half_edge_tail(G, h), half_edge_head(G, h)})
      for (; tree.via[size_t(v)] >= 0; v = half_edge_tail(G, tree.via[size_t(v)])) mark(tree.via[size_t(v)]);
  }
  std::vector<std::array<int, 2>> edges;
  for (int h = 0; h < int(twin.size()); ++h) {
    const int a = half_edge_tail(G, h), b = half_edge_head(G, h);
    const bool virtual_edge = !boundary.empty() && (a == root || b == root);
    if (cut[size_t(h)] && h < twin[size_t(h)] && !virtual_edge) edges.push_back({a, b});
  }
  return edges;
}

}  // namespace lowstretch
