#include "core/laplacian_solver.h"

#include <algorithm>
#include <chrono>
#include <memory>

#include <amgcl/amg.hpp>
#include <amgcl/backend/builtin.hpp>
#include <amgcl/relaxation/gauss_seidel.hpp>
#include <amgcl/solver/bicgstab.hpp>
#include <boost/make_shared.hpp>
#include <boost/range/iterator_range.hpp>

#include "core/metis_lock.h"
#include "core/thread_pool.h"
#include "core/reused_coarsening.h"

namespace lowstretch {

namespace {
using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

// The coarsest level, solved by amgcl's own dense LU: at its default (3000 unknowns) that dense
// solve is the slowest part of every cycle.
constexpr unsigned kCoarseEnough = 1500;

// Below this many unknowns KLU factors and solves faster than UMFPACK (an atlas solves many
// small charts); above it UMFPACK's dense fronts win.
constexpr int kKluMostRows = 30000;

// The hierarchy in float: it only preconditions, so its precision bounds the iterations, not the
// answer, and float halves the bytes of values a cycle streams. Gauss-Seidel smoothing needs no
// set-up and no memory, where ILU(0) factored every level.
using Matrix32 = amgcl::backend::builtin<float>::matrix;
using Hierarchy = amgcl::amg<amgcl::backend::builtin<float>, ReusedCoarsening<Matrix32>, amgcl::relaxation::gauss_seidel>;
using Krylov = amgcl::solver::bicgstab<amgcl::backend::builtin<double>>;

// A hierarchy as BiCGStab's preconditioner: its vectors in double, converted to float around a
// V-cycle.
class Preconditioner {
 public:
  Preconditioner(boost::shared_ptr<Matrix32> A, const Hierarchy::params& prm)
      : amg_(A, prm), f_(amgcl::backend::rows(*A)), x_(f_.size()) {}
  template <class Vec1, class Vec2>
  void apply(const Vec1& rhs, Vec2& x) const {
    for (size_t i = 0; i < f_.size(); ++i) f_[i] = float(rhs[i]);
    amg_.apply(f_, x_);
    for (size_t i = 0; i < f_.size(); ++i) x[i] = x_[i];
  }

