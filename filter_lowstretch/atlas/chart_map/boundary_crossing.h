// Whether a chart's map overlaps itself although no triangle is flipped: a free (natural)
// boundary can fold over itself (a spiral, a long curled flap). With every triangle positive, the
// map can overlap only where its boundary crosses itself, so the boundary edges are tested pair by
// pair.
#pragma once
#include <Eigen/Core>

namespace lowstretch {

// F: the chart's faces; uv: a row per vertex. True if two boundary edges that share no vertex
// touch or cross in uv, or if the angles at a vertex add up to more than a full turn (two fans
// through one vertex, as a pinched boundary has, overlapping each other). The edges are swept
// along u, so that only those whose u-ranges overlap are tested; callers that try a free boundary
// on small charts only skip it above `most_edges`, returning true.
bool uv_boundary_crosses_itself(const Eigen::MatrixXi& F, const Eigen::MatrixXd& uv, int most_edges = 4000);

}  // namespace lowstretch
