// The vocabulary of the method, shared by its steps: boundary shapes, initial weights, why a
// run stopped, and the metrics of one pass. At the bottom of the core: includes nothing of it.
#pragma once

#include "core/solver_options.h"

namespace lowstretch {

// Where the boundary loop goes: the paper's unit square, the circle, a free (natural) boundary,
// or positions the caller gives (Options::given_boundary), such as a rectangle of its own.
enum class BoundaryShape { Square, Circle, Natural, Given };
enum class InitialWeights { Floater, MeanValue, Harmonic };
enum class StopReason { StretchRose, MaxPasses };

// The paper's metrics of one parameterization (METHOD.md section 2). Stretch values are
// normalized so that an isometry up to scale gives 1; a flipped triangle makes them infinite.
struct PassMetrics {
  int pass = 0;
  double l2_stretch = 0, linf_stretch = 0;
  double edge_distortion = 0, angle_distortion = 0, area_distortion = 0;
  int flipped = 0;     // parameter triangles with negative area
  int degenerate = 0;  // parameter triangles with zero area
  double seconds = 0;  // wall time of this pass (weights, solve, metrics), split into:
  double seconds_assembly = 0;       // reweighting and filling the matrix
  double seconds_factorization = 0;  // numeric factorization or multigrid setup
  double seconds_solve = 0;          // solving for u and v
  double seconds_metrics = 0;        // stretch and distortion metrics
  LinearSolver solver = LinearSolver::Direct;  // what solved this pass
  bool solver_fell_back = false;     // multigrid did not converge: the direct solve took over
  int solver_iterations = 0;         // multigrid-preconditioned BiCGStab iterations (u or v, the larger)
  double solver_residual = 0;        // relative residual |A x - b| / |b| of the solution
};

const char* to_string(BoundaryShape shape);
const char* to_string(InitialWeights weights);
const char* to_string(StopReason reason);

}  // namespace lowstretch
