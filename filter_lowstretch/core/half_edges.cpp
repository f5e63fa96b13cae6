#include "core/half_edges.h"

#include <algorithm>
#include <cstdint>
#include <utility>

#include "core/union_find.h"

namespace lowstretch {

std::vector<std::pair<uint64_t, int>> half_edges_by_edge(const Eigen::MatrixXi& F) {
  const int nh = int(3 * F.rows());
  std::vector<std::pair<uint64_t, int>> keyed(static_cast<size_t>(nh));
  const auto key = [&](int h) {
    const uint64_t a = uint64_t(uint32_t(half_edge_tail(F, h))), b = uint64_t(uint32_t(half_edge_head(F, h)));
    return std::min(a, b) << 32 | std::max(a, b);
  };
  const int vertices = F.size() > 0 && F.minCoeff() >= 0 ? F.maxCoeff() + 1 : 0;
  if (vertices == 0 || vertices > 4 * nh) {  // sparse or odd indices: a plain sort
    for (int h = 0; h < nh; ++h) keyed[size_t(h)] = {key(h), h};
    std::sort(keyed.begin(), keyed.end());
    return keyed;
  }
  // The same order in linear time: a counting sort by the smaller vertex (stable, so half-edges
  // stay in increasing h), then each vertex's few half-edges by the key, ties by h.
  std::vector<int> start(size_t(vertices) + 1, 0);
  for (int h = 0; h < nh; ++h) ++start[size_t(key(h) >> 32) + 1];
  for (int v = 0; v < vertices; ++v) start[size_t(v) + 1] += start[size_t(v)];
  std::vector<int> next(start.begin(), start.end() - 1);
  for (int h = 0; h < nh; ++h) keyed[size_t(next[size_t(key(h) >> 32)]++)] = {key(h), h};
  for (int v = 0; v < vertices; ++v) std::sort(keyed.begin() + start[size_t(v)], keyed.begin() + start[size_t(v) + 1]);
  return keyed;
}

std::vector<int> opposite_half_edges(const Eigen::MatrixXi& F) {
  const int nh = int(3 * F.rows());
  const std::vector<std::pair<uint64_t, int>> keyed = half_edges_by_edge(F);
  std::vector<int> twin(size_t(nh), -1);
  for (size_t s = 0; s + 1 < keyed.size(); ++s)
    if (keyed[s].first == keyed[s + 1].first && twin[size_t(keyed[s].second)] < 0) {
      twin[size_t(keyed[s].second)] = keyed[s + 1].second;
      twin[size_t(keyed[s + 1].second)] = keyed[s].second;
      ++s;
    }
  return twin;
}

EdgePairing pair_manifold_half_edges(const Eigen::MatrixXi& F, const std::vector<std::pair<uint64_t, int>>& keyed) {
  EdgePairing pairing;
  pairing.twin.assign(size_t(3 * F.rows()), -1);
  for (size_t s = 0; s < keyed.size();) {
    size_t e = s;
    while (e < keyed.size() && keyed[e].first == keyed[s].first) ++e;
    if (e - s > 2) ++pairing.non_manifold;
    else if (e - s == 2) {
      const int h0 = keyed[s].second, h1 = keyed[s + 1].second;
      if (half_edge_tail(F, h0) == half_edge_tail(F, h1)) ++pairing.misoriented;  // both run the same way
      else {
        pairing.twin[size_t(h0)] = h1;
        pairing.twin[size_t(h1)] = h0;
      }
    }
    s = e;
  }
  return pairing;
}

std::vector<int> corner_fans(const std::vector<int>& twin) {
  const int nh = int(twin.size());
  UnionFind fans(nh);
  for (int h = 0; h < nh; ++h)  // corner h and the corner across the edge that ends at it
    if (twin[size_t(previous_half_edge(h))] >= 0) fans.unite(h, twin[size_t(previous_half_edge(h))]);
  std::vector<int> fan(static_cast<size_t>(nh)), smallest(static_cast<size_t>(nh), -1);
  for (int h = 0; h < nh; ++h) {
    int& s = smallest[size_t(fans.find(h))];
    if (s < 0) s = h;
    fan[size_t(h)] = s;
  }
  return fan;
}

}  // namespace lowstretch
