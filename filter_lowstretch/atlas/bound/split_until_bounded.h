// Charts cut by stretch: every chart is mapped, the ones the bound cuts are cut in two
// (split_chart.h) and their parts mapped again, round after round; then the cuts that did not
// pay are undone. A part far above the bound is cut again before it is mapped (cuts ahead).
#pragma once
#include <Eigen/Core>
#include <string>
#include <vector>

#include "atlas/base/atlas_types.h"
#include "atlas/chart_map/solved_chart.h"
#include "atlas/cut/split_chart.h"

namespace lowstretch {

// Cuts the charts that stretch too much and maps the parts again, round after round, until every
// chart meets the bound, is too small to cut or the chart limit is reached; then undoes the cuts
// that did not pay. Returns the leaves, and if any part was cut, the components as they were.
// `split`: where each chart is cut (split_chart.h).
Error split_until_bounded(const Eigen::MatrixXd& unit_V, const Eigen::MatrixXi& F, std::vector<std::vector<int>> components,
                          const ChartOptions& options, std::vector<SolvedChart>& leaves, std::vector<SolvedChart>& uncut,
                          std::vector<std::string>& notes, const SplitOptions& split = {});

// Whether every part, mapped whole as the cuts are decided, meets the bound (none would be cut).
// False too if a part cannot be mapped: split_until_bounded says why.
bool parts_meet_the_bound(const Eigen::MatrixXd& unit_V, const Eigen::MatrixXi& F, const std::vector<std::vector<int>>& parts,
                          const ChartOptions& options);

}  // namespace lowstretch
