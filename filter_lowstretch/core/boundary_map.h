// Fixed boundary positions on a convex domain, spaced by 3D arc length.
#pragma once
#include <Eigen/Core>
#include <array>
#include <string>
#include <vector>

#include "core/disk_mesh.h"
#include "core/method_types.h"

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
// (the domain stays convex). With ear_bulge > 0 the tip of an ear (a boundary triangle whose
// third edge is interior) bulges further, to ear_bulge times its ear's chord: the ear then keeps
// a fair share of its area, where the side's bulge alone leaves a sliver on a jagged boundary
// (at the cost of a box a little larger than the square). The ears lie outside the convex
// polygon through their chords, each over its own chord, so none overlaps.
// The whole is fitted back into [0,1]^2.
Eigen::MatrixXd square_boundary(const DiskMesh& disk, const std::array<int, 4>& corners,
                                const std::vector<int>& kinks = {}, double aspect = 1,
                                const std::vector<int>& ear_tips = {}, double ear_bulge = 0);
// The square boundary of the method (square_boundary at corners chosen by choose_square_corners),
// with a note where the corners had to move or sides to bend; `settings` (method_types.h) make it
// a rectangle with corners where the boundary turns and bulging ears.
Eigen::MatrixXd rectangle_boundary(const DiskMesh& disk, const RectangleSettings& settings, std::vector<std::string>& notes);
// 0.8%: small enough that the square map still covers nearly all of the texture; less bulge makes
// the triangles at the kinks thinner and raises their stretch.
constexpr double kKinkBulge = 0.008;

}  // namespace lowstretch
