#include "laplacian_solver.h"

#include <chrono>

namespace lowstretch {

namespace {
using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

// Position of entry (row, col) in the value array of a compressed column-major matrix.
int value_index(const Eigen::SparseMatrix<double>& A, int row, int col) {
  const int* inner = A.innerIndexPtr();
  const int begin = A.outerIndexPtr()[col], end = A.outerIndexPtr()[col + 1];
  return int(std::lower_bound(inner + begin, inner + end, row) - inner);
}
}  // namespace

LaplacianSolver::LaplacianSolver(const DiskMesh& disk) : disk_(disk) {
  const int n = int(disk.V.rows());
  unknown_.assign(size_t(n), -1);
  int rows = 0;
  for (int i = 0; i < n; ++i)
    if (!disk.is_boundary[size_t(i)]) unknown_[size_t(i)] = rows++;
  std::vector<Eigen::Triplet<double>> pattern;
  pattern.reserve(disk.ring.size() + size_t(rows));
  for (int i = 0; i < n; ++i) {
    const int r = unknown_[size_t(i)];
    if (r < 0) continue;
    pattern.emplace_back(r, r, 1.0);
    for (int s = disk.ring_start[size_t(i)]; s < disk.ring_start[size_t(i) + 1]; ++s)
      if (unknown_[size_t(disk.ring[size_t(s)])] >= 0) pattern.emplace_back(r, unknown_[size_t(disk.ring[size_t(s)])], 1.0);
  }
  matrix_.resize(rows, rows);
  matrix_.setFromTriplets(pattern.begin(), pattern.end());
  matrix_.makeCompressed();
  slot_to_value_.assign(disk.ring.size(), -1);
  diagonal_value_.assign(size_t(rows), -1);
  for (int i = 0; i < n; ++i) {
    const int r = unknown_[size_t(i)];
    if (r < 0) continue;
    diagonal_value_[size_t(r)] = value_index(matrix_, r, r);
    for (int s = disk.ring_start[size_t(i)]; s < disk.ring_start[size_t(i) + 1]; ++s) {
      const int c = unknown_[size_t(disk.ring[size_t(s)])];
      if (c >= 0) slot_to_value_[size_t(s)] = value_index(matrix_, r, c);
    }
  }
}

Eigen::MatrixXd LaplacianSolver::assemble(const std::vector<double>& weights, const Eigen::MatrixXd& boundary_uv,
                                          Eigen::MatrixXd& uv) {
  const int n = int(disk_.V.rows());
  uv.resize(n, 2);
  for (size_t k = 0; k < disk_.boundary.size(); ++k) uv.row(disk_.boundary[k]) = boundary_uv.row(Eigen::Index(k));
  double* values = matrix_.valuePtr();
  std::fill(values, values + matrix_.nonZeros(), 0.0);
  Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(matrix_.rows(), 2);
  for (int i = 0; i < n; ++i) {
    const int r = unknown_[size_t(i)];
    if (r < 0) continue;
    for (int s = disk_.ring_start[size_t(i)]; s < disk_.ring_start[size_t(i) + 1]; ++s) {
      const double w = weights[size_t(s)];
      values[diagonal_value_[size_t(r)]] += w;
      if (slot_to_value_[size_t(s)] >= 0) values[slot_to_value_[size_t(s)]] -= w;
      else rhs.row(r) += w * uv.row(disk_.ring[size_t(s)]);
    }
  }
  return rhs;
}

void LaplacianSolver::scatter(const Eigen::MatrixXd& x, Eigen::MatrixXd& uv) const {
  for (int i = 0; i < int(disk_.V.rows()); ++i)
    if (unknown_[size_t(i)] >= 0) uv.row(i) = x.row(unknown_[size_t(i)]);
}

bool LaplacianSolver::solve(const std::vector<double>& weights, const Eigen::MatrixXd& boundary_uv,
                            Eigen::MatrixXd& uv) {
  Clock::time_point start = Clock::now();
  const Eigen::MatrixXd rhs = assemble(weights, boundary_uv, uv);
  if (matrix_.rows() == 0) return true;  // every vertex is on the boundary
  seconds_assembly = seconds_since(start);
  start = Clock::now();
  if (!analyzed_) {
    // METIS leaves about half the fill of the default AMD ordering on these meshes. The matrix
    // is diagonally dominant, so the factorization is accurate without iterative refinement
    // (which would triple the cost of a solve).
    lu_.umfpackControl()(UMFPACK_ORDERING) = UMFPACK_ORDERING_METIS;
    lu_.umfpackControl()(UMFPACK_IRSTEP) = 0;
    lu_.analyzePattern(matrix_);
    analyzed_ = true;
  }
  lu_.factorize(matrix_);
  seconds_factorization = seconds_since(start);
  if (lu_.info() != Eigen::Success) return false;
  start = Clock::now();
  const Eigen::MatrixXd x = lu_.solve(rhs);
  seconds_solve = seconds_since(start);
  if (lu_.info() != Eigen::Success || !x.allFinite()) return false;
  scatter(x, uv);
  return true;
}

}  // namespace lowstretch
