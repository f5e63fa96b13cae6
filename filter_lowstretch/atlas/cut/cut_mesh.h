// Opening a mesh along seams: every seam edge becomes two boundary edges, and a vertex on the
// seam becomes one vertex per side (the wedges of per-corner texture coordinates).
#pragma once
#include <Eigen/Core>
#include <array>
#include <vector>

namespace lowstretch {

struct CutMesh {
  Eigen::MatrixXi F;                 // same faces, same corner order, new vertex indices
  std::vector<int> original_vertex;  // new vertex -> vertex of the input
};

// F must be edge-manifold, consistently oriented and vertex-manifold.
CutMesh cut_along(const Eigen::MatrixXi& F, const std::vector<std::array<int, 2>>& seams);

}  // namespace lowstretch
