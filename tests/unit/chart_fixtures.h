// Atlases and charts made the same way by several unit tests of the atlas.
#pragma once
#include <vector>

#include "atlas/chart_map/solved_chart.h"
#include "atlas/charts.h"
#include "generated_meshes.h"

namespace lowstretch {

// NonDisk::Atlas: a disk too is cut while it stretches more than the bound.
ChartsResult bounded_atlas(const testmesh::Mesh& m, double max_stretch = ChartOptions().max_stretch, int max_charts = 1000);
// bounded_atlas with no charts merged for shorter seams: the charts as cut and packed.
ChartsResult unmerged_atlas(const testmesh::Mesh& m, double max_stretch);
// A texture so fine that the gutter costs no measurable area: every chart at one texel density.
ChartsResult fine_charts_of(const testmesh::Mesh& m, double max_stretch = 1e5);
// All of m's faces `faces` (all of them if empty) as one chart, mapped by the method onto its own rectangle.
SolvedChart solved_chart_of(const testmesh::Mesh& m, std::vector<int> faces = {});
// The UV area of a chart's real faces (not those closing its holes), summed here.
double real_uv_area(const SolvedChart& c);

}  // namespace lowstretch
