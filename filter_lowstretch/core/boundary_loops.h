// The boundary loops of a manifold, consistently oriented triangle array.
#pragma once
#include <Eigen/Core>
#include <vector>

namespace lowstretch {

// Each loop lists its vertices in order, the faces on its left. twin: opposite_half_edges(F).
std::vector<std::vector<int>> boundary_loops(const Eigen::MatrixXi& F, const std::vector<int>& twin, int vertex_count);

// The index of the loop with the greatest 3D length (0 if there are none).
size_t longest_loop(const Eigen::MatrixXd& V, const std::vector<std::vector<int>>& loops);

}  // namespace lowstretch
