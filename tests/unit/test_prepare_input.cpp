// The prepare stage (atlas/prepare/prepare_input.h): a scan's defects fixed on a copy, one step at
// a time, until the copy is a disk or no step helps; the charts of the copy given back for the input.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "atlas/charts.h"
#include "atlas/prepare/prepare_input.h"
#include "generated_meshes.h"

using namespace lowstretch;

namespace {

using Kind = PrepareStep::Kind;

std::vector<Kind> kinds(const PreparedInput& p) {
  std::vector<Kind> k;
  for (const PrepareStep& step : p.steps) k.push_back(step.kind);
  return k;
}

const int kCentre = 24;  // the centre vertex of grid(6), 7 by 7 vertices

// A grid with its centre vertex copied onto its own position and one of its faces moved onto the
// copy (a crack of zero width), and a dust triangle of zero area away from it.
testmesh::Mesh grid_with_duplicate_and_dust(int& copy) {
  testmesh::Mesh m = testmesh::grid(6);
  const Eigen::Index n = m.V.rows(), faces = m.F.rows();
  int f = 0;
  while (m.F(f, 0) != kCentre) ++f;
  copy = int(n);
  m.V.conservativeResize(n + 4, 3);
  m.V.row(n) = m.V.row(kCentre);
  m.V.bottomRows(3) << 2, 2, 2, 3, 3, 3, 4, 4, 4;
  m.F(f, 0) = copy;
  m.F.conservativeResize(faces + 1, 3);
  m.F.row(faces) << int(n) + 1, int(n) + 2, int(n) + 3;
  return m;
}

}  // namespace

TEST(PrepareInput, ADiskIsChartedAsItIs) {
  const testmesh::Mesh m = testmesh::grid(5);
  const PreparedInput p = prepare_input(m.V, m.F, ChartOptions(), true);
  EXPECT_FALSE(p.whole.error);
  EXPECT_TRUE(p.steps.empty());
  EXPECT_TRUE(p.V == m.V && p.F == m.F);
}

TEST(PrepareInput, RejectTakesNoStep) {
  int copy = 0;
  const testmesh::Mesh m = grid_with_duplicate_and_dust(copy);
  ChartOptions options;
  options.non_disk = NonDisk::Reject;
  const PreparedInput p = prepare_input(m.V, m.F, options, true);
  EXPECT_TRUE(p.whole.error);
  EXPECT_TRUE(p.steps.empty());
}

TEST(PrepareInput, DuplicatesAreWeldedThenDustLeftOutAndTheCopyIsADisk) {
  int copy = 0;
  const testmesh::Mesh m = grid_with_duplicate_and_dust(copy);
  const PreparedInput p = prepare_input(m.V, m.F, ChartOptions(), true);
  ASSERT_EQ(kinds(p), (std::vector<Kind>{Kind::Weld, Kind::LeaveOutZeroArea}));
  EXPECT_FALSE(p.whole.error) << "the grid alone, welded: a disk";
  EXPECT_EQ(p.F.rows(), m.F.rows() - 1);
  EXPECT_EQ(p.steps[0].welded.onto[size_t(copy)], kCentre);
  EXPECT_EQ(p.steps[1].zero_area, std::vector<int>{int(m.F.rows()) - 1});
  EXPECT_EQ((p.F.array() == copy).count(), 0) << "no face on the copy once welded";
  // Without welding, the crack stays: a hole, which the atlas cuts, not a step of the prepare stage.
  const PreparedInput unwelded = prepare_input(m.V, m.F, ChartOptions(), false);
  EXPECT_EQ(kinds(unwelded), (std::vector<Kind>{Kind::LeaveOutZeroArea}));

  EXPECT_TRUE(unwelded.whole.error);
}

TEST(PrepareInput, TheChartsAreGivenBackForEveryFaceAndVertexOfTheInput) {
  int copy = 0;
  const testmesh::Mesh m = grid_with_duplicate_and_dust(copy);
  const ChartsResult r = parameterize_charts(m.V, m.F, ChartOptions());
  ASSERT_FALSE(r.error) << message(r.error);
  EXPECT_EQ(r.corner_uv.rows(), m.F.rows());
  ASSERT_EQ(r.vertex_stretch.size(), m.V.rows());
  EXPECT_EQ(r.vertex_stretch(copy), r.vertex_stretch(kCentre)) << "the copy takes its vertex's stretch";
  ASSERT_FALSE(r.notes.empty());
  EXPECT_EQ(r.notes.front().rfind("1 duplicate vertex (on another vertex's position) welded", 0), 0u) << r.notes.front();
}

TEST(PrepareInput, PartsTouchingAtAVertexAreChartedAsAManifoldCopy) {
  testmesh::Mesh m;
  m.V.resize(5, 3);
  m.V << 0, 0, 0, 1, 0, 0, 0, 1, 0, -1, 0, 0, 0, -1, 0;
  m.F.resize(2, 3);
  m.F << 0, 1, 2, 0, 3, 4;  // two triangles sharing vertex 0 only
  const PreparedInput p = prepare_input(m.V, m.F, ChartOptions(), true);
  ASSERT_EQ(kinds(p), std::vector<Kind>{Kind::ManifoldCopy});
  EXPECT_EQ(p.V.rows(), 6) << "vertex 0 once per fan";
  EXPECT_EQ(p.steps[0].vertices, 5);
  EXPECT_EQ(p.whole.error.code, ErrorCode::SeveralComponents) << "two parts, charted apart";
  const ChartsResult r = parameterize_charts(m.V, m.F, ChartOptions());
  ASSERT_FALSE(r.error) << message(r.error);
  EXPECT_EQ(r.vertex_stretch.size(), 5);
  EXPECT_EQ(r.charts.size(), 2u);
}
