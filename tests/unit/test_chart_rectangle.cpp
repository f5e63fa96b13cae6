// A chart's rectangle (atlas/chart_map/chart_rectangle.h): corners at the boundary's turns, ears
// bulged out of the sides, given to the core as the boundary's positions.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "atlas/chart_map/chart_rectangle.h"
#include "core/boundary_map.h"
#include "core/disk_mesh.h"
#include "core/parameterize.h"
#include "generated_meshes.h"

using namespace lowstretch;

namespace {

const double kPi = 3.14159265358979323846;

// A flat hexagon fanned from its centre (vertex 0; corners 1..6), with an ear on each side: tip
// 7 + k over the side from corner 1 + k to the next. Each side is an interior edge between two
// boundary vertices, so six ears need a corner inside them, more than a square has.
testmesh::Mesh hexagon_with_ears() {
  testmesh::Mesh m;
  m.V.resize(13, 3);
  m.V.row(0) << 0, 0, 0;
  for (int k = 0; k < 6; ++k) {
    const double a = k * kPi / 3, mid = a + kPi / 6;
    m.V.row(1 + k) << std::cos(a), std::sin(a), 0;
    m.V.row(7 + k) << 1.2 * std::cos(mid), 1.2 * std::sin(mid), 0;
  }
  m.F.resize(12, 3);
  for (int k = 0; k < 6; ++k) {
    m.F.row(k) << 0, 1 + k, 1 + (k + 1) % 6;
    m.F.row(6 + k) << 1 + k, 7 + k, 1 + (k + 1) % 6;
  }
  return m;
}

// The boundary loop's positions given in the mesh's vertex rows, as the atlas gives them.
Options given(const DiskMesh& disk, const Eigen::MatrixXd& loop_uv, Eigen::Index rows) {
  Options o;
  o.boundary = BoundaryShape::Given;
  o.given_boundary = Eigen::MatrixXd::Zero(rows, 2);
  for (size_t i = 0; i < disk.boundary.size(); ++i)
    o.given_boundary.row(disk.input_vertex[size_t(disk.boundary[i])]) = loop_uv.row(Eigen::Index(i));
  return o;
}

double signed_area(const Eigen::MatrixXd& uv, int a, int b, int c) {
  const Eigen::RowVector2d p = uv.row(a), q = uv.row(b), r = uv.row(c);
  return 0.5 * ((q.x() - p.x()) * (r.y() - p.y()) - (r.x() - p.x()) * (q.y() - p.y()));
}

// The smallest UV area of the six ears, as a share of the map's UV area.
double smallest_ear_share(const testmesh::Mesh& m, const Eigen::MatrixXd& uv) {
  double total = 0, least = 1e300;
  for (Eigen::Index f = 0; f < m.F.rows(); ++f) {
    const double a = std::abs(signed_area(uv, m.F(f, 0), m.F(f, 1), m.F(f, 2)));
    total += a;
    if (f >= 6) least = std::min(least, a);
  }
  return least / total;
}

// How many of the loop's points at the corners of its UV box are at a corner of the 2 x 1 strip m
// or one grid step (1/6 along x) from it.
int corners_near_the_strips(const testmesh::Mesh& m, const DiskMesh& disk, const Eigen::MatrixXd& loop_uv) {
  const Eigen::RowVector2d high = loop_uv.colwise().maxCoeff();
  int near = 0;
  for (size_t i = 0; i < disk.boundary.size(); ++i) {
    const Eigen::RowVector2d p = loop_uv.row(Eigen::Index(i));
    const bool at_corner = (std::abs(p.x()) < 1e-12 || std::abs(p.x() - high.x()) < 1e-12) &&
                           (std::abs(p.y()) < 1e-12 || std::abs(p.y() - high.y()) < 1e-12);
    const Eigen::RowVector3d v = m.V.row(disk.input_vertex[size_t(disk.boundary[i])]);
    near += at_corner && std::hypot(std::min(v.x(), 2 - v.x()), std::min(v.y(), 1 - v.y())) <= 1.0 / 6 + 1e-12;
  }
  return near;
}

}  // namespace

