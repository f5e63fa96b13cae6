// One triangle's stretch Hessian (core/stretch_hessian.h), each result computed a second way: the
// Hessian by finite differences of the energy, its projection by a numerical eigen-decomposition.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <random>
#include <vector>

#include "core/stretch_hessian.h"

using namespace lowstretch;

namespace {

double psi(const Eigen::Vector4d& j) {
  Eigen::Matrix2d J;
  J << j(0), j(1), j(2), j(3);
  return J.squaredNorm() / (2 * J.determinant() * J.determinant());
}

Eigen::Vector4d as_vector(const Eigen::Matrix2d& J) { return Eigen::Vector4d(J(0, 0), J(0, 1), J(1, 0), J(1, 1)); }

// Jacobians with det > 0: rotations of diag(s1, s2) with s1 / s2 from 1 to 1000, and random ones.
std::vector<Eigen::Matrix2d> jacobians() {
  std::vector<Eigen::Matrix2d> found;
  std::mt19937 random(11);
  std::uniform_real_distribution<double> entry(-2, 2), angle(-3.1, 3.1);
  const auto rotation = [](double a) { return Eigen::Rotation2Dd(a).toRotationMatrix(); };
  for (const double s2 : {1.0, 0.9, 0.5, 0.1, 0.001})
    for (int k = 0; k < 4; ++k)
      found.push_back(rotation(angle(random)) * Eigen::Vector2d(1.3, 1.3 * s2).asDiagonal() * rotation(angle(random)));
  while (found.size() < 60) {
    Eigen::Matrix2d J;
    J << entry(random), entry(random), entry(random), entry(random);
    if (J.determinant() > 0.05) found.push_back(J);
  }
  return found;
}

}  // namespace

TEST(StretchHessian, MatchesFiniteDifferencesOfTheEnergy) {
  for (const Eigen::Matrix2d& J : jacobians()) {
    const Eigen::Vector4d j = as_vector(J);
    const double h = 1e-4 * J.determinant() / j.norm();  // well inside the distance to a collapse
    Eigen::Matrix4d numeric;
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b) {
        const Eigen::Vector4d ea = h * Eigen::Vector4d::Unit(a), eb = h * Eigen::Vector4d::Unit(b);
        numeric(a, b) = (psi(j + ea + eb) - psi(j + ea - eb) - psi(j - ea + eb) + psi(j - ea - eb)) / (4 * h * h);
      }
    const Eigen::Matrix4d exact = stretch_hessian(J);
    EXPECT_LT((exact - numeric).norm(), 1e-5 * exact.norm()) << "J =\n" << J;
  }
}

TEST(StretchHessian, OnlyTheTwistEigenvalueIsNegative) {
  for (const Eigen::Matrix2d& J : jacobians()) {
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix4d> eigen(stretch_hessian(J));
    const double det = J.determinant();
    const double twist = -(J.squaredNorm() - det) / (det * det * det);
    const double scale = eigen.eigenvalues().cwiseAbs().maxCoeff();
    EXPECT_NEAR(eigen.eigenvalues()(0), twist, 1e-9 * scale) << "J =\n" << J;
    EXPECT_GT(eigen.eigenvalues()(1), 0) << "J =\n" << J;
  }
}

TEST(StretchHessian, ProjectionEqualsTheNumericalOne) {
  for (const Eigen::Matrix2d& J : jacobians()) {
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix4d> eigen(stretch_hessian(J));
    const Eigen::Matrix4d clamped =
        eigen.eigenvectors() * eigen.eigenvalues().cwiseMax(0.0).asDiagonal() * eigen.eigenvectors().transpose();
    const Eigen::Matrix4d projected = projected_stretch_hessian(J);
    EXPECT_LT((projected - clamped).norm(), 1e-9 * clamped.norm()) << "J =\n" << J;
    EXPECT_GE(Eigen::SelfAdjointEigenSolver<Eigen::Matrix4d>(projected).eigenvalues()(0), -1e-9 * clamped.norm());
  }
}
