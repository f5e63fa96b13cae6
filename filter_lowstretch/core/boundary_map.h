// Fixed boundary positions on a convex domain, spaced by 3D arc length.
#pragma once
#include <Eigen/Core>
#include <array>
#include <string>
#include <vector>

#include "core/disk_mesh.h"
#include "core/square_corners.h"

namespace lowstretch {

// Cumulative arc length at each boundary vertex (size = loop length + 1, last = perimeter).
// Zero-length boundary edges get a small positive length so that no two points coincide.
std::vector<double> boundary_arc_lengths(const DiskMesh& disk);

// Boundary loop on the circle inscribed in [0,1]^2, counter-clockwise (rows follow disk.boundary).
Eigen::MatrixXd circle_boundary(const DiskMesh& disk);

// Boundary loop on the unit square with the loop positions `corners` (increasing) at the
// corners (0,0), (1,0), (1,1), (0,1); the points between two corners spaced by arc length.
// With `aspect` != 1 the square is a rectangle of that width / height, and with aspect 0 the
// rectangle whose sides are as long as the arcs between corners (mean of opposite sides).
// A side that holds loop positions of `kinks` bulges outward, by at most kKinkBulge of its
// length, as a concave polyline that bends at each of them: every interior edge joining two
// points of that side with a kink strictly between them then spans a triangle of positive area
// (the domain stays convex). square_sides leaves the rectangle at its own size (width aspect,
// height 1, for a caller that moves points before fitting); square_boundary fits it into [0,1]^2.
Eigen::MatrixXd square_sides(const DiskMesh& disk, const std::array<int, 4>& corners, const std::vector<int>& kinks = {},
                             double aspect = 1);
Eigen::MatrixXd square_boundary(const DiskMesh& disk, const std::array<int, 4>& corners,
                                const std::vector<int>& kinks = {}, double aspect = 1);
// uv moved and scaled uniformly so that its box starts at (0,0) and its longer side is 1.
Eigen::MatrixXd fitted_into_unit_box(const Eigen::MatrixXd& uv);
// The paper's square: square_boundary at the corners choose_square_corners picks, with a note
// (note_square_corners) where they had to move or sides to bend.
Eigen::MatrixXd paper_square_boundary(const DiskMesh& disk, std::vector<std::string>& notes);
void note_square_corners(const SquareCorners& corners, std::vector<std::string>& notes);
// 0.8%: small enough that the square map still covers nearly all of the texture; less bulge makes
// the triangles at the kinks thinner and raises their stretch.
constexpr double kKinkBulge = 0.008;

}  // namespace lowstretch
