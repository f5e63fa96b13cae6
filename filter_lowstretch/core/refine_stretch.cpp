#include "core/refine_stretch.h"

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <Eigen/Sparse>
#include <Eigen/CholmodSupport>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <vector>

#include "core/metis_lock.h"
#include "core/one_openmp_thread.h"
#include "core/stretch.h"
#include "core/stretch_hessian.h"

namespace lowstretch {

namespace {

using Clock = std::chrono::steady_clock;

// From this many unknowns (two per moving vertex) the Newton systems are factored by supernodes
// in METIS order; below it, in AMD order, as CHOLMOD chooses.
constexpr int kLeastSupernodalUnknowns = 20000;

// A triangle in a plane of its own: gradients g[k] (2D) of its three hat functions, and its area.
struct FlatTriangle {
  Eigen::Matrix<double, 3, 2> g;
  double area = 0;
  double least_uv_area = 0;  // see refine_stretch.h
};

std::vector<FlatTriangle> flatten(const DiskMesh& disk) {
  std::vector<FlatTriangle> flat(size_t(disk.F.rows()));
  for (Eigen::Index f = 0; f < disk.F.rows(); ++f) {
    const Eigen::Vector3d p0 = disk.V.row(disk.F(f, 0)), p1 = disk.V.row(disk.F(f, 1)), p2 = disk.V.row(disk.F(f, 2));
    const Eigen::Vector3d e1 = p1 - p0, e2 = p2 - p0;
    const double x1 = e1.norm();
    FlatTriangle& t = flat[size_t(f)];
    if (!(x1 > 0)) continue;
    const double x2 = e2.dot(e1) / x1, y2 = e1.cross(e2).norm() / x1;
    t.area = 0.5 * x1 * y2;
    if (!(t.area > 0)) continue;
    // Local coordinates (0,0), (x1,0), (x2,y2): the hat gradients, rotated edges over 2 area.
    const Eigen::Vector2d q[3] = {{0, 0}, {x1, 0}, {x2, y2}};
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector2d edge = q[(k + 2) % 3] - q[(k + 1) % 3];
      t.g.row(k) = Eigen::RowVector2d(-edge.y(), edge.x()) / (2 * t.area);
    }
  }
  return flat;
}

Eigen::Matrix2d jacobian(const FlatTriangle& t, const Eigen::MatrixXd& uv, const Eigen::RowVector3i& face) {
  Eigen::Matrix2d J = Eigen::Matrix2d::Zero();
  for (int k = 0; k < 3; ++k) J += uv.row(face(k)).transpose() * t.g.row(k);
  return J;
}

// Energy A |J|^2 / (2 det^2); infinite when det <= 0. Adds the gradient to `grad` if given.
double stretch_energy(const DiskMesh& disk, const std::vector<FlatTriangle>& flat, const Eigen::MatrixXd& uv,
                      Eigen::MatrixXd* grad) {
  double total = 0;
  if (grad) grad->setZero(uv.rows(), 2);
  for (Eigen::Index f = 0; f < disk.F.rows(); ++f) {
    const FlatTriangle& t = flat[size_t(f)];
    const Eigen::RowVector3i face = disk.F.row(f);
    // A zero-area 3D triangle carries no stretch, but its UV triangle must keep its least area too.
    if (!(t.area > 0)) {
      if (!(signed_uv_area(uv.row(face(0)), uv.row(face(1)), uv.row(face(2))) > t.least_uv_area))
        return std::numeric_limits<double>::infinity();
      continue;
    }
    const Eigen::Matrix2d J = jacobian(t, uv, face);
    const double det = J.determinant();  // UV area over 3D area
    if (!(det > 0) || !(det * t.area > t.least_uv_area)) return std::numeric_limits<double>::infinity();
    const double norm2 = J.squaredNorm();
    total += t.area * norm2 / (2 * det * det);
    if (!grad) continue;
    Eigen::Matrix2d cofactor;
    cofactor << J(1, 1), -J(1, 0), -J(0, 1), J(0, 0);
    const Eigen::Matrix2d dJ = t.area * (J / (det * det) - norm2 / (det * det * det) * cofactor);
    for (int k = 0; k < 3; ++k) grad->row(face(k)) += (dJ * t.g.row(k).transpose()).transpose();
  }
  return total;
}

// The UV area of the faces with 3D area; adds its gradient to `grad` if given.
double uv_area_of(const DiskMesh& disk, const std::vector<FlatTriangle>& flat, const Eigen::MatrixXd& uv, Eigen::MatrixXd* grad) {
  double total = 0;
  if (grad) grad->setZero(uv.rows(), 2);
  for (Eigen::Index f = 0; f < disk.F.rows(); ++f) {
    if (!(flat[size_t(f)].area > 0)) continue;
    const Eigen::RowVector3i face = disk.F.row(f);
    total += signed_uv_area(uv.row(face(0)), uv.row(face(1)), uv.row(face(2)));
    if (!grad) continue;
    for (int k = 0; k < 3; ++k) {
      const Eigen::RowVector2d a = uv.row(face((k + 1) % 3)), b = uv.row(face((k + 2) % 3));
      grad->row(face(k)) += 0.5 * Eigen::RowVector2d(a.y() - b.y(), b.x() - a.x());
    }
  }
  return total;
}

// Boundary fixed: the stretch energy. Free: the stretch energy times the UV area over `area0`,
// which no scaling changes (the stretch energy alone falls as the map grows).
double energy(const DiskMesh& disk, const std::vector<FlatTriangle>& flat, const Eigen::MatrixXd& uv,
              Eigen::MatrixXd* grad, double area0, double* scale = nullptr) {
  if (area0 <= 0) return stretch_energy(disk, flat, uv, grad);
  Eigen::MatrixXd grad_area;
  const double a = stretch_energy(disk, flat, uv, grad);
  if (!std::isfinite(a)) return a;
  const double area = uv_area_of(disk, flat, uv, grad ? &grad_area : nullptr);
  if (grad) *grad = (area * *grad + a * grad_area) / area0;
  if (scale) *scale = area / area0;
  return a * area / area0;
}

// The largest step t along d that keeps every UV triangle above its least area, capped at 1e9:
// twice the signed area of a triangle moving along d, less twice its least area, is c + b t + a t^2.
double largest_safe_step(const DiskMesh& disk, const std::vector<FlatTriangle>& flat, const Eigen::MatrixXd& uv,
                         const Eigen::MatrixXd& d) {
  double largest = 1e9;
  for (Eigen::Index f = 0; f < disk.F.rows(); ++f) {
    const Eigen::RowVector3i face = disk.F.row(f);
    const Eigen::RowVector2d p1 = uv.row(face(1)) - uv.row(face(0)), p2 = uv.row(face(2)) - uv.row(face(0));
    const Eigen::RowVector2d q1 = d.row(face(1)) - d.row(face(0)), q2 = d.row(face(2)) - d.row(face(0));
    const auto cross = [](const Eigen::RowVector2d& x, const Eigen::RowVector2d& y) { return x.x() * y.y() - x.y() * y.x(); };
    const double c = cross(p1, p2) - 2 * flat[size_t(f)].least_uv_area, b = cross(p1, q2) + cross(q1, p2), a = cross(q1, q2);
    double root = std::numeric_limits<double>::infinity();
    if (std::abs(a) < 1e-300) {
      if (b < 0) root = -c / b;
    } else {
      const double disc = b * b - 4 * a * c;
      if (disc >= 0) {
        const double s = std::sqrt(disc);
        for (double r : {(-b - s) / (2 * a), (-b + s) / (2 * a)})
          if (r > 0) root = std::min(root, r);
      }
    }
    largest = std::min(largest, root);
  }
  return largest;
}

// The Hessian's sparsity pattern, built once, and where each triangle's 6x6 block lands in its
// values: refilling values in place costs a fraction of rebuilding the matrix from triplets.
// Rows are interior unknowns, 2 per vertex (u, then v).
struct HessianLayout {
  Eigen::SparseMatrix<double> H;
  std::vector<Eigen::Index> slot;      // 36 per face, row-major over (a, b); -1: a boundary unknown
  std::vector<Eigen::Index> diagonal;  // slot of (r, r) per row
};

HessianLayout hessian_layout(const DiskMesh& disk, const std::vector<int>& unknown, int count) {
  HessianLayout layout;
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(size_t(disk.F.rows()) * 36 + size_t(2 * count));
  const auto row = [&](Eigen::Index f, int a) {
    const int r = unknown[size_t(disk.F(f, a % 3))];
    return r < 0 ? -1 : 2 * r + a / 3;
  };
  for (Eigen::Index f = 0; f < disk.F.rows(); ++f)
    for (int a = 0; a < 6; ++a)
      for (int b = 0; b < 6; ++b)
        if (row(f, a) >= 0 && row(f, b) >= 0) entries.emplace_back(row(f, a), row(f, b), 0.0);
  for (int r = 0; r < 2 * count; ++r) entries.emplace_back(r, r, 0.0);
  layout.H.resize(2 * count, 2 * count);
  layout.H.setFromTriplets(entries.begin(), entries.end());
  layout.H.makeCompressed();
  // Column-major: the slot of (r, c) is found within column c's sorted row indices.
  const auto find = [&](int r, int c) {
    const int* begin = layout.H.innerIndexPtr() + layout.H.outerIndexPtr()[c];
    const int* end = layout.H.innerIndexPtr() + layout.H.outerIndexPtr()[c + 1];
    return Eigen::Index(std::lower_bound(begin, end, r) - layout.H.innerIndexPtr());
  };
  layout.slot.assign(size_t(disk.F.rows()) * 36, -1);
  for (Eigen::Index f = 0; f < disk.F.rows(); ++f)
    for (int a = 0; a < 6; ++a)
      for (int b = 0; b < 6; ++b)
        if (row(f, a) >= 0 && row(f, b) >= 0) layout.slot[size_t(f) * 36 + size_t(6 * a + b)] = find(row(f, a), row(f, b));
  layout.diagonal.resize(size_t(2 * count));
  for (int r = 0; r < 2 * count; ++r) layout.diagonal[size_t(r)] = find(r, r);
  return layout;
}

// Projected Newton (Teran et al. 2005): each triangle's Hessian with respect to J, its negative
// eigenvalue clamped to zero (core/stretch_hessian.h), pulled back to the triangle's six texture
// coordinates and added into layout.H's values. With a free boundary, the stretch energy's
// Hessian times `scale` (the UV area over its first): the terms of the product with the area are
// left out, which keeps H positive definite and each step a descent.
void fill_projected_hessian(const DiskMesh& disk, const std::vector<FlatTriangle>& flat, const Eigen::MatrixXd& uv,
                            HessianLayout& layout, double scale) {
  double* values = layout.H.valuePtr();
  std::fill(values, values + layout.H.nonZeros(), 0.0);
  for (Eigen::Index f = 0; f < disk.F.rows(); ++f) {
    const FlatTriangle& t = flat[size_t(f)];
    if (!(t.area > 0)) continue;
    const Eigen::RowVector3i face = disk.F.row(f);
    const Eigen::Matrix4d projected = t.area * scale * projected_stretch_hessian(jacobian(t, uv, face));
    // vec(J) = G x with x = (u0, u1, u2, v0, v1, v2).
    Eigen::Matrix<double, 4, 6> G = Eigen::Matrix<double, 4, 6>::Zero();
    for (int k = 0; k < 3; ++k) {
      G(0, k) = t.g(k, 0);
      G(1, k) = t.g(k, 1);
      G(2, 3 + k) = t.g(k, 0);
      G(3, 3 + k) = t.g(k, 1);
    }
    const Eigen::Matrix<double, 6, 6> Hx = G.transpose() * projected * G;
    const Eigen::Index* slot = &layout.slot[size_t(f) * 36];
    for (int a = 0; a < 6; ++a)
      for (int b = 0; b < 6; ++b)
        if (slot[6 * a + b] >= 0) values[slot[6 * a + b]] += Hx(a, b);
  }
  // A small multiple of the diagonal keeps H positive definite where projection left it singular.
  for (const Eigen::Index d : layout.diagonal) values[d] += 1e-8 * (1 + values[d]);
}

}  // namespace

