// Stretch and metrics: analytic values of affine maps, and vcglib's Distortion as a second opinion.
#include <gtest/gtest.h>

#include <cmath>
#include <vcg/complex/complex.h>
// after complex.h, which it needs
#include <vcg/complex/algorithms/parametrization/distortion.h>

#include "atlas/charts.h"
#include "core/disk_mesh.h"
#include "core/parameterize.h"
#include "core/stretch.h"
#include "generated_meshes.h"
#include "vcg_arrays/mesh_arrays.h"

using namespace lowstretch;

namespace {

struct Measured {
  FaceStretch faces;
  PassMetrics metrics;
};

// UV = the grid's (x, y) mapped by the 2x2 matrix A.
Measured measure_affine(const Eigen::Matrix2d& A) {
  const testmesh::Mesh m = testmesh::grid(6);
  DiskMesh disk;
  EXPECT_FALSE(make_disk_mesh(m.V, m.F, disk));
  const Eigen::MatrixXd uv = disk.V.leftCols(2) * A.transpose();
  Measured r{face_stretch(disk.V, disk.F, uv), {}};
  r.metrics = measure(disk.V, disk.F, disk.edges, uv, r.faces);
  return r;
}

}  // namespace

TEST(Stretch, IdentityIsOneEverywhereWithNoDistortion) {
  const Measured r = measure_affine(Eigen::Matrix2d::Identity());
  EXPECT_NEAR(r.metrics.l2_stretch, 1.0, 1e-12);
  EXPECT_NEAR(r.metrics.linf_stretch, 1.0, 1e-12);
  EXPECT_NEAR(r.metrics.edge_distortion, 0.0, 1e-12);
  EXPECT_NEAR(r.metrics.angle_distortion, 0.0, 1e-12);
  EXPECT_NEAR(r.metrics.area_distortion, 0.0, 1e-12);
  EXPECT_EQ(r.metrics.flipped, 0);
}

TEST(Stretch, UniformScalingIsNormalizedAway) {
  const Measured r = measure_affine(2.5 * Eigen::Matrix2d::Identity());
  EXPECT_NEAR(r.faces.sigma(0), 1 / 2.5, 1e-12);  // raw: 3D length per parameter length
  EXPECT_NEAR(r.metrics.l2_stretch, 1.0, 1e-12);
  EXPECT_NEAR(r.metrics.angle_distortion, 0.0, 1e-12);
}

TEST(Stretch, ShearHasItsAnalyticValue) {
  const double k = 0.75;
  Eigen::Matrix2d A;
  A << 1, k, 0, 1;  // u = x + k y: the surface as a function of (u, v) has Jacobian A^-1
  const Measured r = measure_affine(A);
  EXPECT_NEAR(r.metrics.l2_stretch, std::sqrt(1 + k * k / 2), 1e-12);
  EXPECT_NEAR(r.metrics.linf_stretch, (k + std::sqrt(k * k + 4)) / 2, 1e-12);
  EXPECT_NEAR(r.metrics.area_distortion, 0.0, 1e-12);  // det 1
  EXPECT_GT(r.metrics.angle_distortion, 0.1);
}

TEST(Stretch, AnisotropicScalingHasItsAnalyticValue) {
  Eigen::Matrix2d A;
  A << 2, 0, 0, 0.5;  // det 1, singular values of A^-1: 2 and 0.5
  const Measured r = measure_affine(A);
  EXPECT_NEAR(r.metrics.l2_stretch, std::sqrt((4 + 0.25) / 2), 1e-12);
  EXPECT_NEAR(r.metrics.linf_stretch, 2.0, 1e-12);
}

TEST(Stretch, MirroredMapIsAllFlippedAndInfinite) {
  Eigen::Matrix2d A;
  A << -1, 0, 0, 1;
  const Measured r = measure_affine(A);
  EXPECT_EQ(r.metrics.flipped, 72);
  EXPECT_TRUE(std::isinf(r.metrics.l2_stretch));
}

