// A scan's duplicate vertices welded for the charts (atlas/cut/weld_duplicates.h): the atlas of a
// mesh with duplicates is the atlas of the mesh without them, the mesh itself unchanged.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "atlas/charts.h"
#include "atlas/cut/weld_duplicates.h"
#include "generated_meshes.h"

using namespace lowstretch;

namespace {

// m with `count` vertices copied to their own position, one face around each moved onto its copy
// (as tests/bench/make_defects.py makes them); copy_of: the vertex each copy copies.
testmesh::Mesh with_duplicates(const testmesh::Mesh& m, int count, std::vector<int>& copy_of) {
  testmesh::Mesh d = m;
  for (int n = 0; n < count; ++n) {
    const int f = 7 * n + 3, v = m.F(f, 0);
    d.V.conservativeResize(d.V.rows() + 1, 3);
    d.V.row(d.V.rows() - 1) = m.V.row(v);
    d.F(f, 0) = int(d.V.rows() - 1);
    copy_of.push_back(v);
  }
  return d;
}

}  // namespace

TEST(WeldDuplicates, CopiesWithFacesMovedOntoThemAreWeldedBackOntoTheirVertex) {
  const testmesh::Mesh m = testmesh::torus(16, 8);
  std::vector<int> copy_of;
  const testmesh::Mesh d = with_duplicates(m, 5, copy_of);
  const WeldedFaces w = weld_duplicate_vertices(d.V, d.F);
  EXPECT_EQ(w.welded, 5);
  EXPECT_TRUE(w.F == m.F) << "the faces of the mesh before the copies";
  for (size_t n = 0; n < copy_of.size(); ++n) EXPECT_EQ(w.onto[size_t(m.V.rows()) + n], copy_of[n]);
  for (Eigen::Index v = 0; v < m.V.rows(); ++v) EXPECT_EQ(w.onto[size_t(v)], int(v));
}

TEST(WeldDuplicates, UnusedAndNonFiniteVerticesAreNotWelded) {
  testmesh::Mesh m = testmesh::grid(4);
  m.V.conservativeResize(m.V.rows() + 1, 3);
  m.V.row(m.V.rows() - 1) = m.V.row(0);  // on vertex 0, but no face uses it
  EXPECT_EQ(weld_duplicate_vertices(m.V, m.F).welded, 0);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  m.V.row(1) << nan, nan, nan;
  m.V.row(2) << nan, nan, nan;
  const WeldedFaces w = weld_duplicate_vertices(m.V, m.F);
  EXPECT_EQ(w.welded, 0) << "NaN is at no position";
  EXPECT_TRUE(w.F == m.F);
}

TEST(WeldDuplicates, TheAtlasOfAMeshWithDuplicatesIsTheAtlasWithoutThemAndSaysSo) {
  const testmesh::Mesh m = testmesh::torus(32, 16);
  std::vector<int> copy_of;
  const testmesh::Mesh d = with_duplicates(m, 6, copy_of);
  const testmesh::Mesh input = d;
  const ChartsResult clean = parameterize_charts(m.V, m.F, ChartOptions());
  const ChartsResult welded = parameterize_charts(d.V, d.F, ChartOptions());
  ASSERT_FALSE(clean.error) << message(clean.error);
  ASSERT_FALSE(welded.error) << message(welded.error);
  EXPECT_TRUE(d.V == input.V && d.F == input.F) << "the mesh is unchanged";
  EXPECT_EQ(welded.charts.size(), clean.charts.size());
  ASSERT_EQ(welded.corner_uv.rows(), clean.corner_uv.rows());
  EXPECT_LE((welded.corner_uv - clean.corner_uv).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_DOUBLE_EQ(welded.seam_length, clean.seam_length);
  ASSERT_EQ(welded.vertex_stretch.size(), d.V.rows());
  for (size_t n = 0; n < copy_of.size(); ++n)
    EXPECT_EQ(welded.vertex_stretch(m.V.rows() + Eigen::Index(n)), welded.vertex_stretch(copy_of[n]));
  EXPECT_TRUE(std::any_of(welded.notes.begin(), welded.notes.end(), [](const std::string& n) {
    return n.find("6 duplicate vertices") != std::string::npos && n.find("the mesh is unchanged") != std::string::npos;
  }));
}

TEST(WeldDuplicates, TheTwoSidesOfADoubleSidedSheetAreNotWelded) {
  // A sheet and its reversed copy on vertices of their own at the same positions, beside a torus
  // (alone, half its vertices on others would make it a soup): welded, every inner edge of the
  // sheet would hold four faces, and the manifold copy would cut it into single faces.
  const testmesh::Mesh sheet = testmesh::grid(8, [](double x, double y) { return 0.2 * x * y; });
  const testmesh::Mesh torus = testmesh::torus(32, 16);
  testmesh::Mesh both = sheet;
  const Eigen::Index n = sheet.V.rows(), faces = sheet.F.rows();
  both.V.conservativeResize(2 * n, 3);
  both.V.bottomRows(n) = sheet.V;
  both.F.conservativeResize(2 * faces, 3);
  for (Eigen::Index f = 0; f < faces; ++f) both.F.row(faces + f) << sheet.F(f, 0) + int(n), sheet.F(f, 2) + int(n), sheet.F(f, 1) + int(n);
  EXPECT_EQ(weld_duplicate_vertices(both.V, both.F).welded, int(n)) << "the function alone welds them";
  const testmesh::Mesh m = testmesh::joined(both, torus, 1, Eigen::RowVector3d(3, 0, 0));
  const ChartsResult r = parameterize_charts(m.V, m.F, ChartOptions());
  ASSERT_FALSE(r.error) << message(r.error);
  std::vector<int> sheet_charts;
  for (Eigen::Index f = 0; f < 2 * faces; ++f) sheet_charts.push_back(r.face_chart[size_t(f)]);
  std::sort(sheet_charts.begin(), sheet_charts.end());
  EXPECT_LE(std::unique(sheet_charts.begin(), sheet_charts.end()) - sheet_charts.begin(), 2) << "one chart per side";
  EXPECT_TRUE(std::none_of(r.notes.begin(), r.notes.end(), [](const std::string& note) { return note.find("welded") != std::string::npos; }));
}
