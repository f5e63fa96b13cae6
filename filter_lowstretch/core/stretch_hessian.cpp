#include "core/stretch_hessian.h"

#include <cmath>

namespace lowstretch {

Eigen::Matrix4d stretch_hessian(const Eigen::Matrix2d& J) {
  Eigen::Matrix4d C;  // vec(cofactor(J)) = C vec(J); det(J) = vec(J) . C vec(J) / 2
  C << 0, 0, 0, 1, 0, 0, -1, 0, 0, -1, 0, 0, 1, 0, 0, 0;
  const double det = J.determinant(), n = J.squaredNorm();
  const Eigen::Vector4d j(J(0, 0), J(0, 1), J(1, 0), J(1, 1)), c = C * j;
  const double d2 = det * det, d3 = d2 * det;
  return Eigen::Matrix4d::Identity() / d2 - 2 * (j * c.transpose() + c * j.transpose()) / d3 - n * C / d3 +
         3 * n * c * c.transpose() / (d2 * d2);
}

Eigen::Matrix4d projected_stretch_hessian(const Eigen::Matrix2d& J) {
  const double det = J.determinant();
  // The nearest rotation Q = [p -q; q p] / sqrt(p^2 + q^2) (det > 0), and R Q = [-q -p; p -q].
  const double p = J(0, 0) + J(1, 1), q = J(1, 0) - J(0, 1);
  const Eigen::Vector4d twist = Eigen::Vector4d(-q, -p, p, -q) / std::sqrt(2 * (p * p + q * q));
  const double twist_eigenvalue = -(J.squaredNorm() - det) / (det * det * det);
  return stretch_hessian(J) - twist_eigenvalue * twist * twist.transpose();
}

}  // namespace lowstretch
