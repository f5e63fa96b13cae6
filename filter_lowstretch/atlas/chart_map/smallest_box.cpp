#include "atlas/chart_map/smallest_box.h"

#include <Eigen/Geometry>
#include <cmath>

#include "atlas/base/tuning.h"

namespace lowstretch {

Eigen::MatrixXd turned_to_smallest_box(const Eigen::MatrixXd& uv, const Eigen::MatrixXi& F) {
  double best_area = INFINITY, best_angle = 0;
  for (int k = 0; k < kTuning.projection_turns; ++k) {
    const double angle = 0.5 * M_PI * k / kTuning.projection_turns, c = std::cos(angle), s = std::sin(angle);
    Eigen::AlignedBox2d box;
    for (Eigen::Index f = 0; f < F.rows(); ++f)
      for (int j = 0; j < 3; ++j) {
        const Eigen::Vector2d p = uv.row(F(f, j)).transpose();
        box.extend(Eigen::Vector2d(c * p.x() - s * p.y(), s * p.x() + c * p.y()));
      }
    if (box.volume() < best_area) {
      best_area = box.volume();
      best_angle = angle;
    }
  }
  const double c = std::cos(best_angle), s = std::sin(best_angle);
  Eigen::Matrix2d turn;
  turn << c, s, -s, c;  // row vectors times turn: (c x - s y, s x + c y)
  return uv * turn;
}

}  // namespace lowstretch
