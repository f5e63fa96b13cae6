// Where parts or holes touch at a single vertex (scans with dropouts have many such vertices),
// the atlas gives each fan of faces around the vertex its own copy of it: the charts see a
// manifold mesh, and since texture coordinates are stored per face corner, the input mesh
// itself is not changed.
#pragma once
#include <Eigen/Core>
#include <vector>

namespace lowstretch {

struct SplitFans {
  Eigen::MatrixXd V;         // the input's vertices, then one copy per extra fan
  Eigen::MatrixXi F;         // the input's faces, each corner on its fan's vertex
  std::vector<int> origin;   // input vertex of each vertex of V
  int split_vertices = 0;    // input vertices with more than one fan
};

// Keeps the first fan of a vertex (in corner order) on the vertex itself; every other fan gets a
// new vertex at the same position. F must be edge-manifold and consistently oriented.
SplitFans split_vertex_fans(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F);

// Per input vertex from per split vertex: the root mean square of the copies' values, each
// weighted by the 3D area of its faces (as the stretch of a vertex weighs its faces).
Eigen::VectorXd join_vertex_values(const SplitFans& split, const Eigen::VectorXd& value, int input_vertices);

}  // namespace lowstretch
