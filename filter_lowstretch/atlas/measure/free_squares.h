// Squares in the texels a stored layout leaves free, a gutter or more from every chart, from each
// other and from the border: where the last step (valid_as_stored.h) puts the faces it moves, so
// that the layout that stays keeps its gutters.
#pragma once
#include <Eigen/Core>
#include <vector>

#include "atlas/base/atlas_types.h"

namespace lowstretch {

// corner_uv: the stored layout (inside the gutter of [0,1]^2); stays: per face, whether it keeps
// its place. The lower-left corners of `count` squares of `side` (in [0,1]^2's units), each
// square of the texel grid (base/tuning.h: most_grid_side) at least options.gutter texels from
// every face that stays, from the other squares and from the border; none if they do not all fit.
std::vector<Eigen::Vector2d> free_squares(const Eigen::MatrixXd& corner_uv, const std::vector<char>& stays, size_t count,
                                          double side, const ChartOptions& options);

}  // namespace lowstretch
