// The pieces of the charts path on their own: closing holes leaves one boundary loop, and the cut
// graph opens closed and higher-genus surfaces into disks (make_disk_mesh accepts the result).
#include <gtest/gtest.h>

#include "core/boundary_loops.h"
#include "atlas/cut/close_holes.h"
#include "atlas/cut/cut_graph.h"
#include "atlas/cut/cut_mesh.h"
#include "core/disk_mesh.h"
#include "core/half_edges.h"
#include "atlas/cut/mesh_components.h"
#include "generated_meshes.h"

using namespace lowstretch;

namespace {

// The surface cut along cut_graph, as make_disk_mesh sees it.
Error cut_open(const testmesh::Mesh& m, size_t& seam_edges) {
  const std::vector<std::vector<int>> loops = boundary_loops(m.F, opposite_half_edges(m.F), int(m.V.rows()));
  const std::vector<int> boundary = loops.empty() ? std::vector<int>() : loops[longest_loop(m.V, loops)];
  const std::vector<std::array<int, 2>> seams = cut_graph(m.V, m.F, boundary);
  seam_edges = seams.size();
  const CutMesh cut = cut_along(m.F, seams);
  Eigen::MatrixXd V(Eigen::Index(cut.original_vertex.size()), 3);
  for (size_t i = 0; i < cut.original_vertex.size(); ++i) V.row(Eigen::Index(i)) = m.V.row(cut.original_vertex[i]);
  DiskMesh disk;
  return make_disk_mesh(V, cut.F, disk);
}

}  // namespace

TEST(CutToDisk, ClosedAndHigherGenusSurfacesOpenIntoDisks) {
  const std::vector<std::pair<const char*, testmesh::Mesh>> surfaces = {
      {"octahedron", testmesh::octahedron()},
      {"sphere", testmesh::sphere(10, 12)},
      {"torus", testmesh::torus(20, 10)},
      {"punctured torus", testmesh::without_face(testmesh::torus(20, 10), 7)},
      {"double torus", testmesh::double_torus()}};
  for (const auto& s : surfaces) {
    SCOPED_TRACE(s.first);
    size_t seam_edges = 0;
    const Error e = cut_open(s.second, seam_edges);
    EXPECT_FALSE(e) << message(e);
    EXPECT_GE(seam_edges, 2u);
  }
}

TEST(CutToDisk, ADiskNeedsNoCut) {
  const testmesh::Mesh m = testmesh::hemisphere(5, 10);
  size_t seam_edges = 1;
  EXPECT_FALSE(cut_open(m, seam_edges));
  EXPECT_EQ(seam_edges, 0u);
}

TEST(CloseHoles, LeavesOnlyTheLongestLoop) {
  testmesh::Mesh m = testmesh::punched_grid(16, {{0.3, 0.3}, {0.7, 0.7}, {0.3, 0.75}}, 0.1);
  const std::vector<std::vector<int>> loops = boundary_loops(m.F, opposite_half_edges(m.F), int(m.V.rows()));
  ASSERT_EQ(loops.size(), 4u);
  const size_t outer = longest_loop(m.V, loops);
  EXPECT_EQ(loops[outer].size(), 64u);  // the square's border: 4 x 16 edges
  const Eigen::Index faces = m.F.rows();
  close_holes(m.V, m.F, loops, outer);
  EXPECT_EQ(m.F.rows(), faces + Eigen::Index(loops[0].size() + loops[1].size() + loops[2].size() + loops[3].size() -
                                              loops[outer].size()));
  DiskMesh disk;
  const Error e = make_disk_mesh(m.V, m.F, disk);  // the unused vertices of the holes are ignored
  EXPECT_FALSE(e) << message(e);
  EXPECT_EQ(disk.boundary.size(), 64u);
}

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
