// Parts of zero area (atlas/cut/zero_area_parts.h): dust and faces naming a vertex twice are
// left out of the charts and written on their neighbours' corners, or on one point.
#include <gtest/gtest.h>

#include "atlas/charts.h"
#include "generated_meshes.h"
#include "layout_checks.h"

using namespace lowstretch;

namespace {

ChartsResult charts_of(const testmesh::Mesh& m, NonDisk non_disk = NonDisk::Charts) {
  ChartOptions options;
  options.non_disk = non_disk;
  return parameterize_charts(m.V, m.F, options);
}

}  // namespace

TEST(ZeroAreaParts, FacesOfZeroAreaPartsGetZeroAreaCoordinates) {
  testmesh::Mesh m = testmesh::grid(4);
  const Eigen::Index n = m.V.rows(), faces = m.F.rows();
  // Dust of zero area: a triangle on a line, away from the grid, and a face naming a vertex twice.
  m.V.conservativeResize(n + 3, 3);
  m.V.bottomRows(3) << 2, 2, 2, 3, 3, 3, 4, 4, 4;
  m.F.conservativeResize(faces + 2, 3);
  m.F.bottomRows(2) << int(n), int(n) + 1, int(n) + 2, 0, 0, 1;
  EXPECT_EQ(charts_of(m, NonDisk::Reject).error.code, ErrorCode::RepeatedVertexInFace);
  const ChartsResult r = charts_of(m);
  expect_valid_layout(m.F, r, &m.V);
  for (const Eigen::Index f : {faces, faces + 1})
    EXPECT_EQ(signed_area(corner(r, f, 0), corner(r, f, 1), corner(r, f, 2)), 0) << "face " << f;
  for (Eigen::Index f = 0; f < faces; ++f) EXPECT_GT(signed_area(corner(r, f, 0), corner(r, f, 1), corner(r, f, 2)), 0);
  EXPECT_NEAR(r.layout.l2_stretch, 1, 1e-6) << "a flat grid, and dust that adds no area";
  // The face naming vertex 0 twice lies on the grid's own corners of its vertices, in their chart:
  // no seam runs around it. The dust triangle has no mapped vertex: one point.
  const Eigen::Index twice = faces + 1;
  for (int k = 0; k < 3; ++k) {
    bool on_the_grids_corner = false;
    for (Eigen::Index f = 0; f < faces; ++f)
      for (int j = 0; j < 3; ++j)
        on_the_grids_corner = on_the_grids_corner || (m.F(f, j) == m.F(twice, k) && corner(r, f, j) == corner(r, twice, k) &&
                                                      r.face_chart[size_t(f)] == r.face_chart[size_t(twice)]);
    EXPECT_TRUE(on_the_grids_corner) << "corner " << k;
  }
  EXPECT_NE(corner(r, twice, 0), corner(r, twice, 2)) << "vertices 0 and 1 are apart on the grid";
  EXPECT_EQ(corner(r, faces, 0), corner(r, faces, 1));
  EXPECT_EQ(corner(r, faces, 0), corner(r, faces, 2));
  int chart_faces = 0;
  for (const Chart& c : r.charts) chart_faces += c.faces;
  EXPECT_EQ(chart_faces, m.F.rows()) << "each face counted in one chart";
}
