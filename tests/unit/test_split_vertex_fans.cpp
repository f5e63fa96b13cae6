// The manifold copy the charts are made on: cut along bad edges, split at bad vertices.
#include <gtest/gtest.h>

#include <map>
#include <utility>

#include "atlas/cut/split_vertex_fans.h"
#include "core/half_edges.h"
#include "generated_meshes.h"

using namespace lowstretch;

namespace {

// Every edge of F is shared by at most two faces, and two faces run it in opposite directions.
void expect_manifold_edges(const Eigen::MatrixXi& F) {
  std::map<std::pair<int, int>, int> directed;
  for (Eigen::Index f = 0; f < F.rows(); ++f)
    for (int k = 0; k < 3; ++k) ++directed[{F(f, k), F(f, (k + 1) % 3)}];
  for (const auto& d : directed) {
    EXPECT_EQ(d.second, 1) << "edge " << d.first.first << "-" << d.first.second << " run twice the same way";
    EXPECT_NE(d.first.first, d.first.second) << "a face names a vertex twice";
  }
}

// The copy's faces are the input's faces, corner by corner, on copies at the same position.
void expect_same_faces(const testmesh::Mesh& m, const SplitFans& split) {
  ASSERT_EQ(split.F.rows(), m.F.rows());
  ASSERT_EQ(split.origin.size(), size_t(split.V.rows()));
  for (Eigen::Index f = 0; f < m.F.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int v = split.F(f, k);
      EXPECT_EQ(split.origin[size_t(v)], m.F(f, k));
      EXPECT_EQ(split.V.row(v), m.V.row(m.F(f, k)));
    }
}

}  // namespace

TEST(SplitVertexFans, AManifoldOrientedMeshIsUnchanged) {
  const testmesh::Mesh m = testmesh::torus(8, 6);
  const SplitFans split = split_vertex_fans(m.V, m.F);
  EXPECT_EQ(split.new_vertices, 0);
  EXPECT_EQ(split.F, m.F);
  EXPECT_EQ(split.non_manifold_edges + split.misoriented_edges + split.repeated_vertex_faces + split.split_vertices, 0);
}

TEST(SplitVertexFans, FinsAreCutOff) {
  testmesh::Mesh m = testmesh::two_grids(2);
  m.F.conservativeResize(m.F.rows() + 2, 3);
  m.F.bottomRows(2) << 0, 4, 12, 4, 0, 13;  // four faces on the interior diagonal 0-4
  const SplitFans split = split_vertex_fans(m.V, m.F);
  EXPECT_EQ(split.non_manifold_edges, 1);
  EXPECT_EQ(split.misoriented_edges, 0);
  EXPECT_GT(split.new_vertices, 0);
  expect_same_faces(m, split);
  expect_manifold_edges(split.F);
}

TEST(SplitVertexFans, MisorientedEdgesAreCutAndFacesNamingAVertexTwiceDetached) {
  testmesh::Mesh m = testmesh::octahedron();
  std::swap(m.F(0, 1), m.F(0, 2));  // three edges now join faces running the same way
  m.F.conservativeResize(m.F.rows() + 1, 3);
  m.F.bottomRows(1) << 1, 1, 2;
  const SplitFans split = split_vertex_fans(m.V, m.F);
  EXPECT_EQ(split.misoriented_edges, 3);
  EXPECT_EQ(split.repeated_vertex_faces, 1);
  expect_same_faces(m, split);
  expect_manifold_edges(split.F);
}

TEST(SplitVertexFans, PartsTouchingAtAVertexGetOneCopyEach) {
  // Two grids that share only their corner vertex: one split vertex, one new copy.
  testmesh::Mesh m = testmesh::grid(2);
  const Eigen::Index n = m.V.rows();
  testmesh::Mesh second = testmesh::grid(2);
  m.V.conservativeResize(2 * n - 1, 3);
  m.V.bottomRows(n - 1) = second.V.topRows(n - 1).rowwise() + Eigen::RowVector3d(-1, -1, 0);
  const Eigen::Index faces = m.F.rows();
  m.F.conservativeResize(2 * faces, 3);
  for (Eigen::Index f = 0; f < faces; ++f)
    for (int k = 0; k < 3; ++k) {
      const int v = second.F(f, k);
      m.F(faces + f, k) = v == int(n) - 1 ? 0 : int(n) + v;  // its last vertex is the first grid's first
    }
  const SplitFans split = split_vertex_fans(m.V, m.F);
  EXPECT_EQ(split.split_vertices, 1);
  EXPECT_EQ(split.new_vertices, 1);
  EXPECT_EQ(split.non_manifold_edges + split.misoriented_edges, 0);
  expect_same_faces(m, split);
}
