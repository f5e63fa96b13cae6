// Fixed boundary positions on a convex domain, spaced by 3D arc length.
#pragma once
#include <Eigen/Core>
#include <array>
#include <vector>

#include "disk_mesh.h"

namespace lowstretch {

// Cumulative arc length at each boundary vertex (size = loop length + 1, last = perimeter).
// Zero-length boundary edges get a small positive length so that no two points coincide.
std::vector<double> boundary_arc_lengths(const DiskMesh& disk);

// Boundary loop on the circle inscribed in [0,1]^2, counter-clockwise (rows follow disk.boundary).
Eigen::MatrixXd circle_boundary(const DiskMesh& disk);

// Boundary loop on the unit square with the loop positions `corners` (increasing) at the
// corners (0,0), (1,0), (1,1), (0,1); the points between two corners spaced by arc length.
// A side marked in `bow` becomes a parabola bulging outward by a quarter of its length, so
// that no three of its points are collinear (the domain stays convex), and the whole is fitted
// back into [0,1]^2.
Eigen::MatrixXd square_boundary(const DiskMesh& disk, const std::array<int, 4>& corners,
                                const std::array<bool, 4>& bow = {});

}  // namespace lowstretch
