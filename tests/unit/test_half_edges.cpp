// Half-edges of a triangle array (core/half_edges.h): the opposite of each half-edge, the edges'
// keys, and the fans of corners around each vertex.
#include <gtest/gtest.h>

#include <set>
#include <vector>

#include "core/half_edges.h"
#include "generated_meshes.h"

using namespace lowstretch;

// On a grid, each half-edge's opposite runs the other way along the same edge; the grid's
// boundary edges (4 n of them) have none.
TEST(HalfEdges, OppositesRunTheOtherWayAndTheBoundaryHasNone) {
  const int n = 5;
  const testmesh::Mesh m = testmesh::grid(n);
  const std::vector<int> twin = opposite_half_edges(m.F);
  ASSERT_EQ(twin.size(), size_t(3 * m.F.rows()));
  int boundary = 0;
  for (int h = 0; h < int(twin.size()); ++h) {
    EXPECT_EQ(half_edge_tail(m.F, h), m.F(h / 3, h % 3));
    EXPECT_EQ(half_edge_head(m.F, next_half_edge(previous_half_edge(h))), half_edge_head(m.F, h));
    EXPECT_EQ(half_edge_tail(m.F, next_half_edge(h)), half_edge_head(m.F, h));
    const int t = twin[size_t(h)];
    if (t < 0) {
      ++boundary;
      continue;
    }
    EXPECT_EQ(twin[size_t(t)], h);
    EXPECT_EQ(half_edge_tail(m.F, t), half_edge_head(m.F, h));
    EXPECT_EQ(half_edge_head(m.F, t), half_edge_tail(m.F, h));
  }
  EXPECT_EQ(boundary, 4 * n);
}

// Sorted by the undirected edge's key: the two half-edges of an interior edge are neighbours.
TEST(HalfEdges, HalfEdgesOfOneEdgeAreNeighboursByKey) {
  const testmesh::Mesh m = testmesh::octahedron();  // closed: every edge has two half-edges
  const auto by_edge = half_edges_by_edge(m.F);
  ASSERT_EQ(by_edge.size(), size_t(3 * m.F.rows()));
  for (size_t i = 0; i + 1 < by_edge.size(); ++i) EXPECT_LE(by_edge[i].first, by_edge[i + 1].first);
  for (size_t i = 0; i < by_edge.size(); i += 2) {
    ASSERT_EQ(by_edge[i].first, by_edge[i + 1].first) << i;
    const int a = by_edge[i].second, b = by_edge[i + 1].second;
    EXPECT_EQ(half_edge_tail(m.F, a), half_edge_head(m.F, b));
    EXPECT_EQ(half_edge_head(m.F, a), half_edge_tail(m.F, b));
  }
}

// Every vertex of a grid has one fan; two triangles touching at a vertex give it two.
TEST(HalfEdges, CornerFansAreOnePerVertexOnAManifold) {
  const testmesh::Mesh m = testmesh::grid(4);
  const std::vector<int> fans = corner_fans(opposite_half_edges(m.F));
  std::vector<std::set<int>> of_vertex(size_t(m.V.rows()));
  for (int h = 0; h < int(fans.size()); ++h) of_vertex[size_t(half_edge_tail(m.F, h))].insert(fans[size_t(h)]);
  for (size_t v = 0; v < of_vertex.size(); ++v) EXPECT_EQ(of_vertex[v].size(), 1u) << v;
  Eigen::MatrixXi bowtie(2, 3);
  bowtie << 0, 1, 2, 0, 3, 4;
  const std::vector<int> two = corner_fans(opposite_half_edges(bowtie));
  EXPECT_NE(two[0], two[3]) << "vertex 0 in each triangle: a fan each";
  EXPECT_EQ(two[0], 0);  // the smallest corner in the fan
  EXPECT_EQ(two[3], 3);
}
