// The iteration: no flips on convex boundaries, stretch falls, stop rule, options, bookkeeping.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "core/parameterize.h"
#include "core/prepared_disk.h"
#include "core/stretch.h"
#include "generated_meshes.h"

using namespace lowstretch;

namespace {

// Signed area of face f in a map.
double uv_area(const Eigen::MatrixXd& uv, const Eigen::MatrixXi& F, Eigen::Index f) {
  const Eigen::RowVector2d a = uv.row(F(f, 0)), b = uv.row(F(f, 1)), c = uv.row(F(f, 2));
  return 0.5 * ((b.x() - a.x()) * (c.y() - a.y()) - (c.x() - a.x()) * (b.y() - a.y()));
}

void expect_no_bad_triangles(const Result& r) {
  for (const PassMetrics& p : r.passes) {
    EXPECT_EQ(p.flipped, 0) << "pass " << p.pass;
    EXPECT_EQ(p.degenerate, 0) << "pass " << p.pass;
  }
}

}  // namespace

TEST(Parameterize, FlatDiskWithNaturalBoundaryHasStretchOne) {
  const testmesh::Mesh m = testmesh::grid(10, nullptr);
  Options o;
  o.boundary = BoundaryShape::Natural;
  const Result r = parameterize(m.V, m.F, o);
  ASSERT_FALSE(r.error) << message(r.error);
  for (const PassMetrics& p : r.passes) {
    EXPECT_NEAR(p.l2_stretch, 1.0, 1e-9);
    EXPECT_NEAR(p.linf_stretch, 1.0, 1e-9);
    EXPECT_NEAR(p.angle_distortion, 0.0, 1e-9);
  }
  // The map is a similarity: UV differences are a fixed multiple of the 3D ones.
  const double scale = (r.uv.row(1) - r.uv.row(0)).norm() / (m.V.row(1) - m.V.row(0)).norm();
  for (Eigen::Index i = 0; i < m.V.rows(); ++i)
    EXPECT_NEAR((r.uv.row(i) - r.uv.row(0)).norm(), scale * (m.V.row(i) - m.V.row(0)).norm(), 1e-9);
}

TEST(Parameterize, ConvexBoundariesGiveNoFlipsAndLowerStretch) {
  for (const testmesh::Mesh& m : {testmesh::hemisphere(16, 32), testmesh::tall_cap(16, 40)})
    for (BoundaryShape shape : {BoundaryShape::Square, BoundaryShape::Circle})
      for (InitialWeights w : {InitialWeights::Floater, InitialWeights::MeanValue}) {
        SCOPED_TRACE(std::string(to_string(shape)) + " " + to_string(w));
        Options o;
        o.boundary = shape;
        o.weights = w;
        const Result r = parameterize(m.V, m.F, o);
        ASSERT_FALSE(r.error) << message(r.error);
        expect_no_bad_triangles(r);
        ASSERT_GE(r.passes.size(), 2u);
        const double best = r.passes[size_t(r.chosen_pass)].l2_stretch;
        EXPECT_LT(best, r.passes[0].l2_stretch);
        EXPECT_LE(best, r.passes[1].l2_stretch);
        EXPECT_GE(r.uv.minCoeff(), -1e-12);
        EXPECT_LE(r.uv.maxCoeff(), 1 + 1e-12);
      }
}

TEST(Parameterize, StopRuleReturnsTheBestPassAndStopsWhenStretchRises) {
  const testmesh::Mesh m = testmesh::tall_cap(16, 40);
  const Result r = parameterize(m.V, m.F);
  ASSERT_FALSE(r.error);
  const auto best = std::min_element(r.passes.begin(), r.passes.end(),
                                     [](const PassMetrics& a, const PassMetrics& b) { return a.l2_stretch < b.l2_stretch; });
  EXPECT_EQ(best->pass, r.chosen_pass);
  if (r.stop_reason == StopReason::StretchRose) {
    EXPECT_EQ(int(r.passes.size()), r.chosen_pass + 2);
    EXPECT_GE(r.passes.back().l2_stretch, r.passes[size_t(r.chosen_pass)].l2_stretch);
  } else {
    EXPECT_EQ(int(r.passes.size()), 11);
  }
}