Eigen::MatrixXd refine_stretch(const DiskMesh& disk, const Eigen::MatrixXd& uv0, const RefineOptions& options,
                               RefineReport& report) {
  const Clock::time_point start = Clock::now();
  std::vector<FlatTriangle> flat = flatten(disk);
  Eigen::VectorXd uv_area(disk.F.rows());
  for (Eigen::Index f = 0; f < disk.F.rows(); ++f)
    uv_area(f) = std::max(0.0, signed_uv_area(uv0.row(disk.F(f, 0)), uv0.row(disk.F(f, 1)), uv0.row(disk.F(f, 2))));
  const double least = options.least_area_share * uv_area.sum();
  for (Eigen::Index f = 0; f < disk.F.rows(); ++f) flat[size_t(f)].least_uv_area = std::min(least, 0.5 * uv_area(f));
  Eigen::MatrixXd uv = uv0;
  const double area0 = options.free_boundary ? uv_area_of(disk, flat, uv, nullptr) : 0;
  double e = energy(disk, flat, uv, nullptr, area0);
  report = RefineReport();
  report.energy_before = report.energy_after = e;
  if (!std::isfinite(e)) return uv;
  report.started = true;
  const int n = int(disk.V.rows());
  std::vector<int> unknown(size_t(n), -1);
  int count = 0;
  for (int i = 0; i < n; ++i)
    if (options.free_boundary || !disk.is_boundary[size_t(i)]) unknown[size_t(i)] = count++;
  if (count == 0) return uv;
  HessianLayout layout = hessian_layout(disk, unknown, count);
  const OneOpenMpThread alone;
  Eigen::CholmodDecomposition<Eigen::SparseMatrix<double>> newton;  // SuiteSparse's CHOLMOD
  newton.cholmod().nmethods = 1;
  if (2 * count < kLeastSupernodalUnknowns) {
    // AMD and CHOLMOD's own choice of factorization: on a small system METIS's analysis and the
    // supernodes' dense blocks cost more than they save.
    newton.setMode(Eigen::CholmodAuto);
    newton.cholmod().method[0].ordering = CHOLMOD_AMD;
    newton.analyzePattern(layout.H);
  } else {
    // METIS: a costlier analysis (done once) than AMD, for less fill in every factorization.
    newton.setMode(Eigen::CholmodSupernodalLLt);
    newton.cholmod().method[0].ordering = CHOLMOD_METIS;
    const std::lock_guard<std::mutex> one_ordering_at_a_time(metis_lock());
    newton.analyzePattern(layout.H);
  }
  Eigen::MatrixXd grad, d = Eigen::MatrixXd::Zero(n, 2);
  Eigen::VectorXd g(2 * count);
  for (int it = 0; it < options.max_iterations; ++it) {
    double scale = 1;
    energy(disk, flat, uv, &grad, area0, &scale);
    for (int i = 0; i < n; ++i)
      if (unknown[size_t(i)] >= 0) g.segment<2>(2 * unknown[size_t(i)]) = grad.row(i).transpose();
    fill_projected_hessian(disk, flat, uv, layout, scale);
    newton.factorize(layout.H);
    if (newton.info() != Eigen::Success) break;
    const Eigen::VectorXd step = -newton.solve(g);
    for (int i = 0; i < n; ++i)
      if (unknown[size_t(i)] >= 0) d.row(i) = step.segment<2>(2 * unknown[size_t(i)]).transpose();
    const double slope = g.dot(step);  // < 0: a descent direction
    if (!(slope < 0)) break;
    double t = std::min(1.0, 0.9 * largest_safe_step(disk, flat, uv, d));
    double next = std::numeric_limits<double>::infinity();
    for (int tries = 0; tries < 40; ++tries, t /= 2) {
      next = energy(disk, flat, uv + t * d, nullptr, area0);
      if (next <= e + 1e-4 * t * slope) break;
    }
    if (!(next < e)) break;
    uv += t * d;
    const double decrease = (e - next) / e;
    e = next;
    report.iterations = it + 1;
    if (decrease < options.relative_decrease) break;
  }
  report.energy_after = e;
  report.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  return uv;
}

}  // namespace lowstretch
