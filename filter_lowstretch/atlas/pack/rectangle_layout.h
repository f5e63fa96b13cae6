// Where the charts go: every chart is mapped onto a rectangle, so the rectangles can tile the
// unit square with nothing between them but the gutter. A squarified treemap (Bruls, Huizing and
// van Wijk 2000): the charts, largest first, are laid in rows along a side of the space left, a
// row growing while that brings its cells closer to their charts' preferred shapes (squares in
// the original). Every cell's area is its chart's share, so the texel density is the same
// everywhere. Four tilings are made (rows along the shorter or the longer side; a row grows while
// its worst cell or its mean cost improves); the one with the least area in cells too far from
// their charts' shapes (filled in part: a lower texel density), then the one whose cells fit
// best, is kept: a cell filled in part has a lower texel density, and the layout keeps it even.
#pragma once
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <vector>

namespace lowstretch {

// areas: one positive number per chart; preferred: the width / height each chart fits best (a
// chart may turn a quarter, so 2 and 1/2 are the same). Returns each chart's cell; the cells tile
// [0,1]^2.
std::vector<Eigen::AlignedBox2d> slice_unit_square(const std::vector<double>& areas, const std::vector<double>& preferred);

}  // namespace lowstretch
