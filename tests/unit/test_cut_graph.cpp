// The cut graph (atlas/cut/cut_graph.h) and the cut along it (cut_mesh.h): closed and higher-genus
// surfaces open into disks (make_disk_mesh accepts the result); a disk needs no cut.
#include <gtest/gtest.h>

#include "core/boundary_loops.h"
#include "atlas/cut/cut_graph.h"
#include "atlas/cut/cut_mesh.h"
#include "core/disk_mesh.h"
#include "core/half_edges.h"
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

TEST(CutGraph, ClosedAndHigherGenusSurfacesOpenIntoDisks) {
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

TEST(CutGraph, ADiskNeedsNoCut) {
  const testmesh::Mesh m = testmesh::hemisphere(5, 10);
  size_t seam_edges = 1;
  EXPECT_FALSE(cut_open(m, seam_edges));
  EXPECT_EQ(seam_edges, 0u);
}
