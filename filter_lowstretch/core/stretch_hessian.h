// The second derivatives behind refine_stretch's Newton steps. One triangle's L2 stretch energy
// as a function of its map's Jacobian J (from the triangle, in a plane of its own, to UV):
//   psi(J) = |J|_F^2 / (2 det(J)^2) = (1/s1^2 + 1/s2^2) / 2,  s1, s2 the singular values of J,
// which is sigma(T)^2 (Sander et al. 2001) as refine_stretch.h defines it. Matrices act on
// vec(J) = (J00, J01, J10, J11). Both need det(J) > 0.
#pragma once
#include <Eigen/Core>
#include <Eigen/LU>

namespace lowstretch {

// The Hessian of psi with respect to vec(J).
Eigen::Matrix4d stretch_hessian(const Eigen::Matrix2d& J);

// That Hessian with its negative eigenvalues set to zero (projected Newton, Teran et al. 2005), in
// closed form: psi depends on the singular values only, so its eigenvectors are known (Smith et
// al. 2019, "Analytic eigensystems for isotropic distortion energies"). Of the four eigenvalues,
// scaling 3/s1^4 and 3/s2^4 and flip (s1^2 + s1 s2 + s2^2) / (s1 s2)^3 are positive; the twist's,
// -(s1^3 + s2^3) / ((s1 s2)^3 (s1 + s2)) = -(|J|^2 - det) / det^3, is always negative. Its
// eigenvector is vec(R Q) / sqrt(2), R the quarter turn, Q the rotation nearest J.
Eigen::Matrix4d projected_stretch_hessian(const Eigen::Matrix2d& J);

}  // namespace lowstretch
