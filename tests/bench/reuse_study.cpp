// What reusing a factorization across passes buys (issue 5), measured rather than assumed.
// Runs the core's pass loop (square boundary, Floater, exponent 1) and, for every pass after the
// first, solves that pass's system three ways, timing each:
//   refactor   UMFPACK numeric factorization of this pass (symbolic analysis reused) + solve,
//              which is what the core does;
//   LU(0)      GMRES preconditioned by the factorization of pass 0, warm-started from the
//              previous pass;
//   LU(k-1)    GMRES preconditioned by the factorization of the previous pass.
// It prints GMRES iterations, seconds and the largest UV difference from the refactor solution.
//
// usage: lowstretch_reuse_study [--passes N] [--tolerance T] MESH...
#include <Eigen/Sparse>
#include <Eigen/UmfPackSupport>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "core/boundary_map.h"
#include "core/disk_mesh.h"
#include "core/laplacian_solver.h"
#include "core/ring_weights.h"
#include "core/square_corners.h"
#include "core/stretch.h"
#include "mesh_io.h"
#include "vcg/mesh_arrays.h"

using namespace lowstretch;
using Clock = std::chrono::steady_clock;
using SparseMatrix = Eigen::SparseMatrix<double>;
using LU = Eigen::UmfPackLU<SparseMatrix>;

