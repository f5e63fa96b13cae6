#include "atlas/cut/cut_mesh.h"

#include <algorithm>
#include <cstdint>
#include <numeric>

#include "core/half_edges.h"
#include "core/union_find.h"

namespace lowstretch {

namespace {
uint64_t key(int a, int b) { return uint64_t(uint32_t(std::min(a, b))) << 32 | uint64_t(uint32_t(std::max(a, b))); }
}  // namespace

CutMesh cut_along(const Eigen::MatrixXi& F, const std::vector<std::array<int, 2>>& seams) {
  std::vector<uint64_t> seam_keys;
  for (const auto& s : seams) seam_keys.push_back(key(s[0], s[1]));
  std::sort(seam_keys.begin(), seam_keys.end());
  // Corners at one vertex stay together across every edge that is not a seam: each group of
  // joined corners becomes one vertex.
  const int nh = int(3 * F.rows());
  const std::vector<int> twin = opposite_half_edges(F);
  UnionFind corners(nh);
  for (int h = 0; h < nh; ++h) {
    const int t = twin[size_t(h)];
    if (t < h) continue;  // boundary, or seen from the other side
    if (std::binary_search(seam_keys.begin(), seam_keys.end(), key(half_edge_tail(F, h), half_edge_head(F, h))))
      continue;
    corners.unite(h, next_half_edge(t));  // corners at the tail of h
    corners.unite(next_half_edge(h), t);  // corners at the head of h
  }
  CutMesh cut;
  cut.F.resize(F.rows(), 3);
  std::vector<int> new_vertex(size_t(nh), -1);
  for (int h = 0; h < nh; ++h) {
    int& v = new_vertex[size_t(corners.find(h))];
    if (v < 0) {
      v = int(cut.original_vertex.size());
      cut.original_vertex.push_back(half_edge_tail(F, h));
    }
    cut.F(h / 3, h % 3) = v;
  }
  return cut;
}

}  // namespace lowstretch
