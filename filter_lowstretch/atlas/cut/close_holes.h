// Virtual closing of holes: the solver then sees a single boundary loop.
#pragma once
#include <Eigen/Core>
#include <vector>

namespace lowstretch {

// Appends, for every loop except loops[keep], one vertex at the loop's centroid and a fan of
// triangles joining it to the loop (oriented like the mesh). The appended rows of V and F are
// the virtual ones: the caller drops them after solving, so the holes stay holes in the layout.
void close_holes(Eigen::MatrixXd& V, Eigen::MatrixXi& F, const std::vector<std::vector<int>>& loops, size_t keep);

}  // namespace lowstretch