// Without distortions a pass keeps its stretch and flip counts, and the same map comes out.
TEST(Parameterize, PassesMeasuredWithoutDistortionsKeepTheirStretch) {
  const testmesh::Mesh m = testmesh::tall_cap(16, 40);
  Options o;
  const Result full = parameterize(m.V, m.F, o);
  o.measure_distortions = false;
  const Result stretch_only = parameterize(m.V, m.F, o);
  ASSERT_FALSE(full.error);
  ASSERT_FALSE(stretch_only.error);
  ASSERT_EQ(full.passes.size(), stretch_only.passes.size());
  EXPECT_EQ(full.chosen_pass, stretch_only.chosen_pass);
  EXPECT_EQ(full.uv, stretch_only.uv);
  for (size_t i = 0; i < full.passes.size(); ++i) {
    const PassMetrics &a = full.passes[i], &b = stretch_only.passes[i];
    EXPECT_EQ(a.l2_stretch, b.l2_stretch);
    EXPECT_EQ(a.linf_stretch, b.linf_stretch);
    EXPECT_EQ(a.flipped, b.flipped);
    EXPECT_EQ(a.degenerate, b.degenerate);
    EXPECT_GT(a.angle_distortion, 0);  // a cap cannot be mapped flat without it
    EXPECT_GT(a.edge_distortion, 0);
    EXPECT_EQ(b.angle_distortion, 0);
    EXPECT_EQ(b.edge_distortion, 0);
    EXPECT_EQ(b.area_distortion, 0);
  }
}

TEST(Parameterize, MaxPassesZeroGivesU0AndOneGivesU1) {
  const testmesh::Mesh m = testmesh::hemisphere(8, 16);
  Options o;
  o.max_passes = 0;
  Result r = parameterize(m.V, m.F, o);
  ASSERT_FALSE(r.error);
  EXPECT_EQ(r.passes.size(), 1u);
  EXPECT_EQ(r.chosen_pass, 0);
  o.max_passes = 1;
  r = parameterize(m.V, m.F, o);
  EXPECT_EQ(r.passes.size(), 2u);
  EXPECT_EQ(r.chosen_pass, 1);
  o.max_passes = 6;
  o.stop_when_stretch_rises = false;
  r = parameterize(m.V, m.F, o);
  EXPECT_EQ(r.passes.size(), 7u);
}

TEST(Parameterize, SmallerExponentIsGentler) {
  const testmesh::Mesh m = testmesh::hemisphere(12, 24);
  Options o;
  o.max_passes = 1;
  const double full = parameterize(m.V, m.F, o).passes[1].l2_stretch;
  o.exponent = 0.25;
  const Result gentle = parameterize(m.V, m.F, o);
  // U1 with a small exponent moves less far from U0 than with exponent 1.
  EXPECT_GT(gentle.passes[1].l2_stretch, full);
  EXPECT_LT(gentle.passes[1].l2_stretch, gentle.passes[0].l2_stretch);
}

