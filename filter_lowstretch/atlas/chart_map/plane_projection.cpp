#include "atlas/chart_map/plane_projection.h"

#include <Eigen/Geometry>

#include "atlas/chart_map/smallest_box.h"

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
  return turned_to_smallest_box(plane, F);
}

}  // namespace lowstretch
