// Scans have non-manifold edges (fins, faces glued three or four to an edge), edges whose two
// faces disagree on orientation, faces that name one vertex twice, and parts or holes that touch
// at a single vertex. The atlas makes its charts on a manifold copy: it cuts the mesh open along
// every edge that is not shared by exactly two faces of opposite orientation, gives every fan of
// faces around a vertex its own copy of the vertex, and gives a face that names a vertex twice
// corners of its own. Texture coordinates are stored per face corner, so the input mesh itself
// is not changed.
#pragma once
#include <Eigen/Core>
#include <vector>

namespace lowstretch {

struct SplitFans {
  Eigen::MatrixXd V;         // the input's vertices, then one copy per extra fan
  Eigen::MatrixXi F;         // the input's faces, each corner on its fan's vertex
  std::vector<int> origin;   // input vertex of each vertex of V
  int split_vertices = 0;    // input vertices with more than one fan (cut edges' ends included)
  int non_manifold_edges = 0;   // edges of the input shared by more than two faces
  int misoriented_edges = 0;    // edges of the input whose two faces run the same way
  int repeated_vertex_faces = 0;  // faces that name one vertex twice (zero area)
  int new_vertices = 0;         // rows of V after the input's
};

// Keeps the first fan of a vertex (in corner order) on the vertex itself; every other fan gets a
// new vertex at the same position. Faces are joined only across edges that exactly two faces
// share with opposite orientation, so the result is edge-manifold and consistently oriented.
// F's indices must be in range.
SplitFans split_vertex_fans(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F);

// Per input vertex from per split vertex: the root mean square of the copies' values, each
// weighted by the 3D area of its faces (as the stretch of a vertex weighs its faces).
Eigen::VectorXd join_vertex_values(const SplitFans& split, const Eigen::VectorXd& value, int input_vertices);

}  // namespace lowstretch
