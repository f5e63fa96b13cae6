// The last step before an atlas (or a disk's single chart) is returned: every face with 3D area
// gets a UV triangle of positive area as stored in float, whatever made it invalid (a map that
// folds: negative weights, a free boundary; a needle that float rounding collapses; a step that
// fell back to a worse layout). Where a face is invalid:
//   1. a chart holding a flipped face is mapped again with the paper's map onto a square with
//      Floater's weights, which cannot fold (a chart that is not a disk is taken apart instead);
//   2. every face still invalid becomes a chart of its own, its 3D shape (a needle: a right
//      triangle) in a square of the texels the layout leaves free, a gutter from everything
//      (free_squares.h); where they do not all fit, in a cell of a grid along the top of the
//      texture, the rest of the layout scaled below it, each chart shrunk to keep its gutters;
// and the result is stored and measured again, until no face is invalid. So a result that is not
// an error always holds a valid atlas.
#pragma once
#include <Eigen/Core>

#include "atlas/base/atlas_types.h"

namespace lowstretch {

// unit_V: the input's vertices in the unit box (as the atlas measures them), unit: the input's
// length of one unit-box unit; vertex_rows: the input's vertex count. A failed result, or one
// with no invalid face, comes back as it was; ChartsNotPacked if faces stay invalid.
ChartsResult valid_as_stored(const Eigen::MatrixXd& unit_V, const Eigen::MatrixXi& F, double unit, int vertex_rows,
                             const ChartOptions& options, ChartsResult result);

}  // namespace lowstretch
