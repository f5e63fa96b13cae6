// Where the charts go: the rectangles tile the unit square (rectangle_layout.h), every chart at
// the same texel density, each mapped again onto its cell's shape; some small ones may instead go
// into the texels the tiling leaves empty (empty_texels.h).
#pragma once
#include <Eigen/Core>
#include <vector>

#include "atlas/base/atlas_types.h"
#include "atlas/chart_map/solved_chart.h"

namespace lowstretch {

// Each chart's area in the tiling: its 3D area, over the share of its box it fills if it is free
// or has closed holes (so that every chart has the same texel density).
std::vector<double> cell_areas(const std::vector<SolvedChart>& charts);

// A chart that keeps its own shape (packed by outline, or put into empty texels) mapped fully if
// its map was made only to decide: free, or onto its own rectangle, as it was.
void map_at_own_shape(SolvedChart& chart, const Options& options);
// Every chart so, on the thread pool, largest first: once, before layouts that each copy the charts.
void map_all_at_own_shape(std::vector<SolvedChart>& charts, const ChartOptions& options);

// Every chart but the guests onto its cell of the tiling: mapped again onto a rectangle of the
// cell's shape (turned a quarter if the chart is wider the other way), then fitted into the cell
// less half the gutter on each side; then the guests into empty texels, those without room going
// back into the tiling (ChartsNotPacked if some still find none). Fills corner_uv and face_chart.
// Every chart a guest: all packed by outline, outline_density as pack_by_outline's density.
Error lay_out(std::vector<SolvedChart>& charts, const ChartOptions& options, Eigen::Index face_count,
              const std::vector<int>& guests, ChartsResult& result, double& outline_density);

// A repair round's layout by outline (every chart a guest): the charts that were not cut stay where
// the last round put them (last_uv: its corner_uv as laid out; was: each chart's index there, -1
// for a piece cut since), and the pieces go into the texels left empty, at the same density.
// False if a piece finds no room (a whole layout is then needed; result means nothing).
bool lay_out_around(std::vector<SolvedChart>& charts, const ChartOptions& options, const Eigen::MatrixXd& last_uv,
                    const std::vector<int>& was, ChartsResult& result);

}  // namespace lowstretch
