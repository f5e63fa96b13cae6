#include "sharp_patches.h"

#include <Eigen/Geometry>
#include <cmath>

#include "half_edges.h"
#include "union_find.h"

namespace lowstretch {

std::vector<std::vector<int>> patches_between_sharp_edges(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F,
                                                          double angle_degrees) {
  const int m = int(F.rows());
  Eigen::MatrixXd normal(m, 3);
  for (int f = 0; f < m; ++f) {
    const Eigen::Vector3d a = V.row(F(f, 0)), b = V.row(F(f, 1)), c = V.row(F(f, 2));
    normal.row(f) = (b - a).cross(c - a).stableNormalized().transpose();
  }
  const double least_cosine = std::cos(angle_degrees * M_PI / 180);
  UnionFind faces(m);
  const std::vector<int> twin = opposite_half_edges(F);
  for (int h = 0; h < 3 * m; ++h) {
    const int t = twin[size_t(h)];
    if (t < 0) continue;
    const double cosine = normal.row(h / 3).dot(normal.row(t / 3));
    const bool flat_face = normal.row(h / 3).squaredNorm() == 0 || normal.row(t / 3).squaredNorm() == 0;
    if (flat_face || cosine >= least_cosine) faces.unite(h / 3, t / 3);
  }
  std::vector<int> number(size_t(m), -1);
  std::vector<std::vector<int>> patches;
  for (int f = 0; f < m; ++f) {
    int& n = number[size_t(faces.find(f))];
    if (n < 0) {
      n = int(patches.size());
      patches.emplace_back();
    }
    patches[size_t(n)].push_back(f);
  }
  return patches;
}

}  // namespace lowstretch
