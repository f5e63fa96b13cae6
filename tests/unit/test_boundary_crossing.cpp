// atlas/chart_map/boundary_crossing.h: a map whose boundary folds over itself is found, a plain one is not.
#include <gtest/gtest.h>

#include "atlas/chart_map/boundary_crossing.h"
#include "generated_meshes.h"

using namespace lowstretch;

TEST(BoundaryCrossing, GridOnItsOwnShapeDoesNotCross) {
  const testmesh::Mesh m = testmesh::grid(4);
  EXPECT_FALSE(uv_boundary_crosses_itself(m.F, m.V.leftCols(2)));
}

TEST(BoundaryCrossing, CornerFoldedAcrossTheOppositeSideCrosses) {
  const testmesh::Mesh m = testmesh::grid(4);
  Eigen::MatrixXd uv = m.V.leftCols(2);
  uv.row(24) << 0.5, -0.5;  // the corner (1, 1) pulled below the side y = 0
  EXPECT_TRUE(uv_boundary_crosses_itself(m.F, uv));
}

TEST(BoundaryCrossing, TooManyBoundaryEdgesCountsAsCrossing) {
  const testmesh::Mesh m = testmesh::grid(4);  // 16 boundary edges
  EXPECT_TRUE(uv_boundary_crosses_itself(m.F, m.V.leftCols(2), 15));
  EXPECT_FALSE(uv_boundary_crosses_itself(m.F, m.V.leftCols(2), 16));
}
