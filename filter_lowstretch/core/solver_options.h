// How each pass's linear system is solved (laplacian_solver.h).
#pragma once

namespace lowstretch {

enum class LinearSolver {
  Amg,    // algebraic multigrid + BiCGStab; the direct solve for small systems and for a pass
          // where it does not converge
  Direct  // sparse LU (KLU for small systems, UMFPACK)
};

struct SolverOptions {
  LinearSolver method = LinearSolver::Amg;
  // Relative residual |A x - b| / |b| the Krylov iteration stops at. Only the kept pass's map is
  // an output, and the earlier passes only give it its weights: at this residual the kept map
  // stays within a 25th of a texel at 4096^2 (1e-5) of the chain of direct solves, and its L2
  // stretch within 1e-6 relative (lowstretch_benchmark measures both); a tighter residual costs
  // iterations in every pass. The residual is a recurrence: the true one is checked, and above
  // residual_accepted the direct solve takes over, as it does after max_iterations (several
  // times what a pass needs).
  double tolerance = 1e-8;
  double residual_accepted = 1e-7;
  int max_iterations = 50;
  // Smaller systems are solved directly: amgcl would solve them on one level by its own dense LU
  // (its coarse_enough, 3000), slower than a sparse LU.
  int amg_minimum_rows = 3000;
  // Cores one solve may use: 2 solves u and v each on a thread (the second hierarchy a twin that
  // shares the first's operators); 1 solves u then v with one hierarchy (for callers that keep the
  // cores busy).
  int threads = 2;
};

inline const char* to_string(LinearSolver solver) { return solver == LinearSolver::Amg ? "amg" : "direct"; }

}  // namespace lowstretch
