// Shared by the tool's readers: element counts checked against the file size before anything is
// allocated, and the ToolMesh filled from plain arrays.
#pragma once
#include <limits>
#include <string>
#include <vector>

#include "tool/tool_mesh.h"

namespace lowstretch {

// Every vertex takes at least 6 bytes (ASCII "0 0 0\n"; binary: three 4-byte floats) and every
// face at least 4 (binary: a 1-byte count and three 1-byte indices). A header that declares
// more than the file can hold is refused before anything is allocated for it.
inline bool counts_fit(long long vertices, long long faces, long long size, std::string& error) {
  if (vertices < 0 || faces < 0 || vertices > (1LL << 31) - 1 || faces > (1LL << 31) - 1 ||
      vertices * 6 + faces * 4 > size) {
    error = "the header declares " + std::to_string(vertices) + " vertices and " + std::to_string(faces) +
            " faces, more than the " + std::to_string(size) + "-byte file can hold: the file is corrupt or cut short";
    return false;
  }
  return true;
}

// corners: three vertex indices per triangle, all in range; corner_uv: empty, or the texture
// coordinates of each corner (NaN where the file gives none). Without them every wedge is NaN:
// the file had no texture coordinates.
inline void fill_tool_mesh(const std::vector<vcg::Point3d>& points, const std::vector<int>& corners, ToolMesh& mesh,
                           const std::vector<vcg::Point2f>& corner_uv = {}) {
  mesh.Clear();
  auto vi = vcg::tri::Allocator<ToolMesh>::AddVertices(mesh, points.size());
  for (size_t i = 0; i < points.size(); ++i, ++vi) vi->P() = points[i];
  auto fi = vcg::tri::Allocator<ToolMesh>::AddFaces(mesh, corners.size() / 3);
  const float none = std::numeric_limits<float>::quiet_NaN();
  for (size_t f = 0; f < corners.size() / 3; ++f, ++fi)
    for (int k = 0; k < 3; ++k) {
      fi->V(k) = &mesh.vert[size_t(corners[3 * f + size_t(k)])];
      const vcg::Point2f uv = corner_uv.empty() ? vcg::Point2f(none, none) : corner_uv[3 * f + size_t(k)];
      fi->WT(k).U() = uv[0], fi->WT(k).V() = uv[1];
    }
}

}  // namespace lowstretch