namespace {

double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

// One pass's system, as the core's solver assembles it.
struct PassSystem {
  SparseMatrix A;
  Eigen::MatrixXd rhs;
};

// Right-preconditioned GMRES without restart on one column: x is the start and the result.
// Stops when |b - A x| <= tolerance |b|; returns the number of iterations.
int gmres(const SparseMatrix& A, const LU& preconditioner, const Eigen::VectorXd& b, Eigen::VectorXd& x,
          double tolerance, int max_iterations) {
  const Eigen::Index n = b.size();
  const Eigen::VectorXd r = b - A * x;
  const double beta = r.norm(), target = tolerance * b.norm();
  if (beta <= target) return 0;
  Eigen::MatrixXd basis(n, max_iterations + 1), H = Eigen::MatrixXd::Zero(max_iterations + 1, max_iterations);
  Eigen::VectorXd g = Eigen::VectorXd::Zero(max_iterations + 1);
  std::vector<Eigen::JacobiRotation<double>> rotation(static_cast<size_t>(max_iterations));
  basis.col(0) = r / beta;
  g(0) = beta;
  int j = 0;
  while (j < max_iterations) {
    Eigen::VectorXd w = A * preconditioner.solve(Eigen::VectorXd(basis.col(j)));
    for (int i = 0; i <= j; ++i) {
      H(i, j) = basis.col(i).dot(w);
      w -= H(i, j) * basis.col(i);
    }
    H(j + 1, j) = w.norm();
    basis.col(j + 1) = w / H(j + 1, j);
    for (int i = 0; i < j; ++i) H.col(j).applyOnTheLeft(i, i + 1, rotation[size_t(i)].adjoint());
    rotation[size_t(j)].makeGivens(H(j, j), H(j + 1, j));
    H.col(j).applyOnTheLeft(j, j + 1, rotation[size_t(j)].adjoint());
    g.applyOnTheLeft(j, j + 1, rotation[size_t(j)].adjoint());
    ++j;
    if (std::abs(g(j)) <= target) break;
  }
  const Eigen::VectorXd y = H.topLeftCorner(j, j).triangularView<Eigen::Upper>().solve(g.head(j));
  x += preconditioner.solve(Eigen::VectorXd(basis.leftCols(j) * y));
  return j;
}

struct Reuse {
  int iterations[2];
  double seconds, max_difference;
};
Reuse solve_with(const LU& factors, const PassSystem& s, const Eigen::MatrixXd& start, const Eigen::MatrixXd& exact,
                 double tolerance) {
  Reuse result{};
  Eigen::MatrixXd x = start;
  const Clock::time_point t = Clock::now();
  for (int c = 0; c < 2; ++c) {
    Eigen::VectorXd column = x.col(c);
    result.iterations[c] = gmres(s.A, factors, s.rhs.col(c), column, tolerance, 60);
    x.col(c) = column;
  }
  result.seconds = seconds_since(t);
  result.max_difference = (x - exact).cwiseAbs().maxCoeff();
  return result;
}

void study(const std::string& path, int passes, double tolerance) {
  ToolMesh mesh;
  std::string error;
  if (!read_mesh(path, mesh, error)) { std::printf("%s: %s\n", path.c_str(), error.c_str()); return; }
  Eigen::MatrixXd V;
  Eigen::MatrixXi F;
  mesh_to_arrays(mesh, V, F);
  DiskMesh disk;
  if (Error e = make_disk_mesh(V, F, disk)) { std::printf("%s: %s\n", path.c_str(), message(e).c_str()); return; }
  const SquareCorners corners = choose_square_corners(disk);
  const Eigen::MatrixXd boundary_uv = square_boundary(disk, corners.corners, corners.bow_side);
  int fallbacks = 0;
  std::vector<double> weights = initial_weights(disk, InitialWeights::Floater, fallbacks);
  LaplacianSolver solver(disk);
  Eigen::MatrixXd uv;

  std::printf("%s: %ld interior rows, GMRES tolerance %.0e (relative residual)\n", path.c_str(),
              long(solver.matrix().rows()), tolerance);
  std::printf("  pass  refactor+solve | LU(0): its u/v, seconds, max UV diff | LU(k-1): its u/v, seconds, max UV diff\n");
  LU first, previous, current;
  for (LU* lu : {&first, &previous, &current}) {  // the core's settings (laplacian_solver.cpp)
    lu->umfpackControl()(UMFPACK_ORDERING) = UMFPACK_ORDERING_METIS;
    lu->umfpackControl()(UMFPACK_IRSTEP) = 0;
  }
  Eigen::MatrixXd previous_x;
  for (int pass = 0; pass <= passes; ++pass) {
    PassSystem s;
    s.rhs = solver.assemble(weights, boundary_uv, uv);
    s.A = solver.matrix();
    if (pass == 0) current.analyzePattern(s.A);
    Clock::time_point t = Clock::now();
    current.factorize(s.A);
    const Eigen::MatrixXd x = current.solve(s.rhs);
    const double refactor = seconds_since(t);
    if (pass == 0) {
      std::printf("  %4d  %6.3f s (analysis excluded)\n", pass, refactor);
      first.compute(s.A);
    } else {
      const Reuse a = solve_with(first, s, previous_x, x, tolerance);
      const Reuse b = solve_with(previous, s, previous_x, x, tolerance);
      std::printf("  %4d  %6.3f s       | %2d/%2d %6.3f s %8.1e           | %2d/%2d %6.3f s %8.1e\n", pass, refactor,
                  a.iterations[0], a.iterations[1], a.seconds, a.max_difference, b.iterations[0], b.iterations[1],
                  b.seconds, b.max_difference);
    }
    // The previous pass's factors for the next row: factorize again into a second object (the
    // cost is not counted; it is what "LU(k-1)" would have had for free).
    previous.compute(s.A);
    previous_x = x;
    solver.scatter(x, uv);
    reweight(disk, vertex_stretch(disk.F, int(disk.V.rows()), face_stretch(disk.V, disk.F, uv)), 1.0, weights);
  }
}

}  // namespace

int main(int argc, char** argv) {
  int passes = 4;
  double tolerance = 1e-9;
  std::vector<std::string> meshes;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--passes" && i + 1 < argc) passes = std::max(1, std::atoi(argv[++i]));
    else if (a == "--tolerance" && i + 1 < argc) tolerance = std::atof(argv[++i]);
    else meshes.push_back(a);
  }
  if (meshes.empty()) {
    std::fprintf(stderr, "usage: lowstretch_reuse_study [--passes N] [--tolerance T] MESH...\n");
    return 1;
  }
  for (const std::string& m : meshes) study(m, passes, tolerance);
  return 0;
}
