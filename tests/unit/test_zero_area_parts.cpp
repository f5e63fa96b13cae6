// Parts of zero area (atlas/cut/zero_area_parts.h): dust and faces naming a vertex twice are
// left out of the charts and written on one point.
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
}
