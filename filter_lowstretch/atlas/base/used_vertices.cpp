#include "atlas/base/used_vertices.h"

#include <algorithm>
#include <vector>

#include "core/disk_mesh.h"

namespace lowstretch {

namespace {

// Which vertices the faces use.
std::vector<char> used_vertices(Eigen::Index vertices, const Eigen::MatrixXi& F) {
  std::vector<char> used(static_cast<size_t>(vertices), 0);
  for (Eigen::Index f = 0; f < F.rows(); ++f)
    for (int k = 0; k < 3; ++k) used[size_t(F(f, k))] = 1;
  return used;
}

// The rows of V that are `used`.
Eigen::MatrixXd rows_where(const Eigen::MatrixXd& V, const std::vector<char>& used) {
  Eigen::MatrixXd rows(std::count(used.begin(), used.end(), 1), V.cols());
  for (Eigen::Index v = 0, r = 0; v < V.rows(); ++v)
    if (used[size_t(v)]) rows.row(r++) = V.row(v);
  return rows;
}

}  // namespace

Eigen::MatrixXd used_rows(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F) { return rows_where(V, used_vertices(V.rows(), F)); }

Eigen::MatrixXd unit_box_of_used(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, double& unit) {
  const std::vector<char> used = used_vertices(V.rows(), F);
  const UnitBox box = unit_box(rows_where(V, used));
  unit = box.unit();
  Eigen::MatrixXd scaled = Eigen::MatrixXd::Zero(V.rows(), 3);
  for (Eigen::Index v = 0; v < V.rows(); ++v)
    if (used[size_t(v)]) scaled.row(v) = box.map(V.row(v));
  return scaled;
}

}  // namespace lowstretch
