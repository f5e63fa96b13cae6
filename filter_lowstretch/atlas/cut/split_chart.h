// Where to cut a chart whose map stretches too much. The chart is cut across its longest extent
// (the two faces farthest apart, as Iso-charts seeds its splits), at the level set of the
// difference of distances to them that gives the shortest seam for the area it separates: a neck
// or a protrusion's base. Seams along creases count as shorter, so that they follow sharp edges.
// The faces near that level set then take the side of the cheapest seam among them
// (cheapest_seam.h): a level set of distances over faces zigzags, the cheapest seam does not.
#pragma once
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <vector>

namespace lowstretch {

struct SplitOptions {
  double smallest_part = 0.05;  // neither side of the cut holds less of the chart's area
  double crease_discount = 0.5;  // a seam edge at a right-angle crease costs this much of its length
  // Faces whose difference of distances is within this share of the chart's extent of the level
  // set's may change side for a cheaper seam (0: the level set is the seam).
  double seam_band = 0.3;
};

// faces: the chart's faces (indices into F), edge-connected; twin: opposite_half_edges(F).
// Returns its parts, each edge-connected, every face in exactly one, in the order of their first
// face in `faces`; a single part (the chart itself) when it cannot be cut. No part is a sliver:
// faces with two neighbours across the cut change side, and pieces under 1% of the area join
// their neighbour.
std::vector<std::vector<int>> split_chart(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const std::vector<int>& twin,
                                          const std::vector<int>& faces, const SplitOptions& options = {});

}  // namespace lowstretch
