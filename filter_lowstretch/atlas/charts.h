// A low-stretch atlas of any mesh, in stages (each a folder, each including only those before it):
//   base/      the shared types (atlas_types.h) and the tuning (tuning.h);
//   cut/       cutting a mesh into disk charts: components, holes closed virtually, closed or
//              higher-genus parts cut open along short seams, a manifold copy, sharp-edge patches;
//   chart_map/ mapping one chart with the paper's method onto a rectangle (or free);
//   bound/     cutting the charts that stretch more than the bound, or whose map is invalid;
//   pack/      the rectangles tiling the texture, small charts in the texels left empty;
//   measure/   the layout stored and measured as MeshLab holds it.
// This file chooses among the candidate atlases (charts.cpp) and is the entry point.
#pragma once
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <functional>
#include <string>
#include <vector>

#include "atlas/base/atlas_types.h"
#include "core/parameterize.h"

namespace lowstretch {

// A disk gives parameterize's result (one chart, the same UV), and with NonDisk::Atlas too
// when it meets max_stretch. Any other mesh gives parameterize's error unless options.non_disk
// makes charts and the only problems are several components, holes, no boundary or genus;
// non-manifold or non-orientable input stays an error.
ChartsResult parameterize_charts(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const ChartOptions& options);

// Texture efficiency (Sander et al. 2001): coverage / L2^2, the share of the texture used per unit
// of stretch; -1 for a failed result.
double texture_efficiency(const ChartsResult& result);
// The highest L2 stretch of any one chart (0 for a failed result).
double largest_chart_stretch(const ChartsResult& result);

// Whether making charts gets past this error of the disk check (a cut into disks or a manifold copy
// fixes it): the caller then adds how its user asks for charts.
bool charts_would_help(ErrorCode code);


}  // namespace lowstretch
