// An optional step after the paper's method: minimizes the L2 stretch energy
// sum_T A3D(T) sigma(T)^2 directly, boundary fixed (or free: RefineOptions), never letting a UV
// triangle flip or collapse.
// sigma(T)^2 = |J^-1|_F^2 / 2, with J the 2x2 Jacobian of the map from the triangle (in a plane
// of its own) to UV, so the energy grows without bound as a triangle collapses: a step that keeps
// every triangle positive, and lowers the energy, keeps the map valid. Each step is a projected
// Newton step (per-triangle Hessians with their negative eigenvalues clamped, one CHOLMOD Cholesky
// factorization with the pattern analysed once), cut to 90% of the largest step that keeps every
// triangle above its least area (RefineOptions), then backtracked until the energy falls enough
// (Armijo).
#pragma once
#include <Eigen/Core>

#include "core/disk_mesh.h"

namespace lowstretch {

struct RefineOptions {
  // The work budget: at most this many steps, whatever they take, so that every run gives the
  // same map (nothing here depends on time or threads).
  int max_iterations = 25;  // Options::refine_iterations
  double relative_decrease = 1e-5;  // stop when an iteration lowers the energy by less
  // No UV triangle ends below this share of the map's UV area, or half its own area if that is
  // less: a sliver's stretch weighs next to nothing, and the energy alone shrinks its UV triangle
  // toward its near-zero 3D area, past what a texture resolves (an atlas's charts set it).
  double least_area_share = 0;
  // Boundary rows move too, and the energy is the stretch energy times the UV area (which no
  // scaling changes: the stretch energy alone falls as the map grows). The outline may then
  // cross itself: nothing here prevents that.
  bool free_boundary = false;
};

struct RefineReport {
  int iterations = 0;
  // sum_T A3D sigma^2 (unit-box mesh); with free_boundary, times the UV area over the first's.
  double energy_before = 0, energy_after = 0;
  double seconds = 0;  // measured and reported only: no step depends on it
  bool started = false;  // false when uv has a flipped or zero-area triangle: nothing to refine
};

// uv: n x 2 (compact rows of disk), every triangle positive; boundary rows are kept unless
// free_boundary. Returns the refined map (uv itself when it cannot start).
Eigen::MatrixXd refine_stretch(const DiskMesh& disk, const Eigen::MatrixXd& uv, const RefineOptions& options,
                               RefineReport& report);

}  // namespace lowstretch
