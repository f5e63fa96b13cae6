// atlas/chart_map/boundary_crossing.h: a map whose boundary folds over itself is found, a plain one is not.
#include <gtest/gtest.h>

#include <cmath>

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

// A chart whose boundary passes twice through one vertex (two fans of faces there, as a
// reconstruction's pinched vertex gives): fan B (three quarters of a turn) lies inside fan A (a
// half turn) and no two boundary edges that share no vertex meet; the angles at the vertex add up
// to more than a full turn, so the map overlaps itself. Fan B in the quarter turn left free does not.
TEST(BoundaryCrossing, TwoFansAtOneVertexOverlapWithoutCrossingEdges) {
  const auto at = [](double degrees, double radius) {
    return Eigen::RowVector2d(radius * std::cos(degrees * M_PI / 180), radius * std::sin(degrees * M_PI / 180));
  };
  Eigen::MatrixXi F(5, 3);
  F << 0, 1, 2, 0, 2, 3, 0, 3, 4,  // fan A: 0, 90, 180, 270 degrees
      0, 5, 6, 0, 6, 7;             // fan B: 10, 100, 190 degrees
  Eigen::MatrixXd uv(8, 2);
  uv.row(0) << 0, 0;
  for (int i = 0; i < 4; ++i) uv.row(1 + i) = at(90.0 * i, 1);
  for (int i = 0; i < 3; ++i) uv.row(5 + i) = at(10 + 90.0 * i, 0.3);
  EXPECT_TRUE(uv_boundary_crosses_itself(F, uv));
  for (int i = 0; i < 3; ++i) uv.row(5 + i) = at(275 + 40.0 * i, 0.3);  // fan B in the quarter fan A leaves
  EXPECT_FALSE(uv_boundary_crosses_itself(F, uv));
}
