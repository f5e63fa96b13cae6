#include "atlas/cut/close_holes.h"

namespace lowstretch {

void close_holes(Eigen::MatrixXd& V, Eigen::MatrixXi& F, const std::vector<std::vector<int>>& loops, size_t keep) {
  Eigen::Index vertices = V.rows(), faces = F.rows();
  for (size_t l = 0; l < loops.size(); ++l)
    if (l != keep) {
      ++vertices;
      faces += Eigen::Index(loops[l].size());
    }
  V.conservativeResize(vertices, 3);
  F.conservativeResize(faces, 3);
  Eigen::Index v = vertices, f = faces;
  for (size_t l = loops.size(); l-- > 0;) {
    if (l == keep) continue;
    const std::vector<int>& loop = loops[l];
    --v;
    V.row(v).setZero();
    for (int i : loop) V.row(v) += V.row(i) / double(loop.size());
    // The loop runs a -> b with the mesh on its left; the filling face holds b -> a.
    for (size_t i = 0; i < loop.size(); ++i) F.row(--f) << loop[(i + 1) % loop.size()], loop[i], int(v);
  }
}

}  // namespace lowstretch
