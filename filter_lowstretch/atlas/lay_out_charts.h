// Where the charts go: the rectangles tile the unit square (rectangle_layout.h), every chart at
// the same texel density, each mapped again onto its cell's shape.
#pragma once
#include <Eigen/Core>
#include <vector>

#include "charts.h"
#include "solved_chart.h"

namespace lowstretch {

// Every chart onto its cell of the tiling: mapped again onto a rectangle of the cell's shape
// (turned a quarter if the chart is wider the other way), then fitted into the cell less half
// the gutter on each side. Fills corner_uv and face_chart.
Error lay_out(std::vector<SolvedChart>& charts, const ChartOptions& options, Eigen::Index face_count, ChartsResult& result);

}  // namespace lowstretch
