// Low-stretch parameterization of a disk-like triangle mesh (Yoshizawa, Belyaev, Seidel 2004,
// "A fast and simple stretch-minimizing mesh parameterization"):
//   U0 from shape-preserving weights, then w_ij <- w_ij / sigma_j^eta and solve again,
//   keeping the pass of lowest L2 stretch.
#pragma once
#include <Eigen/Core>
#include <functional>
#include <string>
#include <vector>

#include "core/errors.h"
#include "core/method_types.h"

namespace lowstretch {

struct DiskMesh;
struct PreparedDisk;

constexpr int kMostPasses = 1000;
constexpr int kMostRefineIterations = 10000;

struct Options {
  BoundaryShape boundary = BoundaryShape::Square;
  // With Given: #V x 2, the UV of every boundary vertex (other rows are not read). Positions on
  // a convex polygon keep Floater's guarantee that no triangle flips.
  Eigen::MatrixXd given_boundary;
  InitialWeights weights = InitialWeights::Floater;
  double exponent = 1.0;  // eta in (0, 1]: weights are divided by sigma_j^eta each pass
  int max_passes = 10;    // 0: U0 only; 1: U0 and U1; at most kMostPasses
  bool stop_when_stretch_rises = true;  // false forces all max_passes (benchmarks)
  SolverOptions solver;  // how each pass is solved (solver_options.h)
  // After the kept pass, minimize the L2 stretch directly (refine_stretch.h), for at most
  // refine_iterations steps: a work budget, never a time one, so that every run gives the same map;
  // a note says what it gained.
  bool refine = false;
  int refine_iterations = 25;  // 1 to kMostRefineIterations; about what 8.5 times the passes' time reached

  double refine_least_area = 0;  // RefineOptions::least_area_share
  // With the natural boundary, refining moves the boundary too (RefineOptions::free_boundary):
  // less stretch, but the outline may then cross itself, which the caller must check.
  bool refine_moves_boundary = false;
  // Called with a fraction in [0, 1] and the current stage; return false to cancel the run.
  std::function<bool(double fraction, const char* stage)> progress;
  // Called after every pass with that pass's UV (rows as in V, unused rows 0), for callers that
  // measure passes their own way (over some of the faces only, say).
  std::function<void(int pass, const Eigen::MatrixXd& uv)> pass_uv;
  // false: each pass measures its stretch and flips only, not the edge, angle and area distortions
  // (callers that measure passes their own way need none of them).
  bool measure_distortions = true;
};

struct Result {
  Error error;  // error.code != None: nothing below is filled
  // #V x 2, in [0,1]^2; rows of vertices that no face uses are 0.
  Eigen::MatrixXd uv;
  // Per-vertex stretch sigma_i and per-face stretch sigma(T) of the returned pass, normalized
  // like PassMetrics (0 for unreferenced vertices; infinity for a flipped face).
  Eigen::VectorXd vertex_stretch, face_stretch;
  std::vector<PassMetrics> passes;  // every pass computed, including a rejected last one
  int chosen_pass = 0;              // index into passes of the returned parameterization
  StopReason stop_reason = StopReason::MaxPasses;
  double seconds_total = 0;
  std::vector<std::string> notes;   // things a user should know (moved corners, degenerate faces)
};

// V: #V x 3 vertex positions; F: #F x 3 vertex indices of counter-clockwise triangles.
// Vertices that no face uses are ignored (their coordinates may be anything).
Result parameterize(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const Options& options = {});

// The same on a disk that make_disk_mesh built (from V with vertex_rows rows): for a caller that
// needs the disk's boundary loop first, to give its positions.
Result parameterize(const DiskMesh& disk, Eigen::Index vertex_rows, const Options& options);

// The same with the disk's initial weights prepared once (prepared_disk.h); where options.weights
// asks for another kind, that kind is computed.
Result parameterize(const PreparedDisk& prepared, Eigen::Index vertex_rows, const Options& options);

}  // namespace lowstretch
