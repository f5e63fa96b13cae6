// Charts that no rectangle fits, mapped again free: with the natural boundary, or as seen along
// their normal (plane_projection.h).
#pragma once
#include <vector>

#include "atlas/charts.h"
#include "atlas/chart_map/solved_chart.h"

namespace lowstretch {

// How much better a free map must use its box: the rectangle's further passes and the free
// chart's cell, rarely of its shape, eat smaller gains.
constexpr double kFreeMustPay = 4;

// A chart whose rectangle uses its box poorly (kept above the bound: too small to cut, or its parts
// stretched more; or a hole closed for the map left empty) is mapped again free: with the natural
// boundary, or seen along its normal (a flat face of a CAD part, whose needles the natural boundary
// folds). It keeps the free map that uses its box best (fill / L2^2) if that beats the rectangle
// `must_pay` times and it does not fold over itself: a jagged sliver has no good rectangle, but
// maps free with little stretch.
void free_the_charts_that_stretch(std::vector<SolvedChart>& charts, const ChartOptions& options, double must_pay = kFreeMustPay);

// A chart seen along its normal at this L2 stretch or less is flat (a face of a CAD part).
constexpr double kFlatBelow = 1.02;

// Every flat chart on a rectangle that its own shape, seen along its normal, stretches less (a
// rectangle stretches a round or bent face) is mapped so, if that does not fold over itself. Its
// box is no longer filled: worth it where other charts go into the texels it leaves empty.
void see_flat_charts_along_normal(std::vector<SolvedChart>& charts);

}  // namespace lowstretch