TEST(ChartRectangle, CornersGoToTheBoundarysTurns) {
  // A flat 2 x 1 strip. A turn is summed over a vertex and its two loop neighbours (a corner cut
  // over two edges counts whole), so a corner lands on the strip's corner or next to it; the
  // paper's quarter arc lengths put two corners along the long sides instead.
  testmesh::Mesh m = testmesh::grid(12);
  m.V.col(0) *= 2;
  DiskMesh disk;
  ASSERT_FALSE(make_disk_mesh(m.V, m.F, disk));
  std::vector<std::string> notes;
  const Eigen::MatrixXd on_turns = chart_rectangle(disk, {0, 0}, notes);
  EXPECT_TRUE(notes.empty());
  EXPECT_EQ(corners_near_the_strips(m, disk, on_turns), 4);
  EXPECT_LE(corners_near_the_strips(m, disk, paper_square_boundary(disk, notes)), 2);
  const Result r = parameterize(disk, m.V.rows(), given(disk, on_turns, m.V.rows()));
  ASSERT_FALSE(r.error) << message(r.error);
  EXPECT_EQ(r.passes.at(size_t(r.chosen_pass)).flipped, 0);
}

TEST(ChartRectangle, EarsBulgeOutOfTheSidesAndKeepTheirArea) {
  const testmesh::Mesh m = hexagon_with_ears();
  DiskMesh disk;
  ASSERT_FALSE(make_disk_mesh(m.V, m.F, disk));
  std::vector<std::string> notes;
  const Eigen::MatrixXd flat = chart_rectangle(disk, {1, 0}, notes);
  ASSERT_FALSE(notes.empty());  // no corners avoid collapsing an ear: the sides bend
  const Eigen::MatrixXd bulged = chart_rectangle(disk, {1, 0.25}, notes);
  EXPECT_GE(bulged.minCoeff(), 0);
  EXPECT_NEAR(bulged.maxCoeff(), 1, 1e-12);

  // Every tip stands at least a quarter of its chord out of it (a tip at a corner does so by
  // itself); without the bulge, those on the sides lie nearly on their chords.
  const int n = int(disk.boundary.size());
  int flat_tips = 0;
  for (int i = 0; i < n; ++i) {
    if (disk.input_vertex[size_t(disk.boundary[size_t(i)])] < 7) continue;
    const auto height_over_chord = [&](const Eigen::MatrixXd& uv) {  // outward: right of a -> b
      const Eigen::RowVector2d tip = uv.row(i), a = uv.row((i + n - 1) % n), b = uv.row((i + 1) % n);
      const Eigen::RowVector2d chord = b - a;
      return ((tip - a).x() * chord.y() - (tip - a).y() * chord.x()) / chord.squaredNorm();
    };
    EXPECT_GE(height_over_chord(bulged), 0.25 - 1e-12) << "tip at loop position " << i;
    flat_tips += height_over_chord(flat) < 0.05;
  }
  EXPECT_GE(flat_tips, 2);

  const Result with_ears = parameterize(disk, m.V.rows(), given(disk, bulged, m.V.rows()));
  const Result without = parameterize(disk, m.V.rows(), given(disk, flat, m.V.rows()));
  ASSERT_FALSE(with_ears.error || without.error);
  for (const Result* r : {&with_ears, &without}) {
    EXPECT_EQ(r->passes.at(size_t(r->chosen_pass)).flipped, 0);
    EXPECT_EQ(r->passes.at(size_t(r->chosen_pass)).degenerate, 0);
  }
  EXPECT_GT(smallest_ear_share(m, with_ears.uv), 3 * smallest_ear_share(m, without.uv));
}
