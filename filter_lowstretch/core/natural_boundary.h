// A free ("natural") boundary: the boundary of the least squares conformal map (Levy et al.
// 2002; equivalently Desbrun's natural conformal map) with two boundary vertices pinned.
#pragma once
#include <Eigen/Core>

#include "core/disk_mesh.h"
#include "core/errors.h"

namespace lowstretch {

// Rows follow disk.boundary, fitted into [0,1]^2 keeping the aspect ratio. Minimizes
// E_D(u) + E_D(v) - A(u, v) (cotangent Dirichlet energy minus the signed area) with the two
// boundary vertices farthest apart in 3D (approximately) pinned at (0,0) and (1,0).
Error natural_boundary(const DiskMesh& disk, Eigen::MatrixXd& boundary_uv);

}  // namespace lowstretch
