// How each pass's linear system is solved (laplacian_solver.h).
#pragma once

namespace lowstretch {

enum class LinearSolver {
  Amg,    // algebraic multigrid + BiCGStab; the direct solve for small systems and for a pass
          // where it does not converge
  Direct  // sparse LU (UMFPACK)
};

struct SolverOptions {
  LinearSolver method = LinearSolver::Amg;
  // Relative residual |A x - b| / |b| the Krylov iteration stops at (about 1e-7 in UV on the
  // shared disks). Its residual is a recurrence: the true one is checked, and above
  // residual_accepted the direct solve takes over, as it does after max_iterations.
  double tolerance = 1e-8;
  double residual_accepted = 1e-7;
  int max_iterations = 100;
  // A pass first reuses an earlier pass's hierarchy (the matrix differs only in values), and
  // builds a new one only if that took more than this factor times (plus 2) the iterations
  // right after the last build.
  double stale_iteration_factor = 1.5;
  // Smaller systems are solved directly: amgcl would solve them on one level by its own dense LU
  // (its coarse_enough, 3000), slower than UMFPACK.
  int amg_minimum_rows = 3000;
};

inline const char* to_string(LinearSolver solver) { return solver == LinearSolver::Amg ? "amg" : "direct"; }

}  // namespace lowstretch
