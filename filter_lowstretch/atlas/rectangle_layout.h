// Where the charts go: every chart is mapped onto a rectangle, so the rectangles can tile the
// unit square with nothing between them but the gutter. A squarified treemap (Bruls, Huizing and
// van Wijk 2000): the charts, largest first, are laid in rows along the shorter side of the space
// left, a row growing while that makes its cells squarer. Every cell's area is its chart's share,
// so the texel density is the same everywhere, and cells stay close to squares.
#pragma once
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <vector>

namespace lowstretch {

// areas: one positive number per chart. Returns each chart's cell; the cells tile [0,1]^2.
std::vector<Eigen::AlignedBox2d> slice_unit_square(const std::vector<double>& areas);

}  // namespace lowstretch
