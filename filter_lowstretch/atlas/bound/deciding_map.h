// The quick map that decides whether a chart is cut (or two charts merged); the layout maps each
// chart of the atlas fully.
#pragma once
#include "atlas/chart_map/solved_chart.h"
#include "core/parameterize.h"

namespace lowstretch {

// Deciding where to cut needs the map's stretch, not its last digits: U0 and U1 only, never
// refined, with a true residual up to 100 times the tolerance accepted before the sparse LU takes
// over, give the same cuts in less time.
Options deciding_options(Options deciding);

// Onto the chart's own rectangle, or the square where that may bring it under the bound (a chart
// too small to cut takes the better of the two).
void map_to_decide(SolvedChart& chart, const Options& deciding, double max_stretch);

}  // namespace lowstretch
