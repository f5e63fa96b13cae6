// The rectangle a chart is mapped onto: the paper's square boundary (core/boundary_map.h) as the
// atlas sets it for a chart cut out of a larger mesh, whose boundary often has four sharp turns
// already and many ears left by cuts along mesh edges.
#pragma once
#include <Eigen/Core>
#include <string>
#include <vector>

#include "core/disk_mesh.h"

namespace lowstretch {

struct RectangleSettings {
  double aspect = 1;     // width / height; 0: as long as the arcs between the corners
  double ear_bulge = 0;  // how far an ear's tip goes out, in its chord's lengths, from 0 to 1
};

// The boundary loop's UV (rows follow disk.boundary), fitted into [0,1]^2: corners at the loop's
// sharpest turns where they collapse no triangle (else where the paper puts them), sides of the
// rectangle of `aspect`, each ear's tip (a boundary vertex whose two neighbours share an interior
// edge) pushed out to ear_bulge times its chord, where a straight side would squeeze the ear to
// a sliver. The ears lie outside the convex polygon through their chords, each over its own
// chord, so none overlaps. Notes where the corners moved or sides bent, as the core's square.
Eigen::MatrixXd chart_rectangle(const DiskMesh& disk, const RectangleSettings& settings, std::vector<std::string>& notes);

}  // namespace lowstretch