 private:
  Hierarchy amg_;
  mutable amgcl::backend::numa_vector<float> f_, x_;
};

// Eigen's compressed rows as amgcl's matrix, without a copy: BiCGStab's products in double.
using MatrixView = amgcl::backend::crs<double, int, int>;
MatrixView view(Eigen::SparseMatrix<double, Eigen::RowMajor, int>& M) {
  MatrixView A;
  A.nrows = A.ncols = size_t(M.rows());
  A.nnz = size_t(M.nonZeros());
  A.ptr = M.outerIndexPtr();
  A.col = M.innerIndexPtr();
  A.val = M.valuePtr();
  A.own_data = false;
  return A;
}

// Position of entry (row, col) in the value array of a compressed row-major matrix.
int value_index(const Eigen::SparseMatrix<double, Eigen::RowMajor, int>& A, int row, int col) {
  const int* inner = A.innerIndexPtr();
  const int begin = A.outerIndexPtr()[row], end = A.outerIndexPtr()[row + 1];
  return int(std::lower_bound(inner + begin, inner + end, col) - inner);
}

double relative_residual(const Eigen::SparseMatrix<double, Eigen::RowMajor, int>& A, const Eigen::VectorXd& b,
                         const Eigen::VectorXd& x) {
  const double scale = b.norm();
  const double r = (b - A * x).norm();
  return scale > 0 ? r / scale : r;
}
}  // namespace

struct LaplacianSolver::Transfers {
  TransferRecord<Matrix32> record;
};

LaplacianSolver::~LaplacianSolver() = default;

LaplacianSolver::LaplacianSolver(const DiskMesh& disk, const SolverOptions& options, LuOrdering* ordering)
    : disk_(disk), options_(options), small_lu_(ordering) {
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

Eigen::MatrixXd LaplacianSolver::interior_rows(const Eigen::MatrixXd& uv) const {
  Eigen::MatrixXd x = Eigen::MatrixXd::Zero(matrix_.rows(), 2);
  if (uv.rows() != disk_.V.rows() || uv.cols() != 2 || !uv.allFinite()) return x;
  for (int i = 0; i < int(disk_.V.rows()); ++i)
    if (unknown_[size_t(i)] >= 0) x.row(unknown_[size_t(i)]) = uv.row(i);
  return x;
}

void LaplacianSolver::scatter(const Eigen::MatrixXd& x, Eigen::MatrixXd& uv) const {
  for (int i = 0; i < int(disk_.V.rows()); ++i)
    if (unknown_[size_t(i)] >= 0) uv.row(i) = x.row(unknown_[size_t(i)]);
}

// u and v with a hierarchy each, so that two threads can solve them at once (a hierarchy holds its
// cycle's work vectors), the second a twin of the first that shares its fine matrix, transfer and
// coarse operators: two threads cost the smoothers' and the coarsest level's set-up twice, not the
// hierarchy's memory.
bool LaplacianSolver::solve_amg(const Eigen::MatrixXd& rhs, Eigen::MatrixXd& x) {
  const int n = int(matrix_.rows());
  if (!transfers_) transfers_ = std::make_unique<Transfers>();
  TransferRecord<Matrix32>& record = transfers_->record;
  Hierarchy::params prm;
  prm.coarse_enough = kCoarseEnough;
  prm.coarsening.record = &record;
  Krylov::params krylov_prm;
  krylov_prm.tol = options_.tolerance;
  krylov_prm.maxiter = size_t(options_.max_iterations);
  const MatrixView A = view(matrix_);
  const bool two = options_.threads >= 2;
  std::unique_ptr<const Preconditioner> amg[2];
  Clock::time_point start = Clock::now();
  try {  // amgcl throws on a zero pivot or a breakdown; the direct solve takes over then
    const auto fine = boost::make_shared<Matrix32>(A);
    record.level = 0;
    record.twin = false;
    amg[0] = std::make_unique<const Preconditioner>(fine, prm);
    if (two) {
      record.level = 0;
      record.twin = true;
      amg[1] = std::make_unique<const Preconditioner>(fine, prm);
    }
  } catch (...) {
    record.coarse.clear();
    return false;
  }
  record.coarse.clear();  // the hierarchies hold them
  report_.seconds_setup = seconds_since(start);
  size_t iterations[2] = {0, 0};
  bool failed[2] = {false, false};
  auto solve_column = [&](int c) {
    try {
      const Krylov krylov(size_t(n), krylov_prm);
      // The columns in place (Eigen stores them contiguously): no copy of either.
      const auto b = boost::make_iterator_range(rhs.col(c).data(), rhs.col(c).data() + n);
      auto u = boost::make_iterator_range(x.col(c).data(), x.col(c).data() + n);
      double estimate = 0;
      boost::tie(iterations[c], estimate) = krylov(A, *amg[two ? c : 0], b, u);
    } catch (...) {
      failed[c] = true;
    }
  };
  // On two pool threads when one is idle (core/thread_pool.h), else one after the other.
  const Clock::time_point solve_start = Clock::now();
  if (two) {
    for_each_index(2, [&](int c, int) { solve_column(c); });
  } else {
    solve_column(0);
    solve_column(1);
  }
  report_.seconds_solve = seconds_since(solve_start);
  report_.iterations = int(std::max(iterations[0], iterations[1]));
  report_.relative_residual = std::max(relative_residual(matrix_, rhs.col(0), x.col(0)),
                                       relative_residual(matrix_, rhs.col(1), x.col(1)));
  return !failed[0] && !failed[1] && x.allFinite() && report_.iterations < options_.max_iterations &&
         report_.relative_residual <= options_.residual_accepted;
}

bool LaplacianSolver::solve_direct(const Eigen::MatrixXd& rhs, Eigen::MatrixXd& x) {
  Clock::time_point start = Clock::now();
  if (matrix_.rows() < kKluMostRows) {
    // The first pass's pivots serve the later ones (the weights change, the dominant diagonal
    // stays); where they fail or leave too large a residual, the pass is factored afresh, as
    // UMFPACK would, whose residual is taken as it is.
    for (const bool fresh : {false, true}) {
      const bool factored = small_lu_.factorize(matrix_, fresh);
      report_.seconds_setup += seconds_since(start);
      start = Clock::now();
      const bool solved = factored && small_lu_.solve(rhs, x) && x.allFinite();
      report_.seconds_solve += seconds_since(start);
      start = Clock::now();
      if (!solved) continue;
      report_.relative_residual = std::max(relative_residual(matrix_, rhs.col(0), x.col(0)),
                                           relative_residual(matrix_, rhs.col(1), x.col(1)));
      if (fresh || report_.relative_residual <= options_.residual_accepted) return true;
    }
    return false;
  }
  const Eigen::SparseMatrix<double> column_major = matrix_;  // UMFPACK takes compressed columns
  if (!analyzed_) {
    // METIS leaves less fill than the default AMD ordering on these meshes. The matrix is
    // diagonally dominant, so the factorization is accurate without iterative refinement (which
    // would triple the cost of a solve).
    lu_.umfpackControl()(UMFPACK_ORDERING) = UMFPACK_ORDERING_METIS;
    lu_.umfpackControl()(UMFPACK_IRSTEP) = 0;
    {
      const std::lock_guard<std::mutex> one_ordering_at_a_time(metis_lock());
      lu_.analyzePattern(column_major);
    }
    analyzed_ = true;
  }
  lu_.factorize(column_major);
  report_.seconds_setup += seconds_since(start);
  if (lu_.info() != Eigen::Success) return false;
  start = Clock::now();
  x = lu_.solve(rhs);
  report_.seconds_solve += seconds_since(start);
  if (lu_.info() != Eigen::Success || !x.allFinite()) return false;
  report_.relative_residual = std::max(relative_residual(matrix_, rhs.col(0), x.col(0)),
                                       relative_residual(matrix_, rhs.col(1), x.col(1)));
  return true;
}

bool LaplacianSolver::solve(const std::vector<double>& weights, const Eigen::MatrixXd& boundary_uv,
                            Eigen::MatrixXd& uv) {
  report_ = SolveReport();
  const Clock::time_point start = Clock::now();
  Eigen::MatrixXd x = interior_rows(uv);  // the previous pass: AMG's starting guess
  const Eigen::MatrixXd rhs = assemble(weights, boundary_uv, uv);
  report_.seconds_assembly = seconds_since(start);
  if (matrix_.rows() == 0) return true;  // every vertex is on the boundary
  report_.used = options_.method == LinearSolver::Amg && matrix_.rows() >= options_.amg_minimum_rows ? LinearSolver::Amg : LinearSolver::Direct;
  if (report_.used == LinearSolver::Amg) {
    // A system multigrid failed on once (zero-area triangles, extreme weights) fails again with the
    // next pass's weights: those passes go straight to the direct solve.
    if (!multigrid_failed_ && solve_amg(rhs, x)) {
      scatter(x, uv);
      return true;
    }
    multigrid_failed_ = true;
    report_.used = LinearSolver::Direct;
    report_.fell_back = true;
  }
  if (!solve_direct(rhs, x)) return false;
  scatter(x, uv);
  return true;
}

}  // namespace lowstretch
