// Where to cut a closed or higher-genus surface so that it opens into a disk.
#pragma once
#include <Eigen/Core>
#include <array>
#include <vector>

namespace lowstretch {

// The edges (vertex pairs) to cut in a manifold, consistently oriented, connected triangle array
// with at most one boundary loop (`boundary`, empty when closed) so that it becomes a disk:
// - genus > 0: a tree-cotree cut graph (Erickson and Whittlesey 2005): a shortest-path tree from
//   the boundary (or from vertex 0 when closed), a dual spanning tree that keeps the longest
//   loops uncut, and for each of the 2g edges left over, its loop of shortest paths; the loops
//   end on the boundary, so together with it they cut every handle.
// - closed genus 0: the shortest path between two far-apart vertices (at least two edges, so
//   that the cut opens).
// - a disk: nothing.
std::vector<std::array<int, 2>> cut_graph(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F,
                                          const std::vector<int>& boundary);

}  // namespace lowstretch
