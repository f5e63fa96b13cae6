#include "atlas/cut/sharp_patches.h"

#include <Eigen/Geometry>
#include <cmath>

#include "atlas/cut/mesh_components.h"

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
  int count = 0;
  const std::vector<int> patch = face_components(F, count, [&](int h, int t) {
    const bool flat_face = normal.row(h / 3).squaredNorm() == 0 || normal.row(t / 3).squaredNorm() == 0;
    return flat_face || normal.row(h / 3).dot(normal.row(t / 3)) >= least_cosine;
  });
  std::vector<std::vector<int>> patches(static_cast<size_t>(count));
  for (int f = 0; f < m; ++f) patches[size_t(patch[size_t(f)])].push_back(f);
  return patches;
}

}  // namespace lowstretch
