#include "atlas/cut/weld_duplicates.h"

#include <algorithm>
#include <numeric>
#include <tuple>

namespace lowstretch {

WeldedFaces weld_duplicate_vertices(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F) {
  WeldedFaces w;
  w.F = F;
  w.onto.resize(size_t(V.rows()));
  std::iota(w.onto.begin(), w.onto.end(), 0);
  std::vector<char> used(size_t(V.rows()), 0);
  for (Eigen::Index f = 0; f < F.rows(); ++f)
    for (int k = 0; k < 3; ++k) used[size_t(F(f, k))] = 1;
  std::vector<int> order;
  for (int v = 0; v < int(V.rows()); ++v)
    if (used[size_t(v)] && V.row(v).allFinite()) order.push_back(v);  // NaN does not sort
  const auto position = [&](int i) { return std::make_tuple(V(i, 0), V(i, 1), V(i, 2)); };
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return position(a) < position(b); });  // ties by index
  for (size_t s = 1; s < order.size(); ++s)
    if (position(order[s]) == position(order[s - 1])) {
      w.onto[size_t(order[s])] = w.onto[size_t(order[s - 1])];
      ++w.welded;
    }
  for (Eigen::Index f = 0; f < F.rows(); ++f)
    for (int k = 0; k < 3; ++k) w.F(f, k) = w.onto[size_t(F(f, k))];
  return w;
}

}  // namespace lowstretch
