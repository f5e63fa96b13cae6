// The linear system of one pass: for every interior vertex i, sum_j w_ij (u_j - u_i) = 0 with
// the boundary fixed. Every pass has the same sparsity pattern, so the solver builds it and
// runs the symbolic analysis once; a pass only refills the values and factorizes.
#pragma once
#include <Eigen/Core>
#include <Eigen/Sparse>
#include <Eigen/UmfPackSupport>
#include <memory>
#include <vector>

#include "disk_mesh.h"

namespace lowstretch {

class LaplacianSolver {
 public:
  explicit LaplacianSolver(const DiskMesh& disk);

  // weights: aligned with disk.ring; boundary_uv: rows follow disk.boundary. Returns UV for
  // every vertex of the disk, or false if the factorization fails.
  bool solve(const std::vector<double>& weights, const Eigen::MatrixXd& boundary_uv, Eigen::MatrixXd& uv);

  // The steps of solve(), for studies of other solvers (tests/bench/reuse_study.cpp): fill the
  // system (matrix() and the returned right-hand sides, one row per interior vertex) and put the
  // boundary into uv; then write a solution's rows into uv.
  Eigen::MatrixXd assemble(const std::vector<double>& weights, const Eigen::MatrixXd& boundary_uv, Eigen::MatrixXd& uv);
  const Eigen::SparseMatrix<double>& matrix() const { return matrix_; }
  void scatter(const Eigen::MatrixXd& x, Eigen::MatrixXd& uv) const;

  // Seconds the last solve() spent filling the matrix, factorizing and solving.
  double seconds_assembly = 0, seconds_factorization = 0, seconds_solve = 0;

 private:
  const DiskMesh& disk_;
  std::vector<int> unknown_;             // compact vertex -> row of the system, -1 on the boundary
  Eigen::SparseMatrix<double> matrix_;   // column-major, as UMFPACK takes it
  std::vector<int> slot_to_value_;       // ring slot -> index in matrix_.valuePtr(), -1 for boundary
  std::vector<int> diagonal_value_;      // row -> index of its diagonal in valuePtr()
  Eigen::UmfPackLU<Eigen::SparseMatrix<double>> lu_;
  bool analyzed_ = false;
};

}  // namespace lowstretch
