#include "boundary_map.h"

#include <cmath>

namespace lowstretch {

std::vector<double> boundary_arc_lengths(const DiskMesh& disk) {
  const size_t n = disk.boundary.size();
  std::vector<double> length(n), arc(n + 1, 0.0);
  double total = 0;
  for (size_t i = 0; i < n; ++i) {
    length[i] = (disk.V.row(disk.boundary[(i + 1) % n]) - disk.V.row(disk.boundary[i])).norm();
    total += length[i];
  }
  const double floor = total > 0 ? 1e-6 * total / double(n) : 1.0;
  for (size_t i = 0; i < n; ++i) arc[i + 1] = arc[i] + std::max(length[i], floor);
  return arc;
}

Eigen::MatrixXd circle_boundary(const DiskMesh& disk) {
  const std::vector<double> arc = boundary_arc_lengths(disk);
  const size_t n = disk.boundary.size();
  Eigen::MatrixXd uv(Eigen::Index(n), 2);
  const double two_pi = 6.28318530717958647692;
  for (size_t i = 0; i < n; ++i) {
    const double t = two_pi * arc[i] / arc[n];
    uv(Eigen::Index(i), 0) = 0.5 + 0.5 * std::cos(t);
    uv(Eigen::Index(i), 1) = 0.5 + 0.5 * std::sin(t);
  }
  return uv;
}

Eigen::MatrixXd square_boundary(const DiskMesh& disk, const std::array<int, 4>& corners,
                                const std::array<bool, 4>& bow) {
  static const double corner_uv[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  static const double outward[4][2] = {{0, -1}, {1, 0}, {0, 1}, {-1, 0}};
  const double bow_height = 0.25;
  const std::vector<double> arc = boundary_arc_lengths(disk);
  const int n = int(disk.boundary.size());
  Eigen::MatrixXd uv(n, 2);
  for (int side = 0; side < 4; ++side) {
    const int from = corners[size_t(side)];
    const int to = side < 3 ? corners[size_t(side) + 1] : corners[0] + n;
    const auto arc_at = [&](int i) { return i < n ? arc[size_t(i)] : arc[size_t(i - n)] + arc[size_t(n)]; };
    const double span = arc_at(to) - arc_at(from);
    for (int i = from; i < to; ++i) {
      const double t = span > 0 ? (arc_at(i) - arc_at(from)) / span : 0.0;
      const double* a = corner_uv[side];
      const double* b = corner_uv[(side + 1) % 4];
      const double bulge = bow[size_t(side)] ? 4 * bow_height * t * (1 - t) : 0.0;
      uv(i % n, 0) = a[0] + t * (b[0] - a[0]) + bulge * outward[side][0];
      uv(i % n, 1) = a[1] + t * (b[1] - a[1]) + bulge * outward[side][1];
    }
  }
  const Eigen::RowVector2d lo = uv.colwise().minCoeff(), hi = uv.colwise().maxCoeff();
  return (uv.rowwise() - lo) / (hi - lo).maxCoeff();
}

}  // namespace lowstretch
