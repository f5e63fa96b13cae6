// The linear system of one pass: for every interior vertex i, sum_j w_ij (u_j - u_i) = 0 with
// the boundary fixed. Every pass has the same sparsity pattern, so the solver builds it once; a
// pass only refills the values.
//
// Two ways to solve it (SolverOptions in solver_options.h):
// - Amg: algebraic multigrid (amgcl: smoothed aggregation, Gauss-Seidel smoothing, in float)
//   preconditioning BiCGStab (in double), warm-started from the previous pass's solution, u and v
//   on two threads (or one after the other, SolverOptions::threads). One set of coarse operators
//   serves both; a later pass rebuilds them from the values only (reused_coarsening.h). The matrix
//   is an irreducibly diagonally dominant M-matrix for positive weights, the ideal case for AMG,
//   and it needs no fill, so time and memory grow linearly with the mesh.
// - Direct: sparse LU, symbolic analysis once: KLU for small systems (small_system_lu.h),
//   UMFPACK with METIS ordering for large ones.
// An AMG solve that does not converge, or whose true residual is too large, falls back to the
// direct solve for that pass and every later one; each pass's SolveReport says so. Small systems
// are always solved directly.
#pragma once
#include <Eigen/Core>
#include <Eigen/Sparse>
#include <Eigen/UmfPackSupport>
#include <memory>
#include <vector>

#include "core/disk_mesh.h"
#include "core/small_system_lu.h"
#include "core/solver_options.h"

namespace lowstretch {

// What one solve() did, for the pass's metrics.
struct SolveReport {
  LinearSolver used = LinearSolver::Direct;  // Direct also when AMG fell back
  bool fell_back = false;                    // AMG was asked for but did not converge, in this pass or an earlier one
  int iterations = 0;                        // Krylov iterations, the larger of u and v
  double relative_residual = 0;              // max over u, v of |A x - b| / |b|
  double seconds_assembly = 0, seconds_setup = 0, seconds_solve = 0;
};

class LaplacianSolver {
 public:
  // ordering: the LU's ordering of this disk's system, shared with other solvers of the same disk
  // (prepared_disk.h), or null for one of its own.
  LaplacianSolver(const DiskMesh& disk, const SolverOptions& options, LuOrdering* ordering = nullptr);
  ~LaplacianSolver();

  // weights: aligned with disk.ring; boundary_uv: rows follow disk.boundary. uv: on entry the
  // previous pass's solution (the AMG's starting guess) or empty; on return UV for every vertex
  // of the disk. Returns false if no solver could solve the system.
  bool solve(const std::vector<double>& weights, const Eigen::MatrixXd& boundary_uv, Eigen::MatrixXd& uv);
  const SolveReport& report() const { return report_; }


 private:
  using RowMatrix = Eigen::SparseMatrix<double, Eigen::RowMajor, int>;
  Eigen::MatrixXd assemble(const std::vector<double>& weights, const Eigen::MatrixXd& boundary_uv, Eigen::MatrixXd& uv);
  Eigen::MatrixXd interior_rows(const Eigen::MatrixXd& uv) const;
  void scatter(const Eigen::MatrixXd& x, Eigen::MatrixXd& uv) const;
  bool solve_amg(const Eigen::MatrixXd& rhs, Eigen::MatrixXd& x);
  bool solve_direct(const Eigen::MatrixXd& rhs, Eigen::MatrixXd& x);

  const DiskMesh& disk_;
  const SolverOptions options_;
  std::vector<int> unknown_;        // compact vertex -> row of the system, -1 on the boundary
  RowMatrix matrix_;                // row r: the equation of one interior vertex
  std::vector<int> slot_to_value_;  // ring slot -> index in matrix_.valuePtr(), -1 for boundary
  std::vector<int> diagonal_value_; // row -> index of its diagonal in valuePtr()
  Eigen::UmfPackLU<Eigen::SparseMatrix<double>> lu_;  // from kKluMostRows rows
  SmallSystemLu small_lu_;                            // below
  bool analyzed_ = false;
  struct Transfers;                      // the multigrid's P and R per level, kept across passes
  std::unique_ptr<Transfers> transfers_;
  SolveReport report_;
  bool multigrid_failed_ = false;  // on an earlier pass: later passes are solved directly
};

}  // namespace lowstretch
