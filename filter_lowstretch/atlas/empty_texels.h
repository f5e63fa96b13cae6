// Small charts put into the texels a tiling leaves empty: the holes of charts with closed holes,
// the corners of free charts' cells, the parts of cells a chart fills only in part. The layout is
// drawn on the texture's own texel grid, every chart grown by the gutter, and each small chart's
// box goes where it first fits (lowest row, then column, either way round), at the texel density
// of the tiled charts. Nothing is moved that is already placed, so no overlap can come of it.
#pragma once
#include <Eigen/Core>
#include <vector>

#include "charts.h"
#include "solved_chart.h"

namespace lowstretch {

// Below this share of empty texels there is nothing worth filling (statues tile at 0.95 or more).
constexpr double kLeastEmptyShare = 0.05;

// The charts worth taking out of the tiling to be put into empty texels: rectangles that fill
// their box (a box is all the placement sees), smallest first, while their area stays under a
// share of the texture the tiling is expected to leave empty (closed holes, free charts' cells).
// own_area: each chart's cell area in the tiling (area / fill for charts that do not fill their box).
std::vector<int> charts_to_put_in_empty_texels(const std::vector<SolvedChart>& charts, const std::vector<double>& own_area);

// corner_uv holds the layout of every chart but `guests` in [0,1]^2 (store() moves it inside the
// gutter). Each guest goes into empty texels at the tiled charts' texel density, `gutter` texels or
// more from every other chart and from the border; its corners are written and face_chart set.
// Returns the guests that found no room (their corners are left as they were).
std::vector<int> put_in_empty_texels(const std::vector<SolvedChart>& charts, const std::vector<int>& guests,
                                     const ChartOptions& options, Eigen::MatrixXd& corner_uv, std::vector<int>& face_chart);

}  // namespace lowstretch
