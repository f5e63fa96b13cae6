// A low-stretch atlas of any mesh, in stages (each a folder, each including only those before it):
//   base/      the shared types (atlas_types.h) and the tuning (tuning.h);
//   cut/       cutting a mesh into disk charts: components, holes closed virtually, closed or
//              higher-genus parts cut open along short seams, a manifold copy, sharp-edge patches;
//   chart_map/ mapping one chart with the paper's method onto a rectangle (or free);
//   bound/     cutting the charts that stretch more than the bound, or whose map is invalid;
//   pack/      the rectangles tiling the texture, small charts in the texels left empty;
//   measure/   the layout stored and measured as MeshLab holds it;
//   prepare/   the input made ready once, up front (welded duplicates, a manifold copy, parts of
//              zero area left out), and the charts of what was charted given back for the input;
//   search/    the candidate atlases, each cut, mapped, laid out and measured, the best kept.
// This file is the entry point: it prepares the input, keeps a disk's own map where that is
// better (charts.cpp), hands the rest to search/, and checks the result as it is stored.
#pragma once
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <functional>
#include <string>
#include <vector>

#include "atlas/base/atlas_types.h"
#include "atlas/prepare/prepare_input.h"  // charts_would_help
#include "core/parameterize.h"

namespace lowstretch {

// A disk gives parameterize's result (one chart, the same UV), and with NonDisk::Atlas too
// when it meets max_stretch. Any other mesh gives parameterize's error unless options.non_disk
// makes charts and the only problems are several components, holes, no boundary or genus;
// non-manifold or non-orientable input stays an error.
ChartsResult parameterize_charts(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const ChartOptions& options);

// result.least_gutter of a valid result, looked for up to twice options.gutter.
void measure_gutter(const ChartOptions& options, ChartsResult& result);

// The options' values in range (InvalidOption names the first that is not).
Error check_chart_options(const ChartOptions& options);


}  // namespace lowstretch
