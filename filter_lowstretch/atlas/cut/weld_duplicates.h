// A scan's duplicate vertices (a vertex copied to its own position, some faces moved onto the copy)
// welded for the charts: each leaves a crack of zero width between faces that meet in 3D, which a
// chart would have to keep as a hole or be cut along. Welding may make vertices or edges
// non-manifold; the manifold copy (split_vertex_fans.h) then splits them as it would any other.
#pragma once
#include <Eigen/Core>
#include <vector>

namespace lowstretch {

struct WeldedFaces {
  Eigen::MatrixXi F;          // the faces, each corner on the first used vertex at its position
  std::vector<int> onto;      // per vertex: the vertex it was welded onto (itself if none)
  int welded = 0;             // used vertices welded onto another
};

// Exact positions only: vertices a little apart are parts that touch, not duplicates.
WeldedFaces weld_duplicate_vertices(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F);

}  // namespace lowstretch
