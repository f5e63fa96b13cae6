#include "atlas/chart_map/plane_projection.h"

#include "atlas/base/tuning.h"

#include <Eigen/Geometry>
#include <cmath>

namespace lowstretch {

Eigen::MatrixXd project_onto_own_plane(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F) {
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
  for (Eigen::Index f = 0; f < F.rows(); ++f) {
    const Eigen::Vector3d a = V.row(F(f, 0)), b = V.row(F(f, 1)), c = V.row(F(f, 2));
    normal += (b - a).cross(c - a);
  }
  normal = normal.norm() > 0 ? normal.normalized() : Eigen::Vector3d::UnitZ();
  // Any right-handed basis of the plane keeps the faces counter-clockwise seen from the normal.
  const Eigen::Vector3d x = normal.unitOrthogonal(), y = normal.cross(x);
  Eigen::MatrixXd plane(V.rows(), 2);
  plane.col(0) = V * x;
  plane.col(1) = V * y;
  double best_area = INFINITY, best_angle = 0;
  for (int k = 0; k < kTuning.projection_turns; ++k) {
    const double angle = 0.5 * M_PI * k / kTuning.projection_turns, c = std::cos(angle), s = std::sin(angle);
    Eigen::AlignedBox2d box;
    for (Eigen::Index f = 0; f < F.rows(); ++f)
      for (int j = 0; j < 3; ++j) {
        const Eigen::Vector2d p = plane.row(F(f, j)).transpose();
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
  return plane * turn;
}

}  // namespace lowstretch
