#include "core/stretch.h"

#include <Eigen/Geometry>
#include <cmath>
#include <limits>

namespace lowstretch {

namespace {
const double kInf = std::numeric_limits<double>::infinity();
}  // namespace

FaceStretch face_stretch(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const Eigen::MatrixXd& UV) {
  const Eigen::Index m = F.rows();
  FaceStretch s;
  s.area_3d.resize(m);
  s.area_uv.resize(m);
  s.sigma.resize(m);
  s.gamma.resize(m);
  s.valid.resize(m);
  double total_uv = 0, total_3d = 0;
  for (Eigen::Index f = 0; f < m; ++f) {
    const double s1 = UV(F(f, 0), 0), s2 = UV(F(f, 1), 0), s3 = UV(F(f, 2), 0);
    const double t1 = UV(F(f, 0), 1), t2 = UV(F(f, 1), 1), t3 = UV(F(f, 2), 1);
    s.area_3d(f) = face_area_3d(V, F, f);
    s.area_uv(f) = 0.5 * ((s2 - s1) * (t3 - t1) - (s3 - s1) * (t2 - t1));
    total_uv += std::abs(s.area_uv(f));
    total_3d += s.area_3d(f);
  }
  // A parameter triangle is degenerate below this area: ~1e-16 of the domain, where rounding
  // of unit-sized coordinates starts.
  const double tolerance = 1e-16 * total_uv;
  for (Eigen::Index f = 0; f < m; ++f) {
    const Eigen::Vector3d p1 = V.row(F(f, 0)), p2 = V.row(F(f, 1)), p3 = V.row(F(f, 2));
    const double s1 = UV(F(f, 0), 0), s2 = UV(F(f, 1), 0), s3 = UV(F(f, 2), 0);
    const double t1 = UV(F(f, 0), 1), t2 = UV(F(f, 1), 1), t3 = UV(F(f, 2), 1);
    const double a_uv = s.area_uv(f);
    if (std::abs(a_uv) <= tolerance && is_flat_face(V, F, f)) {
      // No surface to stretch or collapse (a scan's zero-area face): a point or segment in UV too.
      s.valid(f) = true;
      s.sigma(f) = s.gamma(f) = 0;
      continue;
    }
    s.valid(f) = a_uv > tolerance;
    if (a_uv < -tolerance) ++s.flipped;
    else if (!s.valid(f)) ++s.degenerate;
    const double two_area = 2 * std::max(std::abs(a_uv), tolerance > 0 ? tolerance : 1e-300);
    const Eigen::Vector3d Ss = (p1 * (t2 - t3) + p2 * (t3 - t1) + p3 * (t1 - t2)) / two_area;
    const Eigen::Vector3d St = (p1 * (s3 - s2) + p2 * (s1 - s3) + p3 * (s2 - s1)) / two_area;
    const double a = Ss.dot(Ss), b = Ss.dot(St), c = St.dot(St);
    s.sigma(f) = std::sqrt((a + c) / 2);
    s.gamma(f) = std::sqrt(((a + c) + std::sqrt((a - c) * (a - c) + 4 * b * b)) / 2);
  }
  s.normalization = total_3d > 0 ? std::sqrt(total_uv / total_3d) : 1.0;
  return s;
}

Eigen::VectorXd vertex_stretch(const Eigen::MatrixXi& F, int vertex_count, const FaceStretch& s) {
  Eigen::VectorXd weighted = Eigen::VectorXd::Zero(vertex_count), area = Eigen::VectorXd::Zero(vertex_count);
  double global_weighted = 0, global_area = 0;
  for (Eigen::Index f = 0; f < F.rows(); ++f) {
    const double a = s.area_3d(f), e = a * s.sigma(f) * s.sigma(f);
    global_weighted += e;
    global_area += a;
    for (int k = 0; k < 3; ++k) {
      weighted(F(f, k)) += e;
      area(F(f, k)) += a;
    }
  }
  const double global = global_area > 0 ? std::sqrt(global_weighted / global_area) : 1.0;
  Eigen::VectorXd sigma(vertex_count);
  for (int i = 0; i < vertex_count; ++i)
    sigma(i) = s.normalization * (area(i) > 0 ? std::sqrt(weighted(i) / area(i)) : global);
  return sigma;
}

namespace {
// face(i) for i in [0, count): the faces to sum over.
template <class FaceAt>
double l2_stretch_over(const FaceStretch& s, Eigen::Index count, FaceAt face, bool skip_invalid) {
  double weighted = 0, valid_area = 0, area_3d = 0, area_uv = 0;
  for (Eigen::Index i = 0; i < count; ++i) {
    const Eigen::Index f = face(i);
    area_3d += s.area_3d(f);
    area_uv += std::abs(s.area_uv(f));
    if (!s.valid(f)) {
      if (!skip_invalid) return kInf;
      continue;
    }
    weighted += s.area_3d(f) * s.sigma(f) * s.sigma(f);
    valid_area += s.area_3d(f);
  }
  if (!(valid_area > 0)) return kInf;
  return std::sqrt(area_uv / area_3d) * std::sqrt(weighted / valid_area);
}
}  // namespace

double l2_stretch(const FaceStretch& s, bool skip_invalid) {
  return l2_stretch_over(s, s.sigma.size(), [](Eigen::Index i) { return i; }, skip_invalid);
}

double l2_stretch(const FaceStretch& s, const std::vector<int>& faces) {
  return l2_stretch_over(s, Eigen::Index(faces.size()), [&](Eigen::Index i) { return Eigen::Index(faces[size_t(i)]); }, false);
}

SurfaceReference surface_reference(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const Eigen::MatrixXi& edges) {
  SurfaceReference r;
  const Eigen::Index ne = edges.rows(), nf = F.rows();
  r.edge_length.resize(ne);
  for (Eigen::Index e = 0; e < ne; ++e) {
    r.edge_length(e) = (V.row(edges(e, 0)) - V.row(edges(e, 1))).norm();
    r.total_edge_length += r.edge_length(e);
  }
  r.corner_angle.resize(nf, 3);
  for (Eigen::Index f = 0; f < nf; ++f)
    for (int k = 0; k < 3; ++k) {
      const int i = F(f, k), j = F(f, (k + 1) % 3), l = F(f, (k + 2) % 3);
      const Eigen::Vector3d a = (V.row(j) - V.row(i)).transpose(), b = (V.row(l) - V.row(i)).transpose();
      r.corner_angle(f, k) = std::atan2(a.cross(b).norm(), a.dot(b));
    }
  return r;
}

PassMetrics measure(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const Eigen::MatrixXi& edges,
                    const Eigen::MatrixXd& UV, const FaceStretch& s) {
  return measure(F, edges, UV, s, surface_reference(V, F, edges));
}

PassMetrics measure_stretch(const FaceStretch& s) {
  PassMetrics m;
  m.flipped = s.flipped;
  m.degenerate = s.degenerate;
  if (m.flipped + m.degenerate > 0) {
    m.l2_stretch = m.linf_stretch = kInf;
  } else {
    m.l2_stretch = l2_stretch(s);
    m.linf_stretch = s.normalization * s.gamma.maxCoeff();
  }
  return m;
}

PassMetrics measure(const Eigen::MatrixXi& F, const Eigen::MatrixXi& edges, const Eigen::MatrixXd& UV, const FaceStretch& s,
                    const SurfaceReference& reference) {
  PassMetrics m = measure_stretch(s);
  const Eigen::Index nf = F.rows();
  const double total_3d = s.area_3d.sum(), total_uv = s.area_uv.cwiseAbs().sum();

  const Eigen::Index ne = edges.rows();
  Eigen::VectorXd lu(ne);
  for (Eigen::Index e = 0; e < ne; ++e) lu(e) = (UV.row(edges(e, 0)) - UV.row(edges(e, 1))).norm();
  const double length_uv = lu.sum();
  for (Eigen::Index e = 0; e < ne; ++e)
    m.edge_distortion += std::abs(reference.edge_length(e) / reference.total_edge_length - lu(e) / length_uv);

  double angle_sum = 0;
  for (Eigen::Index f = 0; f < nf; ++f)
    for (int k = 0; k < 3; ++k) {
      const int i = F(f, k), j = F(f, (k + 1) % 3), l = F(f, (k + 2) % 3);
      const double ax = UV(j, 0) - UV(i, 0), ay = UV(j, 1) - UV(i, 1), bx = UV(l, 0) - UV(i, 0), by = UV(l, 1) - UV(i, 1);
      angle_sum += std::abs(reference.corner_angle(f, k) - std::atan2(std::abs(ax * by - ay * bx), ax * bx + ay * by));
    }
  m.angle_distortion = angle_sum / (3.0 * double(nf));

  for (Eigen::Index f = 0; f < nf; ++f)
    m.area_distortion += std::abs(s.area_3d(f) / total_3d - s.area_uv(f) / total_uv);
  return m;
}

}  // namespace lowstretch
