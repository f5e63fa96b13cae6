// Charts that no rectangle fits, mapped again free: with the natural boundary, or as seen along
// their normal (plane_projection.h).
#pragma once
#include <vector>

#include "atlas/base/tuning.h"
#include "atlas/base/atlas_types.h"
#include "atlas/chart_map/solved_chart.h"

namespace lowstretch {

// A chart of the same faces, with no map yet.
SolvedChart unmapped_copy(const SolvedChart& chart);

// Whether a free map's outline crosses itself (so the map overlaps itself).
bool crosses_itself(const SolvedChart& free);

// A chart whose rectangle uses its box poorly (kept above the bound: too small to cut, or its parts
// stretched more; or a hole closed for the map left empty) is mapped again free: with the natural
// boundary, or seen along its normal (a flat face of a CAD part, whose needles the natural boundary
// folds). It keeps the free map that uses its box best (fill / L2^2) if that beats the rectangle
// `must_pay` times and it does not fold over itself: a jagged sliver has no good rectangle, but
// maps free with little stretch.
void free_the_charts_that_stretch(std::vector<SolvedChart>& charts, const ChartOptions& options, double must_pay = kTuning.free_must_pay);

// Every chart on a rectangle above kTuning.free_above whose free map (natural boundary, or seen
// along its normal) stretches less is mapped so, if that does not fold over itself, and turned to
// its smallest box (turn_free_charts_to_smallest_box): packed by its outline, a chart costs its own
// area rather than its box. How many were.
int free_where_it_stretches_less(std::vector<SolvedChart>& charts, const ChartOptions& options);

// Whether free_where_it_stretches_less tries the chart free.
bool may_free_for_less_stretch(const SolvedChart& chart);

// With options.disk.refine: every free chart that uses its box better (fill / L2^2) with the
// natural boundary refined with its boundary moving too (core/refine_stretch.h) is mapped so, if
// that does not fold over itself. Where to free a chart is decided on maps refined with the
// boundary kept: a moving boundary would free a lone chart that packs better on its rectangle.
void refine_free_outlines(std::vector<SolvedChart>& charts, const ChartOptions& options);

// Every flat chart on a rectangle that its own shape, seen along its normal, stretches less (a
// rectangle stretches a round or bent face) is mapped so, if that does not fold over itself. Its
// box is no longer filled: worth it where other charts go into the texels it leaves empty.
void see_flat_charts_along_normal(std::vector<SolvedChart>& charts);

// Every free chart turned in its plane so that its box is smallest, which leaves its stretch as it
// is: the natural boundary lies along its pins, and the outline packer turns charts only by quarter
// turns. Not for tiling: a cell may fit the squarer box of a free map as it came better.
void turn_free_charts_to_smallest_box(std::vector<SolvedChart>& charts);

}  // namespace lowstretch
