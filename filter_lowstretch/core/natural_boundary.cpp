#include "core/natural_boundary.h"

#include <Eigen/SparseCholesky>
#include <Eigen/Geometry>
#include <cmath>
#include <vector>

namespace lowstretch {

namespace {

// cot of the angle at `apex`, bounded so that zero-area triangles cannot produce inf or NaN.
double bounded_cot(const Eigen::RowVector3d& apex, const Eigen::RowVector3d& a, const Eigen::RowVector3d& b) {
  const Eigen::RowVector3d u = a - apex, v = b - apex;
  const double s = u.cross(v).norm(), c = u.dot(v);
  const double limit = 1e6;
  if (!(s > 0)) return c > 0 ? limit : (c < 0 ? -limit : 0.0);
  return std::max(-limit, std::min(limit, c / s));
}

// The boundary vertex farthest from `from`.
int farthest_boundary_vertex(const DiskMesh& disk, int from) {
  int best = disk.boundary[0];
  double best_d = -1;
  for (int v : disk.boundary) {
    const double d = (disk.V.row(v) - disk.V.row(from)).squaredNorm();
    if (d > best_d) {
      best_d = d;
      best = v;
    }
  }
  return best;
}

// Unknowns x = [u; v] (2n). Quadratic form Q = [L, -M/2; M/2, L]: L the cotangent Laplacian
// (E_D(u) = u'Lu/2) and u'Mv = sum over boundary half-edges i->j of (u_i v_j - u_j v_i) = 2A.
// x'Qx / 2 is the conformal energy E_D - A of least-squares conformal maps.
Eigen::SparseMatrix<double> conformal_energy(const DiskMesh& disk) {
  const int n = int(disk.V.rows());
  const int nb = int(disk.boundary.size());
  std::vector<Eigen::Triplet<double>> q;
  q.reserve(size_t(disk.F.rows()) * 24 + size_t(nb) * 4);
  for (Eigen::Index f = 0; f < disk.F.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int i = disk.F(f, (k + 1) % 3), j = disk.F(f, (k + 2) % 3), apex = disk.F(f, k);
      const double w = 0.5 * bounded_cot(disk.V.row(apex), disk.V.row(i), disk.V.row(j));
      for (int c = 0; c < 2; ++c) {
        const int o = c * n;
        q.emplace_back(o + i, o + j, -w);
        q.emplace_back(o + j, o + i, -w);
        q.emplace_back(o + i, o + i, w);
        q.emplace_back(o + j, o + j, w);
      }
    }
  for (int k = 0; k < nb; ++k) {
    const int i = disk.boundary[size_t(k)], j = disk.boundary[size_t((k + 1) % nb)];
    // -u'Mv split symmetrically: entries (u_i, v_j) and (v_j, u_i) get -1/2, (u_j, v_i) +1/2.
    q.emplace_back(i, n + j, -0.5);
    q.emplace_back(n + j, i, -0.5);
    q.emplace_back(j, n + i, 0.5);
    q.emplace_back(n + i, j, 0.5);
  }
  Eigen::SparseMatrix<double> Q(2 * n, 2 * n);
  Q.setFromTriplets(q.begin(), q.end());
  return Q;
}

}  // namespace

Error natural_boundary(const DiskMesh& disk, Eigen::MatrixXd& boundary_uv) {
  const int n = int(disk.V.rows());
  const int nb = int(disk.boundary.size());
  // Pins: the boundary vertex farthest from the loop's first vertex, then the one farthest from
  // that (two sweeps approximate the diameter).
  const int pin_a = farthest_boundary_vertex(disk, disk.boundary[0]);
  const int pin_b = farthest_boundary_vertex(disk, pin_a);
  const Eigen::SparseMatrix<double> Q = conformal_energy(disk);

  // Eliminate the four pinned unknowns: Q_ff x_f = -Q_fp x_p.
  const double scale = (disk.V.row(pin_a) - disk.V.row(pin_b)).norm();
  std::vector<int> free_index(size_t(2 * n), -1);
  Eigen::VectorXd pinned_value = Eigen::VectorXd::Zero(2 * n);
  std::vector<char> pinned(size_t(2 * n), 0);
  pinned[size_t(pin_a)] = pinned[size_t(n + pin_a)] = pinned[size_t(pin_b)] = pinned[size_t(n + pin_b)] = 1;
  pinned_value(pin_b) = scale;  // pin_a at (0,0), pin_b at (scale, 0): keeps 3D units
  int nf = 0;
  for (int i = 0; i < 2 * n; ++i)
    if (!pinned[size_t(i)]) free_index[size_t(i)] = nf++;
  std::vector<Eigen::Triplet<double>> qff;
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(nf);
  for (int col = 0; col < Q.outerSize(); ++col)
    for (Eigen::SparseMatrix<double>::InnerIterator it(Q, col); it; ++it) {
      const int r = int(it.row()), c = int(it.col());
      if (pinned[size_t(r)]) continue;
      if (pinned[size_t(c)]) rhs(free_index[size_t(r)]) -= it.value() * pinned_value(c);
      else qff.emplace_back(free_index[size_t(r)], free_index[size_t(c)], it.value());
    }
  Eigen::SparseMatrix<double> Qff(nf, nf);
  Qff.setFromTriplets(qff.begin(), qff.end());
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(Qff);
  if (solver.info() != Eigen::Success) return {ErrorCode::SolverFailed, 0, "natural boundary factorization"};
  const Eigen::VectorXd xf = solver.solve(rhs);
  if (solver.info() != Eigen::Success || !xf.allFinite())
    return {ErrorCode::SolverFailed, 0, "natural boundary solve"};

  auto value = [&](int i) { return pinned[size_t(i)] ? pinned_value(i) : xf(free_index[size_t(i)]); };
  boundary_uv.resize(nb, 2);
  for (int k = 0; k < nb; ++k) {
    boundary_uv(k, 0) = value(disk.boundary[size_t(k)]);
    boundary_uv(k, 1) = value(n + disk.boundary[size_t(k)]);
  }
  // Fit into [0,1]^2; the loop runs counter-clockwise for an orientation-preserving map.
  const Eigen::RowVector2d lo = boundary_uv.colwise().minCoeff(), hi = boundary_uv.colwise().maxCoeff();
  const double extent = (hi - lo).maxCoeff();
  if (!(extent > 0)) return {ErrorCode::SolverFailed, 0, "natural boundary collapsed to a point"};
  boundary_uv = (boundary_uv.rowwise() - lo) / extent;
  return {};
}

}  // namespace lowstretch
