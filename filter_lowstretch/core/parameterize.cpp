#include "core/parameterize.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <utility>

#include "core/boundary_map.h"
#include "core/disk_mesh.h"
#include "core/laplacian_solver.h"
#include "core/natural_boundary.h"
#include "core/prepared_disk.h"
#include "core/refine_stretch.h"
#include "core/ring_weights.h"
#include "core/stretch.h"

namespace lowstretch {

namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

Error check_options(const Options& o) {
  if (!(o.exponent > 0 && o.exponent <= 1))
    return {ErrorCode::InvalidOption, 0, "must be in (0, 1], got " + number_text(o.exponent), "exponent"};
  if (o.max_passes < 0 || o.max_passes > kMostPasses)
    return {ErrorCode::InvalidOption, 0, "must be from 0 to " + std::to_string(kMostPasses) + ", got " +
                                             std::to_string(o.max_passes), "max_passes"};
  if (o.refine_iterations < 1 || o.refine_iterations > kMostRefineIterations)
    return {ErrorCode::InvalidOption, 0, "must be from 1 to " + std::to_string(kMostRefineIterations) + ", got " +
                                             std::to_string(o.refine_iterations), "refine_iterations"};
  const SolverOptions& s = o.solver;
  if (!(s.tolerance > 0 && s.tolerance < 1 && s.residual_accepted >= s.tolerance && s.max_iterations > 0 &&
        s.amg_minimum_rows >= 1))
    return {ErrorCode::InvalidOption, 0, "are out of range (tolerance in (0, 1), accepted residual at least the "
                                         "tolerance, at least one iteration)", "solver settings"};
  return {};
}

// Passes are ranked by (flipped + degenerate triangles, L2 stretch over the valid triangles):
// with a convex boundary there are none, and the rank is the paper's E_s.
std::pair<int, double> rank(const FaceStretch& s) {
  return {s.flipped + s.degenerate, l2_stretch(s, true)};
}

// Given positions, checked: one finite UV per vertex row, read at the boundary vertices.
Error given_positions(const DiskMesh& disk, const Eigen::MatrixXd& given, Eigen::Index vertex_rows,
                      Eigen::MatrixXd& boundary_uv) {
  if (given.rows() != vertex_rows || given.cols() != 2)
    return {ErrorCode::InvalidOption, 0, "must have one row of two coordinates per vertex, got " +
                                             std::to_string(given.rows()) + " x " + std::to_string(given.cols()),
            "given_boundary"};
  boundary_uv.resize(Eigen::Index(disk.boundary.size()), 2);
  for (size_t i = 0; i < disk.boundary.size(); ++i) {
    boundary_uv.row(Eigen::Index(i)) = given.row(disk.input_vertex[size_t(disk.boundary[i])]);
    if (!boundary_uv.row(Eigen::Index(i)).allFinite())
      return {ErrorCode::InvalidOption, 0, "must be finite at every boundary vertex", "given_boundary"};
  }
  return {};
}

Error boundary_positions(const DiskMesh& disk, const Options& options, Eigen::Index vertex_rows,
                         Eigen::MatrixXd& boundary_uv, std::vector<std::string>& notes) {
  switch (options.boundary) {
    case BoundaryShape::Circle: boundary_uv = circle_boundary(disk); return {};
    case BoundaryShape::Natural: return natural_boundary(disk, boundary_uv);
    case BoundaryShape::Square: boundary_uv = paper_square_boundary(disk, notes); return {};
    case BoundaryShape::Given: return given_positions(disk, options.given_boundary, vertex_rows, boundary_uv);
  }
  return {};
}

// Negative (harmonic) weights can put interior vertices outside the boundary's hull and so
// outside [0,1]^2: scale the whole map uniformly back in. Returns whether it had to.
bool fit_into_unit_square(Eigen::MatrixXd& uv) {
  const Eigen::RowVector2d low = uv.colwise().minCoeff(), high = uv.colwise().maxCoeff();
  if (low.minCoeff() >= 0 && high.maxCoeff() <= 1) return false;
  const double extent = (high - low).maxCoeff();
  uv = ((uv.rowwise() - low) / (extent > 0 ? extent : 1)).eval();
  return true;
}

// Compact disk rows back to the input's rows; unreferenced vertices get zeros.
Eigen::MatrixXd input_rows(const DiskMesh& disk, const Eigen::MatrixXd& uv, Eigen::Index rows) {
  Eigen::MatrixXd out = Eigen::MatrixXd::Zero(rows, 2);
  for (size_t i = 0; i < disk.input_vertex.size(); ++i) out.row(disk.input_vertex[i]) = uv.row(Eigen::Index(i));
  return out;
}

// The metrics of one solved pass, with the time of each phase and what the solver did (the
// caller adds the reweighting time and the pass number).
// Without a reference, the stretch metrics only (Options::measure_distortions).
PassMetrics measure_pass(const DiskMesh& disk, const Eigen::MatrixXd& uv, const FaceStretch& stretch,
                         const SurfaceReference* reference, const SolveReport& solved) {
  const Clock::time_point start = Clock::now();
  PassMetrics m = reference ? measure(disk.F, disk.edges, uv, stretch, *reference) : measure_stretch(stretch);
  m.seconds_metrics = seconds_since(start);
  m.seconds_assembly = solved.seconds_assembly;
  m.seconds_factorization = solved.seconds_setup;
  m.seconds_solve = solved.seconds_solve;
  m.solver = solved.used;
  m.solver_fell_back = solved.fell_back;
  m.solver_iterations = solved.iterations;
  m.solver_residual = solved.relative_residual;
  return m;
}

// Multigrid is not tried again after the pass it failed in (laplacian_solver.h).
void note_solver_fallbacks(Result& result) {
  const auto first = std::find_if(result.passes.begin(), result.passes.end(), [](const PassMetrics& p) { return p.solver_fell_back; });
  if (first == result.passes.end()) return;
  const long pass = long(first - result.passes.begin()), after = long(result.passes.size()) - pass - 1;
  result.notes.push_back("multigrid did not converge in pass " + std::to_string(pass) + (pass == 0 ? " (U0)" : "") +
                         ": the sparse LU solved it" + (after == 1 ? " and the pass after it" : after > 1 ? " and the " + std::to_string(after) + " passes after it" : ""));
}

// The kept pass in the caller's rows: UV (scaled into [0,1]^2 if it left it), vertex and face
// stretch.
void keep_pass(const DiskMesh& disk, Eigen::MatrixXd uv, const FaceStretch& stretch, Eigen::Index vertex_rows,
               Result& result) {
  if (fit_into_unit_square(uv))
    result.notes.push_back("negative weights put vertices outside the boundary: the map was scaled into [0,1]^2");
  result.uv = input_rows(disk, uv, vertex_rows);
  const int n = int(disk.V.rows());
  result.vertex_stretch = Eigen::VectorXd::Zero(vertex_rows);
  const Eigen::VectorXd sigma = vertex_stretch(disk.F, n, stretch);
  for (int i = 0; i < n; ++i) result.vertex_stretch(disk.input_vertex[size_t(i)]) = sigma(i);
  result.face_stretch.resize(disk.F.rows());
  const double inf = std::numeric_limits<double>::infinity();
  for (Eigen::Index f = 0; f < disk.F.rows(); ++f)
    result.face_stretch(f) = stretch.valid(f) ? stretch.normalization * stretch.sigma(f) : inf;
}

// Lowers the kept map's L2 stretch directly (refine_stretch.h) within method.refine_iterations
// steps (counted, not timed: the map is the same every run); notes the gain.
void refine(const DiskMesh& disk, const Options& method, Eigen::MatrixXd& uv, FaceStretch& stretch, Result& result) {
  RefineOptions options;
  options.max_iterations = method.refine_iterations;
  options.least_area_share = method.refine_least_area;
  options.free_boundary = method.refine_moves_boundary && method.boundary == BoundaryShape::Natural;
  RefineReport report;
  const Eigen::MatrixXd refined = refine_stretch(disk, uv, options, report);
  if (!report.started) {
    result.notes.push_back("not refined: the kept map has flipped or zero-area triangles");
    return;
  }
  const FaceStretch refined_stretch = face_stretch(disk.V, disk.F, refined);
  const double before = l2_stretch(stretch), after = l2_stretch(refined_stretch);
  if (!(after < before)) return;
  result.notes.push_back("refined: L2 stretch " + number_text(before) + " -> " + number_text(after) + " in " +
                         std::to_string(report.iterations) + " iterations, " + number_text(report.seconds) + " s");
  uv = refined;
  stretch = refined_stretch;
}

Result failed(Error error) {
  Result result;
  result.error = std::move(error);
  return result;
}

// The initial weights (ring_weights.h), prepared or computed here, with a note where a degenerate
// one-ring got uniform ones.
std::vector<double> noted_initial_weights(const DiskMesh& disk, const PreparedDisk* prepared, InitialWeights kind,
                                          std::vector<std::string>& notes) {
  int fallbacks = 0;
  std::vector<double> weights;
  if (prepared && prepared->kind == kind) {
    weights = prepared->weights;
    fallbacks = prepared->uniform_fallbacks;
  } else {
    weights = initial_weights(disk, kind, fallbacks);
  }
  if (fallbacks > 0)
    notes.push_back(std::to_string(fallbacks) +
                    " interior vertices have a degenerate one-ring (zero-length edges or zero-area "
                    "triangles): uniform weights used there");
  return weights;
}

// The method on a disk, with its initial weights as prepared where they are (may be null).
Result parameterize_disk(const DiskMesh& disk, const PreparedDisk* prepared, Eigen::Index vertex_rows, const Options& options) {
  const Clock::time_point start = Clock::now();
  Result result;
  auto report = [&](double fraction, const char* stage) {
    return !options.progress || options.progress(fraction, stage);
  };
  if (Error e = check_options(options)) return failed(e);
  if (!report(0.02, "boundary")) return failed({ErrorCode::Cancelled, 0, ""});
  Eigen::MatrixXd boundary_uv;
  if (Error e = boundary_positions(disk, options, vertex_rows, boundary_uv, result.notes)) return failed(e);

  std::vector<double> weights = noted_initial_weights(disk, prepared, options.weights, result.notes);

  LaplacianSolver solver(disk, options.solver, prepared ? prepared->ordering.get() : nullptr);
  SurfaceReference reference;
  if (options.measure_distortions) reference = surface_reference(disk.V, disk.F, disk.edges);
  const int n = int(disk.V.rows());
  Eigen::MatrixXd uv, best_uv;
  FaceStretch stretch, best_stretch;
  std::pair<int, double> best_rank;
  for (int pass = 0; pass <= options.max_passes; ++pass) {
    const Clock::time_point pass_start = Clock::now();
    if (!report(0.05 + 0.9 * pass / (options.max_passes + 1.0), pass == 0 ? "initial parameterization" : "stretch pass"))
      return failed({ErrorCode::Cancelled, 0, ""});
    Clock::time_point phase = Clock::now();
    if (pass > 0) reweight(disk, vertex_stretch(disk.F, n, stretch), options.exponent, weights);
    const double reweighting = seconds_since(phase);
    if (!solver.solve(weights, boundary_uv, uv) || !uv.allFinite())
      return failed({ErrorCode::SolverFailed, pass, "singular or non-finite system"});
    stretch = face_stretch(disk.V, disk.F, uv);
    PassMetrics metrics = measure_pass(disk, uv, stretch, options.measure_distortions ? &reference : nullptr, solver.report());
    metrics.pass = pass;
    metrics.seconds_assembly += reweighting;
    metrics.seconds = seconds_since(pass_start);
    result.passes.push_back(metrics);
    if (options.pass_uv) options.pass_uv(pass, input_rows(disk, uv, vertex_rows));

    const std::pair<int, double> this_rank = rank(stretch);
    if (pass == 0 || this_rank < best_rank) {
      result.chosen_pass = pass;
      best_rank = this_rank;
      best_uv = uv;
      best_stretch = stretch;
    } else if (options.stop_when_stretch_rises) {
      result.stop_reason = StopReason::StretchRose;
      break;
    }
  }

  note_solver_fallbacks(result);
  if (options.refine)
    refine(disk, options, best_uv, best_stretch, result);
  keep_pass(disk, best_uv, best_stretch, vertex_rows, result);
  result.seconds_total = seconds_since(start);
  report(1.0, "done");
  return result;
}

}  // namespace

Result parameterize(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const Options& options) {
  const Clock::time_point start = Clock::now();
  if (Error e = check_options(options)) return failed(e);
  DiskMesh disk;
  if (Error e = make_disk_mesh(V, F, disk)) return failed(e);
  Result result = parameterize(disk, V.rows(), options);
  result.seconds_total = seconds_since(start);
  return result;
}

Result parameterize(const DiskMesh& disk, Eigen::Index vertex_rows, const Options& options) {
  return parameterize_disk(disk, nullptr, vertex_rows, options);
}

Result parameterize(const PreparedDisk& prepared, Eigen::Index vertex_rows, const Options& options) {
  return parameterize_disk(prepared.disk, &prepared, vertex_rows, options);
}

}  // namespace lowstretch
