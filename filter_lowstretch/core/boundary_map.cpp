#include "core/boundary_map.h"

#include <algorithm>
#include <cmath>
#include <utility>
#include <string>
#include <vector>

namespace lowstretch {

std::vector<double> boundary_arc_lengths(const DiskMesh& disk) {
  const size_t n = disk.boundary.size();
  std::vector<double> length(n), arc(n + 1, 0.0);
  double total = 0;
  for (size_t i = 0; i < n; ++i) {
    length[i] = (disk.V.row(disk.boundary[(i + 1) % n]) - disk.V.row(disk.boundary[i])).norm();
    total += length[i];
  }
  // A zero-length edge (scans have them) still moves on by a thousandth of a mean edge, so that
  // its two ends stay apart when the texture is stored as float; a smaller step can round them
  // together and collapse their triangle.
  const double floor = total > 0 ? 1e-3 * total / double(n) : 1.0;
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

namespace {

// Outward bulge along a side whose kinks are at `kink_t` (each in (0,1)): a sum of tents, each zero
// at the corners and bending once at its kink, so concave, scaled so that its largest value is
// kKinkBulge. Zero without kinks. Its peak is found once per side: finding it again for every
// vertex would be quadratic on a side with thousands of kinks.
class SideBulge {
 public:
  explicit SideBulge(std::vector<double> kink_t) : kink_t_(std::move(kink_t)) {
    for (double k : kink_t_) highest_ = std::max(highest_, tents(k));  // a concave polyline peaks at one of its kinks
  }
  double at(double t) const { return kink_t_.empty() ? 0.0 : kKinkBulge * tents(t) / highest_; }

 private:
  double tents(double x) const {
    double sum = 0;
    for (double k : kink_t_) sum += std::min(x / k, (1 - x) / (1 - k));
    return sum;
  }
  std::vector<double> kink_t_;
  double highest_ = 0;
};

}  // namespace

Eigen::MatrixXd square_sides(const DiskMesh& disk, const std::array<int, 4>& corners, const std::vector<int>& kinks,
                             double aspect) {
  static const double outward[4][2] = {{0, -1}, {1, 0}, {0, 1}, {-1, 0}};
  const std::vector<double> arc = boundary_arc_lengths(disk);
  const int n = int(disk.boundary.size());
  const auto arc_at = [&](int i) { return i < n ? arc[size_t(i)] : arc[size_t(i - n)] + arc[size_t(n)]; };
  const auto side_from = [&](int side) { return corners[size_t(side)]; };
  const auto side_to = [&](int side) { return side < 3 ? corners[size_t(side) + 1] : corners[0] + n; };
  if (aspect == 0) {  // sides 0 and 2 run along u, 1 and 3 along v
    const auto length = [&](int side) { return arc_at(side_to(side)) - arc_at(side_from(side)); };
    const double along_u = length(0) + length(2), along_v = length(1) + length(3);
    aspect = along_u > 0 && along_v > 0 ? std::min(64.0, std::max(1.0 / 64, along_u / along_v)) : 1.0;
  }
  const double corner_uv[4][2] = {{0, 0}, {aspect, 0}, {aspect, 1}, {0, 1}};
  Eigen::MatrixXd uv(n, 2);
  for (int side = 0; side < 4; ++side) {
    const int from = side_from(side), to = side_to(side);
    const double span = arc_at(to) - arc_at(from), side_length = side % 2 == 0 ? aspect : 1.0;
    const auto t_of = [&](int i) { return span > 0 ? (arc_at(i) - arc_at(from)) / span : 0.0; };
    std::vector<double> kink_t;
    for (int k : kinks) {
      const int unrolled = k < from ? k + n : k;
      if (unrolled > from && unrolled < to) kink_t.push_back(t_of(unrolled));
    }
    const SideBulge bulge(std::move(kink_t));
    for (int i = from; i < to; ++i) {
      const double t = t_of(i), b = side_length * bulge.at(t);
      const double* a = corner_uv[side];
      const double* c = corner_uv[(side + 1) % 4];
      uv(i % n, 0) = a[0] + t * (c[0] - a[0]) + b * outward[side][0];
      uv(i % n, 1) = a[1] + t * (c[1] - a[1]) + b * outward[side][1];
    }
  }
  return uv;
}

Eigen::MatrixXd fitted_into_unit_box(const Eigen::MatrixXd& uv) {
  const Eigen::RowVector2d lo = uv.colwise().minCoeff(), hi = uv.colwise().maxCoeff();
  return (uv.rowwise() - lo) / (hi - lo).maxCoeff();
}

Eigen::MatrixXd square_boundary(const DiskMesh& disk, const std::array<int, 4>& corners, const std::vector<int>& kinks,
                                double aspect) {
  return fitted_into_unit_box(square_sides(disk, corners, kinks, aspect));
}

void note_square_corners(const SquareCorners& corners, std::vector<std::string>& notes) {
  if (corners.moved) notes.push_back("square corners moved off the quarter arc lengths so that no boundary triangle collapses");
  if (corners.collapsed_chords > 0)
    notes.push_back(std::to_string(corners.collapsed_chords) +
                    " interior edges join two boundary vertices of one square side whatever the corners: "
                    "those sides bend outward slightly (at most 0.8% of their length) so that no triangle collapses");
}

Eigen::MatrixXd paper_square_boundary(const DiskMesh& disk, std::vector<std::string>& notes) {
  const SquareCorners corners = choose_square_corners(disk);
  note_square_corners(corners, notes);
  return square_boundary(disk, corners.corners, corners.kinks);
}

}  // namespace lowstretch
