#include "atlas/bound/deciding_map.h"

#include <algorithm>
#include <limits>

#include "atlas/base/tuning.h"

namespace lowstretch {

Options deciding_options(Options deciding) {
  deciding.max_passes = std::min(deciding.max_passes, 1);
  deciding.solver.residual_accepted = std::max(deciding.solver.residual_accepted, 100 * deciding.solver.tolerance);
  deciding.solver.max_iterations = std::min(deciding.solver.max_iterations, kTuning.deciding_iterations);
  deciding.refine = false;  // the layouts refine the maps they keep
  return deciding;
}

void map_to_decide(SolvedChart& chart, const Options& deciding, double max_stretch) {
  const bool may_cut = int(chart.faces.size()) >= 2 * kTuning.smallest_chart;
  solve_chart(chart, deciding, 0, may_cut ? kTuning.square_may_meet * max_stretch : std::numeric_limits<double>::infinity());
  chart.deciding_map = true;
}

}  // namespace lowstretch
