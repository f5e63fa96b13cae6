// The pass's linear solve: multigrid keeps the map the direct LU keeps, its residual is what it
// reports, and the direct solve takes over where multigrid cannot converge.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "core/boundary_map.h"
#include "core/disk_mesh.h"
#include "core/laplacian_solver.h"
#include "core/parameterize.h"
#include "core/ring_weights.h"
#include "generated_meshes.h"

using namespace lowstretch;

namespace {

struct PassRun {
  Result result;
  std::vector<Eigen::MatrixXd> uv;  // every pass's map
};

PassRun run(const testmesh::Mesh& m, BoundaryShape boundary, const SolverOptions& solver) {
  Options o;
  o.boundary = boundary;
  o.max_passes = 4;
  o.stop_when_stretch_rises = false;
  o.solver = solver;
  PassRun r;
  o.pass_uv = [&](int, const Eigen::MatrixXd& uv) { r.uv.push_back(uv); };
  r.result = parameterize(m.V, m.F, o);
  return r;
}

SolverOptions with(LinearSolver method) {
  SolverOptions s;
  s.method = method;
  return s;
}

// sum_j w_ij (u_j - u_i) over every interior vertex, relative to the largest term: the
// equations the solver was given, evaluated on its answer.
double largest_relative_imbalance(const DiskMesh& disk, const std::vector<double>& w, const Eigen::MatrixXd& uv) {
  double worst = 0;
  for (Eigen::Index i = 0; i < disk.V.rows(); ++i) {
    if (disk.is_boundary[size_t(i)]) continue;
    Eigen::RowVector2d sum = Eigen::RowVector2d::Zero();
    double scale = 0;
    for (int s = disk.ring_start[size_t(i)]; s < disk.ring_start[size_t(i) + 1]; ++s) {
      sum += w[size_t(s)] * (uv.row(disk.ring[size_t(s)]) - uv.row(i));
      scale += w[size_t(s)];
    }
    worst = std::max(worst, sum.cwiseAbs().maxCoeff() / scale);
  }
  return worst;
}

}  // namespace

// Only the kept map is an output: multigrid's passes may differ from the direct solves' in their
// last digits, but the map they keep is the direct chain's to 1e-5 in UV (a 25th of a texel at
// 4096^2) and 1e-6 relative in L2 stretch, from the same pass with the same flips.
TEST(LaplacianSolver, MultigridKeepsTheMapOfTheChainOfDirectSolves) {
  const testmesh::Mesh m = testmesh::tall_cap(60, 120);  // 7,201 vertices: above the direct-solve size
  for (BoundaryShape boundary : {BoundaryShape::Square, BoundaryShape::Circle}) {
    const PassRun amg = run(m, boundary, with(LinearSolver::Amg));
    const PassRun direct = run(m, boundary, with(LinearSolver::Direct));
    ASSERT_FALSE(amg.result.error) << message(amg.result.error);
    ASSERT_FALSE(direct.result.error) << message(direct.result.error);
    ASSERT_EQ(amg.uv.size(), 5u);
    ASSERT_EQ(direct.uv.size(), 5u);
    for (size_t p = 0; p < amg.uv.size(); ++p) {
      const PassMetrics& a = amg.result.passes[p];
      EXPECT_EQ(a.solver, LinearSolver::Amg) << "pass " << p;
      EXPECT_FALSE(a.solver_fell_back) << "pass " << p;
      EXPECT_GT(a.solver_iterations, 0) << "pass " << p;
      EXPECT_LE(a.solver_residual, SolverOptions().residual_accepted) << "pass " << p;
      EXPECT_EQ(direct.result.passes[p].solver, LinearSolver::Direct);
    }
    const int kept = amg.result.chosen_pass;
    ASSERT_EQ(kept, direct.result.chosen_pass) << to_string(boundary);
    EXPECT_LT((amg.result.uv - direct.result.uv).cwiseAbs().maxCoeff(), 1e-5) << to_string(boundary);
    const double l2 = direct.result.passes[size_t(kept)].l2_stretch;
    EXPECT_LT(std::abs(amg.result.passes[size_t(kept)].l2_stretch - l2) / l2, 1e-6) << to_string(boundary);
    EXPECT_EQ(amg.result.passes[size_t(kept)].flipped, direct.result.passes[size_t(kept)].flipped);
  }
}