TEST(Parameterize, UnreferencedVerticesKeepTheirRowsAndChangeNothing) {
  const testmesh::Mesh m = testmesh::hemisphere(8, 16);
  testmesh::Mesh padded;
  padded.V.resize(m.V.rows() + 2, 3);
  padded.V.row(0) << std::nan(""), 0, 0;  // unreferenced, first
  padded.V.middleRows(1, m.V.rows()) = m.V;
  padded.V.bottomRows(1) << 5, 5, 5;       // unreferenced, last
  padded.F = (m.F.array() + 1).matrix();
  const Result a = parameterize(m.V, m.F), b = parameterize(padded.V, padded.F);
  ASSERT_FALSE(b.error) << message(b.error);
  EXPECT_EQ(b.uv.rows(), padded.V.rows());
  EXPECT_EQ(b.uv.row(0), Eigen::RowVector2d::Zero());
  EXPECT_LT((b.uv.middleRows(1, m.V.rows()) - a.uv).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_EQ(a.chosen_pass, b.chosen_pass);
}

// The free boundary carries no no-flip guarantee: every pass's reported flip and zero-area counts
// must be those of its map, counted again here from the UV it hands out.
TEST(Parameterize, NaturalBoundaryOnACurvedDiskReportsItsFlips) {
  for (const testmesh::Mesh& m : {testmesh::hemisphere(12, 24), testmesh::tall_cap(16, 40)}) {
    Options o;
    o.boundary = BoundaryShape::Natural;
    o.max_passes = 6;
    o.stop_when_stretch_rises = false;
    std::vector<Eigen::MatrixXd> maps;
    o.pass_uv = [&](int, const Eigen::MatrixXd& uv) { maps.push_back(uv); };
    const Result r = parameterize(m.V, m.F, o);
    ASSERT_FALSE(r.error) << message(r.error);
    ASSERT_EQ(maps.size(), r.passes.size());
    for (size_t p = 0; p < maps.size(); ++p) {
      int negative = 0, zero = 0;
      double total = 0;
      for (Eigen::Index f = 0; f < m.F.rows(); ++f) total += std::abs(uv_area(maps[p], m.F, f));
      for (Eigen::Index f = 0; f < m.F.rows(); ++f) {
        const double a = uv_area(maps[p], m.F, f);
        if (a < -1e-16 * total) ++negative;
        else if (a <= 1e-16 * total) ++zero;
      }
      EXPECT_EQ(r.passes[p].flipped, negative) << "pass " << p;
      EXPECT_EQ(r.passes[p].degenerate, zero) << "pass " << p;
      EXPECT_EQ(std::isinf(r.passes[p].l2_stretch), negative + zero > 0) << "pass " << p;
    }
    EXPECT_LT(r.passes[size_t(r.chosen_pass)].l2_stretch, r.passes[0].l2_stretch);
  }
}

TEST(Parameterize, ProgressIsReportedAndCanCancel) {
  const testmesh::Mesh m = testmesh::hemisphere(8, 16);
  Options o;
  double last = -1;
  bool monotone = true;
  o.progress = [&](double f, const char*) {
    monotone = monotone && f >= last;
    last = f;
    return true;
  };
  EXPECT_FALSE(parameterize(m.V, m.F, o).error);
  EXPECT_TRUE(monotone);
  EXPECT_DOUBLE_EQ(last, 1.0);
  o.progress = [](double f, const char*) { return f < 0.1; };  // cancel in pass 1
  EXPECT_EQ(parameterize(m.V, m.F, o).error.code, ErrorCode::Cancelled);
}

TEST(Parameterize, ZeroAreaTrianglesInsideAreHandled) {
  // Collapse one interior edge's triangles to zero area by moving a vertex onto its neighbour's line.
  testmesh::Mesh m = testmesh::grid(6, [](double x, double y) { return 0.3 * x * y; });
  m.V.row(8) = 0.5 * (m.V.row(7) + m.V.row(9));  // vertex 8 on the segment 7-9
  m.V.row(15) = m.V.row(16);                       // vertices 15 and 16 coincide
  for (BoundaryShape shape : {BoundaryShape::Square, BoundaryShape::Circle}) {
    Options o;
    o.boundary = shape;
    const Result r = parameterize(m.V, m.F, o);
    ASSERT_FALSE(r.error) << message(r.error);
    EXPECT_EQ(r.passes[size_t(r.chosen_pass)].flipped, 0);
    EXPECT_EQ(r.passes[size_t(r.chosen_pass)].degenerate, 0);
    EXPECT_TRUE(r.uv.allFinite());
  }
}

// Harmonic weights can be negative, so an interior vertex can land outside the boundary's hull
// and so outside [0,1]^2 (found by the fuzzer: a hemisphere with its apex pulled sideways, natural
// boundary, every pass). The result is scaled back into the unit square.
TEST(Parameterize, TextureCoordinatesStayInTheUnitSquareWithNegativeWeights) {
  testmesh::Mesh m = testmesh::hemisphere(4, 4);
  m.V(0, 0) = 1.375;
  Options o;
  o.boundary = BoundaryShape::Natural;
  o.weights = InitialWeights::Harmonic;
  o.max_passes = 2;
  o.stop_when_stretch_rises = false;
  const Result r = parameterize(m.V, m.F, o);
  ASSERT_FALSE(r.error) << message(r.error);
  EXPECT_GE(r.uv.minCoeff(), 0.0);
  EXPECT_LE(r.uv.maxCoeff(), 1.0);
  // The scaling is uniform, so the reported face stretch is still that of the written UV.
  const FaceStretch written = face_stretch(m.V, m.F, r.uv);
  for (Eigen::Index f = 0; f < m.F.rows(); ++f)
    if (written.valid(f)) EXPECT_NEAR(r.face_stretch(f), written.normalization * written.sigma(f), 1e-9 * r.face_stretch(f));
}

// The core checks every option value once and names the option; each caller renames it the way
// its user knows it (the tool's flag, the filter's label).
TEST(Parameterize, BadOptionsAreNamedTheWayTheCallerKnowsThem) {
  const testmesh::Mesh m = testmesh::grid(5);
  const auto flag = [](const std::string& option) { return "--" + option; };
  Options o;
  o.exponent = 2;
  Result r = parameterize(m.V, m.F, o);
  EXPECT_EQ(r.error.code, ErrorCode::InvalidOption);
  EXPECT_EQ(r.error.option, "exponent");
  EXPECT_NE(message(r.error).find("exponent"), std::string::npos) << message(r.error);
  EXPECT_EQ(message(r.error).find("--exponent"), std::string::npos) << message(r.error);
  EXPECT_NE(message(r.error, flag).find("--exponent"), std::string::npos) << message(r.error, flag);
  o = Options();
  o.max_passes = kMostPasses + 1;
  r = parameterize(m.V, m.F, o);
  EXPECT_EQ(r.error.option, "max_passes");
  EXPECT_NE(message(r.error, flag).find("--max_passes"), std::string::npos) << message(r.error, flag);
  // Other errors keep their own message.
  const Result closed = parameterize(testmesh::octahedron().V, testmesh::octahedron().F);
  EXPECT_EQ(message(closed.error, flag), message(closed.error));
}

TEST(Parameterize, RejectsInvalidOptionsBeforeTouchingTheMesh) {
  const testmesh::Mesh m = testmesh::grid(3);
  Options o;
  o.exponent = 0;
  EXPECT_EQ(parameterize(m.V, m.F, o).error.code, ErrorCode::InvalidOption);
  o.exponent = 1.5;
  EXPECT_EQ(parameterize(m.V, m.F, o).error.code, ErrorCode::InvalidOption);
  o.exponent = 1;
  o.max_passes = -1;
  EXPECT_EQ(parameterize(m.V, m.F, o).error.code, ErrorCode::InvalidOption);
}

TEST(Parameterize, GivenBoundaryPositionsMapAsTheShapeTheyComeFrom) {
  // The circle's own positions, given: the same map as the circle, to the last bit.
  const testmesh::Mesh m = testmesh::hemisphere(8, 16);
  Options circle;
  circle.boundary = BoundaryShape::Circle;
  const Result expected = parameterize(m.V, m.F, circle);
  ASSERT_FALSE(expected.error) << message(expected.error);
  Options given;
  given.boundary = BoundaryShape::Given;
  given.given_boundary = Eigen::MatrixXd::Constant(m.V.rows(), 2, std::nan(""));  // interior rows are not read
  int boundary = 0;
  for (Eigen::Index i = 0; i < m.V.rows(); ++i)
    if (std::abs(m.V(i, 2)) < 1e-12) {  // the hemisphere's rim
      given.given_boundary.row(i) = expected.uv.row(i);
      ++boundary;
    }
  ASSERT_EQ(boundary, 16);
  const Result r = parameterize(m.V, m.F, given);
  ASSERT_FALSE(r.error) << message(r.error);
  EXPECT_EQ(r.uv, expected.uv);
  EXPECT_EQ(r.chosen_pass, expected.chosen_pass);
}

TEST(Parameterize, GivenBoundaryPositionsAreChecked) {
  const testmesh::Mesh m = testmesh::grid(3);
  Options o;
  o.boundary = BoundaryShape::Given;
  const Result none = parameterize(m.V, m.F, o);  // no positions at all
  EXPECT_EQ(none.error.code, ErrorCode::InvalidOption);
  EXPECT_EQ(none.error.option, "given_boundary");
  EXPECT_NE(message(none.error).find("one row of two coordinates per vertex, got 0 x 0"), std::string::npos) << message(none.error);
  o.given_boundary = Eigen::MatrixXd::Zero(m.V.rows(), 2);
  o.given_boundary(0, 1) = std::numeric_limits<double>::infinity();  // vertex 0 is a corner of the grid
  const Result infinite = parameterize(m.V, m.F, o);
  EXPECT_EQ(infinite.error.code, ErrorCode::InvalidOption);
  EXPECT_NE(message(infinite.error).find("finite at every boundary vertex"), std::string::npos) << message(infinite.error);
  EXPECT_TRUE(infinite.uv.size() == 0);
}

// A disk prepared once (prepared_disk.h) maps exactly as the mesh itself, onto every boundary (its
// maps share one LU ordering, the mesh's maps each have their own); a prepared kind other than the
// options' is not used.
TEST(Parameterize, PreparedDiskMapsAsTheMeshDoes) {
  const testmesh::Mesh m = testmesh::grid(12, [](double x, double y) { return 0.3 * std::sin(3 * x) * std::cos(2 * y); });
  PreparedDisk prepared;
  ASSERT_FALSE(prepare_disk(m.V, m.F, InitialWeights::Floater, prepared));
  for (const BoundaryShape shape : {BoundaryShape::Square, BoundaryShape::Circle, BoundaryShape::Natural}) {
    for (const InitialWeights weights : {InitialWeights::Floater, InitialWeights::MeanValue}) {
      Options o;
      o.boundary = shape;
      o.weights = weights;
      const Result direct = parameterize(m.V, m.F, o);
      const Result reused = parameterize(prepared, m.V.rows(), o);
      ASSERT_FALSE(direct.error);
      ASSERT_FALSE(reused.error);
      EXPECT_EQ(reused.uv, direct.uv) << to_string(weights);
      EXPECT_EQ(reused.chosen_pass, direct.chosen_pass);
      EXPECT_GT(direct.passes.size(), 1u);
    }
  }
  // The mean value weights differ from Floater's on this curved grid, so the check above could fail.
  Options floater, mean_value;
  mean_value.weights = InitialWeights::MeanValue;
  EXPECT_NE(parameterize(prepared, m.V.rows(), floater).uv, parameterize(prepared, m.V.rows(), mean_value).uv);
}
