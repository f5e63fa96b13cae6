// The atlas as the user gets it: the charts' maps laid out, moved inside the gutter, rounded to
// float as MeshLab stores them and measured (the paper's metrics of the whole layout, each
// chart's stretch, seams, coverage), with notes on the charts that stay above the bound.
#pragma once
#include <Eigen/Core>
#include <vector>

#include "atlas/base/atlas_types.h"
#include "atlas/chart_map/solved_chart.h"

namespace lowstretch {

// A result that carries only `error`.
ChartsResult failed_result(Error error);

// The charts laid out and measured as the result; the guests go into texels the tiling leaves
// empty (lay_out). Charts with invalid faces as stored, specks aside, are cut and laid out again
// (cut_invalid_charts.h). The `flat` faces (of no 3D area, in no chart) sit on one point.
ChartsResult atlas_of(std::vector<SolvedChart> charts, std::vector<int> guests, const Eigen::MatrixXd& unit_V,
                      const Eigen::MatrixXi& F, double unit, int vertex_rows, const ChartOptions& options,
                      std::vector<int> flat = {});

// A layout of the charts (result.corner_uv in [0,1]^2 and result.face_chart, for the charts'
// faces) measured as atlas_of's: the flat faces on one point, the charts' summaries, seams and
// notes, then stored.
ChartsResult stored_layout(const std::vector<SolvedChart>& charts, const std::vector<int>& flat, ChartsResult result,
                           const Eigen::MatrixXd& unit_V, const Eigen::MatrixXi& F, double unit, int vertex_rows,
                           const ChartOptions& options);

// The layout as MeshLab stores it: inside the gutter, rounded to float, then measured; counts
// the triangles no texture shows (smaller than a texel of 4096^2) and those that rounding flips or
// collapses (a note).
void store(const Eigen::MatrixXd& unit_V, const Eigen::MatrixXi& F, int vertex_rows,
           const std::vector<std::vector<int>>& faces_of, const ChartOptions& options, ChartsResult& result);

// 3D length of the edges whose two faces are in different charts (face_chart: each face's).
double length_between_charts(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const std::vector<int>& face_chart);

// The measures of `from` (stretch, distortions, flips) into `to`, whose pass and timings stay.
void copy_measures(const PassMetrics& from, PassMetrics& to);

}  // namespace lowstretch