TEST(LaplacianSolver, ReportedResidualIsTheResidualOfTheSolution) {
  const testmesh::Mesh m = testmesh::tall_cap(60, 120);  // 7,201 vertices: above the direct-solve size
  DiskMesh disk;
  ASSERT_FALSE(make_disk_mesh(m.V, m.F, disk));
  int fallbacks = 0;
  const std::vector<double> w = initial_weights(disk, InitialWeights::Floater, fallbacks);
  ASSERT_EQ(fallbacks, 0);
  for (LinearSolver method : {LinearSolver::Amg, LinearSolver::Direct}) {
    LaplacianSolver solver(disk, with(method));
    Eigen::MatrixXd uv;
    ASSERT_TRUE(solver.solve(w, circle_boundary(disk), uv));
    EXPECT_EQ(solver.report().used, method);
    const double imbalance = largest_relative_imbalance(disk, w, uv);
    EXPECT_LT(imbalance, 1e-6) << to_string(method);
    EXPECT_LE(solver.report().relative_residual, SolverOptions().residual_accepted) << to_string(method);
    if (method == LinearSolver::Direct) EXPECT_LT(imbalance, 1e-11);
  }
}

TEST(LaplacianSolver, DirectSolveTakesOverWhereMultigridDoesNotConverge) {
  const testmesh::Mesh m = testmesh::tall_cap(60, 120);  // 7,201 vertices: above the direct-solve size
  SolverOptions starved = with(LinearSolver::Amg);
  starved.max_iterations = 1;  // no pass converges in one BiCGStab iteration at 1e-8
  const PassRun amg = run(m, BoundaryShape::Square, starved);
  const PassRun direct = run(m, BoundaryShape::Square, with(LinearSolver::Direct));
  ASSERT_FALSE(amg.result.error) << message(amg.result.error);
  for (size_t p = 0; p < amg.uv.size(); ++p) {
    EXPECT_TRUE(amg.result.passes[p].solver_fell_back) << "pass " << p;
    EXPECT_EQ(amg.result.passes[p].solver, LinearSolver::Direct) << "pass " << p;
    EXPECT_LT((amg.uv[p] - direct.uv[p]).cwiseAbs().maxCoeff(), 1e-12) << "pass " << p;
    // Multigrid ran its one iteration in U0 only: the later passes are not tried on it again.
    EXPECT_EQ(amg.result.passes[p].solver_iterations, p == 0 ? 1 : 0) << "pass " << p;
  }
  EXPECT_EQ(amg.result.passes.size(), 5u);  // every one of the 5 passes fell back (checked above)
  EXPECT_GT(amg.result.notes.size(), direct.result.notes.size()) << "a note says the multigrid fell back";
}

TEST(LaplacianSolver, SmallSystemsAreSolvedDirectly) {
  const testmesh::Mesh m = testmesh::grid(20);
  const PassRun r = run(m, BoundaryShape::Square, with(LinearSolver::Amg));
  ASSERT_FALSE(r.result.error) << message(r.result.error);
  for (const PassMetrics& p : r.result.passes) {
    EXPECT_EQ(p.solver, LinearSolver::Direct);
    EXPECT_FALSE(p.solver_fell_back);
  }
  // Below the threshold multigrid still solves when asked to.
  SolverOptions small = with(LinearSolver::Amg);
  small.amg_minimum_rows = 1;
  const PassRun forced = run(m, BoundaryShape::Square, small);
  const PassRun direct = run(m, BoundaryShape::Square, with(LinearSolver::Direct));
  for (size_t p = 0; p < forced.uv.size(); ++p) {
    EXPECT_EQ(forced.result.passes[p].solver, LinearSolver::Amg);
    EXPECT_LT((forced.uv[p] - direct.uv[p]).cwiseAbs().maxCoeff(), 1e-6);
  }
}

TEST(LaplacianSolver, OutOfRangeSettingsAreRejected) {
  const testmesh::Mesh m = testmesh::grid(5);
  SolverOptions bad;
  bad.tolerance = 0;
  Options o;
  o.solver = bad;
  const Result r = parameterize(m.V, m.F, o);
  EXPECT_EQ(r.error.code, ErrorCode::InvalidOption);
}

// u then v with one hierarchy (as the atlas solves its charts) gives the solution of u and v on
// two threads, each with a hierarchy of its own: the same iteration on the same matrix.
TEST(LaplacianSolver, OneHierarchyForBothColumnsSolvesTheSame) {
  const testmesh::Mesh m = testmesh::tall_cap(60, 120);  // 7,201 vertices: above the direct-solve size
  SolverOptions sequential = with(LinearSolver::Amg);
  sequential.threads = 1;
  const PassRun one = run(m, BoundaryShape::Square, sequential);
  const PassRun two = run(m, BoundaryShape::Square, with(LinearSolver::Amg));
  ASSERT_FALSE(one.result.error) << message(one.result.error);
  ASSERT_EQ(one.uv.size(), two.uv.size());
  for (size_t p = 0; p < one.uv.size(); ++p) {
    EXPECT_EQ(one.result.passes[p].solver, LinearSolver::Amg) << "pass " << p;
    EXPECT_FALSE(one.result.passes[p].solver_fell_back) << "pass " << p;
    EXPECT_EQ(one.uv[p], two.uv[p]) << "pass " << p;
  }
}
