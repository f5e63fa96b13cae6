#include "half_edges.h"

#include <algorithm>
#include <cstdint>
#include <utility>

namespace lowstretch {

std::vector<std::pair<uint64_t, int>> half_edges_by_edge(const Eigen::MatrixXi& F) {
  const int nh = int(3 * F.rows());
  std::vector<std::pair<uint64_t, int>> keyed(static_cast<size_t>(nh));
  for (int h = 0; h < nh; ++h) {
    const uint64_t a = uint64_t(uint32_t(half_edge_tail(F, h))), b = uint64_t(uint32_t(half_edge_head(F, h)));
    keyed[size_t(h)] = {std::min(a, b) << 32 | std::max(a, b), h};
  }
  std::sort(keyed.begin(), keyed.end());
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

}  // namespace lowstretch