// A vcglib mesh with double wedge texcoords, for Distortion<Mesh, true>.
class TV;
class TF;
struct TU : vcg::UsedTypes<vcg::Use<TV>::AsVertexType, vcg::Use<TF>::AsFaceType> {};
class TV : public vcg::Vertex<TU, vcg::vertex::Coord3d, vcg::vertex::TexCoord2d, vcg::vertex::Qualityd, vcg::vertex::BitFlags> {};
class TF : public vcg::Face<TU, vcg::face::VertexRef, vcg::face::WedgeTexCoord2d, vcg::face::Qualityd, vcg::face::BitFlags,
                            vcg::face::CurvatureDird> {};
class TM : public vcg::tri::TriMesh<std::vector<TV>, std::vector<TF>> {};

TEST(Stretch, AgreesWithVcglibDistortionOnAParameterizedSurface) {
  const testmesh::Mesh m = testmesh::hemisphere(12, 24);
  ChartOptions o;
  o.disk.max_passes = 3;
  const ChartsResult r = parameterize_charts(m.V, m.F, o);
  ASSERT_FALSE(r.error) << message(r.error);
  ASSERT_TRUE(r.input_is_disk);

  TM tm;
  vcg::tri::Allocator<TM>::AddVertices(tm, size_t(m.V.rows()));
  vcg::tri::Allocator<TM>::AddFaces(tm, size_t(m.F.rows()));
  for (Eigen::Index i = 0; i < m.V.rows(); ++i) tm.vert[size_t(i)].P() = vcg::Point3d(m.V(i, 0), m.V(i, 1), m.V(i, 2));
  for (Eigen::Index f = 0; f < m.F.rows(); ++f)
    for (int k = 0; k < 3; ++k) tm.face[size_t(f)].V(k) = &tm.vert[size_t(m.F(f, k))];
  Eigen::MatrixXd V;
  Eigen::MatrixXi F;
  const ArrayRows rows = mesh_to_arrays(tm, V, F);
  write_parameterization(tm, rows, r);

  using D = vcg::tri::Distortion<TM, true>;
  double area_scale = 0, edge_scale = 0;
  D::MeshScalingFactor(tm, area_scale, edge_scale);
  double weighted = 0, area = 0, linf = 0;
  for (size_t f = 0; f < tm.face.size(); ++f) {
    const double l2_squared = D::L2StretchEnergySquared(&tm.face[f], area_scale);
    EXPECT_NEAR(std::sqrt(l2_squared), r.face_stretch(Eigen::Index(f)), 1e-9 * r.face_stretch(Eigen::Index(f)));
    EXPECT_DOUBLE_EQ(tm.face[f].Q(), r.face_stretch(Eigen::Index(f)));
    weighted += D::Area3D(&tm.face[f]) * l2_squared;
    area += D::Area3D(&tm.face[f]);
    linf = std::max(linf, D::LInfStretchEnergy(&tm.face[f], area_scale));
  }
  // The reported metrics are those of the texture coordinates as stored (float), which vcglib
  // measured here; the kept pass, computed in double, differs from them by the rounding only.
  EXPECT_NEAR(std::sqrt(weighted / area), r.layout.l2_stretch, 1e-9);
  EXPECT_NEAR(linf, r.layout.linf_stretch, 1e-9 * linf);
  EXPECT_EQ(D::FoldedNum(tm), r.layout.flipped);
  const PassMetrics& kept = r.disk_passes[size_t(r.chosen_pass)];
  EXPECT_EQ(r.layout.pass, kept.pass);
  EXPECT_NEAR(r.layout.l2_stretch, kept.l2_stretch, 1e-6 * kept.l2_stretch);
}

TEST(Stretch, VertexStretchIsTheAreaWeightedMeanOfItsFaces) {
  const testmesh::Mesh m = testmesh::hemisphere(6, 12);
  const Result r = parameterize(m.V, m.F);
  ASSERT_FALSE(r.error);
  // The apex (vertex 0) touches the first 12 faces; compute its sigma from them by hand.
  double weighted = 0, area = 0;
  for (int f = 0; f < 12; ++f) {
    const Eigen::RowVector3d a = m.V.row(m.F(f, 0)), b = m.V.row(m.F(f, 1)), c = m.V.row(m.F(f, 2));
    const double A = 0.5 * (b - a).cross(c - a).norm();
    weighted += A * r.face_stretch(f) * r.face_stretch(f);
    area += A;
  }
  EXPECT_NEAR(r.vertex_stretch(0), std::sqrt(weighted / area), 1e-12);
}
