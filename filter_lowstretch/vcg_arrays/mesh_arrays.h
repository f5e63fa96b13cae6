// Conversion between a vcglib triangle mesh (MeshLab's CMeshO or the tool's own mesh type) and
// the core's Eigen arrays. Meshes may carry deleted vertices and faces left by earlier filters:
// rows are made only of live elements, and the maps below say which element each row came from.
#pragma once
#include <Eigen/Core>
#include <limits>
#include <vector>

#include <vcg/complex/complex.h>

#include "atlas/charts.h"
#include "core/parameterize.h"

namespace lowstretch {

// Which mesh element each array row stands for (indices into m.vert and m.face).
struct ArrayRows {
  std::vector<int> vertex_index;  // row of V -> index in m.vert
  std::vector<int> face_index;    // row of F -> index in m.face
};

// V: one row per live vertex; F: one row per live face, in rows of V. A live face that refers to
// a deleted vertex keeps index -1, which the core rejects as an index out of range.
template <class MeshType>
ArrayRows mesh_to_arrays(const MeshType& m, Eigen::MatrixXd& V, Eigen::MatrixXi& F) {
  ArrayRows rows;
  std::vector<int> row_of_vertex(m.vert.size(), -1);
  for (size_t i = 0; i < m.vert.size(); ++i) {
    if (m.vert[i].IsD()) continue;
    row_of_vertex[i] = int(rows.vertex_index.size());
    rows.vertex_index.push_back(int(i));
  }
  for (size_t i = 0; i < m.face.size(); ++i)
    if (!m.face[i].IsD()) rows.face_index.push_back(int(i));

  V.resize(Eigen::Index(rows.vertex_index.size()), 3);
  for (size_t r = 0; r < rows.vertex_index.size(); ++r)
    for (int c = 0; c < 3; ++c) V(Eigen::Index(r), c) = double(m.vert[size_t(rows.vertex_index[r])].cP()[c]);

  F.resize(Eigen::Index(rows.face_index.size()), 3);
  for (size_t r = 0; r < rows.face_index.size(); ++r) {
    const auto& f = m.face[size_t(rows.face_index[r])];
    for (int k = 0; k < 3; ++k) {
      const auto* v = f.cV(k);
      const bool inside = v != nullptr && v >= &m.vert.front() && v <= &m.vert.back();
      F(Eigen::Index(r), k) = inside ? row_of_vertex[size_t(v - &m.vert.front())] : -1;
    }
  }
  return rows;
}

// The per-wedge texcoords of the faces of `rows` (#F x 6, corners 0, 1, 2), NaN where the mesh has
// none: the atlas to pack again (repack.h).
template <class MeshType>
Eigen::MatrixXd wedge_texcoords(const MeshType& m, const ArrayRows& rows) {
  Eigen::MatrixXd uv = Eigen::MatrixXd::Constant(Eigen::Index(rows.face_index.size()), 6, std::numeric_limits<double>::quiet_NaN());
  if (!vcg::tri::HasPerWedgeTexCoord(m)) return uv;
  for (size_t r = 0; r < rows.face_index.size(); ++r)
    for (int k = 0; k < 3; ++k) {
      const auto& t = m.face[size_t(rows.face_index[r])].cWT(k);
      uv.block(Eigen::Index(r), 2 * k, 1, 2) << double(t.U()), double(t.V());
    }
  return uv;
}

// Writes the result into components the caller has made available: per-wedge texcoords
// (texture index 0) from the per-corner UV (a seam vertex has one per side), per-vertex
// texcoords (one of the vertex's wedges, the only one for a disk; (0, 0) if no face uses it),
// per-vertex quality = vertex stretch and per-face quality = face stretch. Returns whether every
// vertex's wedges agree (no seam): otherwise the per-vertex texcoords hold one side of each seam
// only, and a caller that keeps them lets exporters take them for the wedges' (MeshLab's ASCII PLY
// writer does).
template <class MeshType>
bool write_parameterization(MeshType& m, const ArrayRows& rows, const ChartsResult& result) {
  using TexScalar = typename MeshType::FaceType::TexCoordType::ScalarType;
  using VertexTexScalar = typename MeshType::VertexType::TexCoordType::ScalarType;
  for (size_t r = 0; r < rows.vertex_index.size(); ++r) {
    auto& v = m.vert[size_t(rows.vertex_index[r])];
    v.Q() = typename MeshType::VertexType::QualityType(result.vertex_stretch(Eigen::Index(r)));
    v.T().U() = v.T().V() = VertexTexScalar(0);
    v.T().N() = 0;
  }
  for (size_t r = 0; r < rows.face_index.size(); ++r) {
    auto& f = m.face[size_t(rows.face_index[r])];
    for (int k = 0; k < 3; ++k) {
      f.WT(k).U() = TexScalar(result.corner_uv(Eigen::Index(r), 2 * k));
      f.WT(k).V() = TexScalar(result.corner_uv(Eigen::Index(r), 2 * k + 1));
      f.WT(k).N() = 0;
      f.V(k)->T().U() = VertexTexScalar(f.WT(k).U());
      f.V(k)->T().V() = VertexTexScalar(f.WT(k).V());
      f.V(k)->T().N() = 0;
    }
    f.Q() = typename MeshType::FaceType::QualityType(result.face_stretch(Eigen::Index(r)));
  }
  for (size_t r = 0; r < rows.face_index.size(); ++r) {
    const auto& f = m.face[size_t(rows.face_index[r])];
    for (int k = 0; k < 3; ++k)
      if (VertexTexScalar(f.cWT(k).U()) != f.cV(k)->cT().U() || VertexTexScalar(f.cWT(k).V()) != f.cV(k)->cT().V())
        return false;
  }
  return true;
}

}  // namespace lowstretch
