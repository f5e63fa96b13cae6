#include "atlas/chart_map/chart_rectangle.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>

#include "core/boundary_map.h"
#include "core/square_corners.h"

namespace lowstretch {

namespace {

const double kPi = 3.14159265358979323846;

// How much the boundary turns at each loop position: pi minus the sum of the face angles at the
// vertex, summed with its two loop neighbours so that a corner cut over two edges counts whole.
std::vector<double> boundary_turning(const DiskMesh& disk) {
  const int n = int(disk.boundary.size());
  std::vector<double> angle_sum(size_t(disk.V.rows()), 0.0);
  for (Eigen::Index f = 0; f < disk.F.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector3d a = disk.V.row(disk.F(f, (k + 1) % 3)) - disk.V.row(disk.F(f, k));
      const Eigen::Vector3d b = disk.V.row(disk.F(f, (k + 2) % 3)) - disk.V.row(disk.F(f, k));
      angle_sum[size_t(disk.F(f, k))] += std::atan2(a.cross(b).norm(), a.dot(b));
    }
  std::vector<double> turning(static_cast<size_t>(n), 0.0);
  for (int i = 0; i < n; ++i)
    for (int d = -1; d <= 1; ++d) turning[size_t(i)] += kPi - angle_sum[size_t(disk.boundary[size_t((i + d + n) % n)])];
  return turning;
}

// Corners at the quarter arc lengths from the sharpest turn, each of the other three moved to the
// sharpest turn within an eighth of the perimeter of it if that turns by 30 degrees or more (a
// round boundary, where no turn stands out, keeps the quarter arc lengths). Increasing positions.
std::array<int, 4> sharpest_turn_corners(const DiskMesh& disk) {
  const int n = int(disk.boundary.size());
  const std::vector<double> arc = boundary_arc_lengths(disk);
  const std::vector<double> turning = boundary_turning(disk);
  const double perimeter = arc[size_t(n)];
  const int first = int(std::max_element(turning.begin(), turning.end()) - turning.begin());
  std::array<int, 4> corners{first, first, first, first};
  int at = first;  // walks the loop once from the first corner
  for (int k = 1; k < 4; ++k) {
    const double target = arc[size_t(first)] + k * perimeter / 4;
    const auto unrolled = [&](int i) { return i >= first ? arc[size_t(i)] : arc[size_t(i)] + perimeter; };
    int nearest = -1, sharpest = -1;
    for (int step = at - first + 1; step < n; ++step) {
      const int i = (first + step) % n;
      const double d = unrolled(i) - target;
      if (d > perimeter / 8) break;
      if (d < -perimeter / 8) continue;
      if (nearest < 0 || std::abs(d) < std::abs(unrolled(nearest) - target)) nearest = i;
      if (sharpest < 0 || turning[size_t(i)] > turning[size_t(sharpest)]) sharpest = i;
    }
    if (nearest < 0) nearest = (at + 1) % n;  // a coarse loop: the next vertex
    corners[size_t(k)] = sharpest >= 0 && turning[size_t(sharpest)] >= kPi / 6 ? sharpest : nearest;
    at = corners[size_t(k)];
  }
  std::sort(corners.begin(), corners.end());
  return corners;
}

// Pushes each ear's tip out from its chord, by ear_bulge of the chord's length (the interior is on
// the left of the loop).
void bulge_ears(Eigen::MatrixXd& uv, const std::vector<int>& ear_tips, double ear_bulge) {
  const int n = int(uv.rows());
  for (int tip : ear_tips) {
    const Eigen::RowVector2d a = uv.row((tip + n - 1) % n), b = uv.row((tip + 1) % n);
    const Eigen::RowVector2d chord = b - a;
    const Eigen::RowVector2d outward(chord.y(), -chord.x());
    const Eigen::RowVector2d foot = a + chord * std::max(0.0, std::min(1.0, (uv.row(tip) - a).dot(chord) / chord.squaredNorm()));
    const double height = (uv.row(tip) - foot).dot(outward.normalized());
    const double wanted = ear_bulge * chord.norm();
    if (chord.squaredNorm() > 0 && height < wanted) uv.row(tip) += (wanted - height) * outward.normalized();
  }
}

}  // namespace

Eigen::MatrixXd chart_rectangle(const DiskMesh& disk, const RectangleSettings& settings, std::vector<std::string>& notes) {
  std::array<int, 4> at_turns{};
  const bool has_turns = disk.boundary.size() >= 4;  // a lone triangle takes three corners of the square
  if (has_turns) at_turns = sharpest_turn_corners(disk);
  const SquareCorners corners = choose_square_corners(disk, has_turns ? &at_turns : nullptr);
  note_square_corners(corners, notes);
  Eigen::MatrixXd uv = square_sides(disk, corners.corners, corners.kinks, settings.aspect);
  bulge_ears(uv, corners.ear_tips, settings.ear_bulge);
  return fitted_into_unit_box(uv);
}

}  // namespace lowstretch
