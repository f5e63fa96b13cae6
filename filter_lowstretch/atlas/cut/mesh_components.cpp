#include "atlas/cut/mesh_components.h"

#include "core/half_edges.h"
#include "core/union_find.h"

namespace lowstretch {

std::vector<int> face_components(const Eigen::MatrixXi& F, int& count, const std::function<bool(int, int)>& joins) {
  const int m = int(F.rows());
  UnionFind faces(m);
  const std::vector<int> twin = opposite_half_edges(F);
  for (int h = 0; h < 3 * m; ++h) {
    const int t = twin[size_t(h)];
    if (t >= 0 && (!joins || joins(h, t))) faces.unite(h / 3, t / 3);
  }
  std::vector<int> number(static_cast<size_t>(m), -1), component(static_cast<size_t>(m));
  count = 0;
  for (int f = 0; f < m; ++f) {
    int& n = number[size_t(faces.find(f))];
    if (n < 0) n = count++;
    component[size_t(f)] = n;
  }
  return component;
}

int vertices_shared_by_components(const Eigen::MatrixXi& F, int vertex_count, const std::vector<int>& component) {
  std::vector<int> owner(size_t(vertex_count), -1);
  std::vector<char> shared(size_t(vertex_count), 0);
  int count = 0;
  for (Eigen::Index f = 0; f < F.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      const size_t v = size_t(F(f, k));
      if (owner[v] < 0) owner[v] = component[size_t(f)];
      else if (owner[v] != component[size_t(f)] && !shared[v]) {
        shared[v] = 1;
        ++count;
      }
    }
  return count;
}

}  // namespace lowstretch
