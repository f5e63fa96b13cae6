// Connected parts (atlas/cut/mesh_components.h): faces joined across edges, and the vertices
// two parts share.
#include <gtest/gtest.h>

#include <vector>

#include "atlas/cut/mesh_components.h"
#include "generated_meshes.h"

using namespace lowstretch;

TEST(MeshComponents, EdgeConnectedPartsAndSharedVertices) {
  const testmesh::Mesh m = testmesh::two_grids(3);
  int count = 0;
  const std::vector<int> component = face_components(m.F, count);
  EXPECT_EQ(count, 2);
  for (Eigen::Index f = 0; f < m.F.rows(); ++f) EXPECT_EQ(component[size_t(f)], f < m.F.rows() / 2 ? 0 : 1);
  EXPECT_EQ(vertices_shared_by_components(m.F, int(m.V.rows()), component), 0);
  // Two triangles that touch at one vertex: two components sharing it.
  Eigen::MatrixXi bowtie(2, 3);
  bowtie << 0, 1, 2, 0, 3, 4;
  const std::vector<int> parts = face_components(bowtie, count);
  EXPECT_EQ(count, 2);
  EXPECT_EQ(vertices_shared_by_components(bowtie, 5, parts), 1);
}
