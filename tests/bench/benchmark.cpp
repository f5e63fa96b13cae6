// Speed benchmark (not a test): for each mesh, our passes with the time of each phase solved by
// multigrid and by the direct LU side by side (how far multigrid's kept map is from the chain of
// direct solves, and what a fallback costs), a CHOLMOD Cholesky factorization of the same sparsity
// pattern as a yardstick, and CGAL's iterative authalic and mean value parameterizers, all
// measured in one run and reported as medians.
//
// usage: lowstretch_benchmark [--runs N] [--cgal-max-vertices N] [--passes N] [--tolerance T] MESH...
// (--tolerance: multigrid's relative residual, SolverOptions::tolerance, to measure another one)
#include <fcntl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_parameterization/Iterative_authalic_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Mean_value_coordinates_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Square_border_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>
#include <Eigen/CholmodSupport>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "core/disk_mesh.h"
#include "core/parameterize.h"
#include "core/stretch.h"
#include "tool/mesh_io.h"
#include "vcg_arrays/mesh_arrays.h"

using namespace lowstretch;
using Clock = std::chrono::steady_clock;

namespace {

double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }
double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0 : v[v.size() / 2];
}
double peak_rss_mb() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return double(usage.ru_maxrss) / 1024.0;
}

// CHOLMOD supernodal Cholesky of an SPD matrix with the pattern of our system (interior rows,
// interior neighbours): graph Laplacian plus the boundary coupling on the diagonal.
double cholmod_factorization_seconds(const DiskMesh& disk, int runs, double& analyze_seconds) {
  const int n = int(disk.V.rows());
  std::vector<int> row(size_t(n), -1);
  int rows = 0;
  for (int i = 0; i < n; ++i)
    if (!disk.is_boundary[size_t(i)]) row[size_t(i)] = rows++;
  std::vector<Eigen::Triplet<double>> t;
  for (int i = 0; i < n; ++i) {
    if (row[size_t(i)] < 0) continue;
    const int b = disk.ring_start[size_t(i)], e = disk.ring_start[size_t(i) + 1];
    t.emplace_back(row[size_t(i)], row[size_t(i)], double(e - b) + 1e-3);
    for (int s = b; s < e; ++s)
      if (row[size_t(disk.ring[size_t(s)])] >= 0) t.emplace_back(row[size_t(i)], row[size_t(disk.ring[size_t(s)])], -1.0);
  }
  Eigen::SparseMatrix<double> A(rows, rows);
  A.setFromTriplets(t.begin(), t.end());
  Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<double>> llt;
  Clock::time_point start = Clock::now();
  llt.analyzePattern(A);
  analyze_seconds = seconds_since(start);
  std::vector<double> times;
  for (int r = 0; r < runs; ++r) {
    start = Clock::now();
    llt.factorize(A);
    times.push_back(seconds_since(start));
  }
  return median(times);
}

using Kernel = CGAL::Simple_cartesian<double>;
using SurfaceMesh = CGAL::Surface_mesh<Kernel::Point_3>;
using VertexIndex = SurfaceMesh::Vertex_index;
namespace SMP = CGAL::Surface_mesh_parameterization;

struct CgalRun {
  double seconds = 0;
  PassMetrics metrics;
  bool ok = false;
};

template <class Parameterize>
CgalRun run_cgal(const DiskMesh& disk, Parameterize parameterize_with_cgal) {
  SurfaceMesh sm;
  std::vector<VertexIndex> vertex;
  for (Eigen::Index i = 0; i < disk.V.rows(); ++i)
    vertex.push_back(sm.add_vertex(Kernel::Point_3(disk.V(i, 0), disk.V(i, 1), disk.V(i, 2))));
  for (Eigen::Index f = 0; f < disk.F.rows(); ++f)
    sm.add_face(vertex[size_t(disk.F(f, 0))], vertex[size_t(disk.F(f, 1))], vertex[size_t(disk.F(f, 2))]);
  auto uv = sm.add_property_map<VertexIndex, Kernel::Point_2>("v:uv").first;
  const auto border = CGAL::Polygon_mesh_processing::longest_border(sm).first;
  CgalRun run;
  std::fflush(stdout);
  const int saved_stdout = dup(1), null = open("/dev/null", O_WRONLY);  // CGAL prints every iteration
  dup2(null, 1);
  const Clock::time_point start = Clock::now();
  run.ok = parameterize_with_cgal(sm, border, uv) == SMP::OK;
  run.seconds = seconds_since(start);
  std::fflush(stdout);
  dup2(saved_stdout, 1);
  close(null);
  close(saved_stdout);
  Eigen::MatrixXd UV(disk.V.rows(), 2);
  for (Eigen::Index i = 0; i < disk.V.rows(); ++i) UV.row(i) << uv[vertex[size_t(i)]].x(), uv[vertex[size_t(i)]].y();
  // CGAL may run the border the other way round: flips count against the majority orientation.
  if (face_stretch(disk.V, disk.F, UV).area_uv.sum() < 0) UV.col(0) = (1 - UV.col(0).array()).matrix();
  run.metrics = measure(disk.V, disk.F, disk.edges, UV, face_stretch(disk.V, disk.F, UV));
  return run;
}

using Border = SMP::Square_border_arc_length_parameterizer_3<SurfaceMesh>;

std::string report_cgal(const char* name, const CgalRun& r) {
  std::printf("  %-34s %8.3f s  L2 %8.4f  flips %d  zero-area %d%s\n", name, r.seconds, r.metrics.l2_stretch,
              r.metrics.flipped, r.metrics.degenerate, r.ok ? "" : "  (CGAL reported an error)");
  char cell[96];
  std::snprintf(cell, sizeof cell, "%.2f s, L2 %.3f, %d/%d", r.seconds, r.metrics.l2_stretch, r.metrics.flipped,
                r.metrics.degenerate);
  return cell;
}

std::string base_name(const std::string& path) { return path.substr(path.find_last_of('/') + 1); }

// Prints the mesh's report and returns its row of the summary table ("" if it could not run).
std::string benchmark_mesh(const std::string& path, int runs, int passes, long cgal_max_vertices, double tolerance) {
  ToolMesh mesh;
  std::string error;
  if (!read_mesh(path, mesh, error)) { std::printf("%s: %s\n", path.c_str(), error.c_str()); return ""; }
  Eigen::MatrixXd V;
  Eigen::MatrixXi F;
  mesh_to_arrays(mesh, V, F);
  DiskMesh disk;
  if (Error e = make_disk_mesh(V, F, disk)) { std::printf("%s: %s\n", path.c_str(), message(e).c_str()); return ""; }
  long interior = 0;
  for (char b : disk.is_boundary) interior += !b;
  std::printf("%s: %ld vertices, %ld interior rows, %ld faces\n", path.c_str(), long(V.rows()), interior, long(F.rows()));

  double analyze = 0;
  const double cholmod = cholmod_factorization_seconds(disk, runs, analyze);
  std::printf("  CHOLMOD supernodal LLT of the pattern: analyze %.3f s, factorize %.3f s (median of %d)\n", analyze, cholmod, runs);

  // Both solvers, each with the stop rule and with every pass forced; how far apart their kept
  // maps are, and whether they keep the same pass with the same flips.
  struct SolverRun {
    double stop = 0, forced = 0;
    Result stop_rule, all_passes;
  };
  SolverRun run[2];
  const LinearSolver methods[2] = {LinearSolver::Amg, LinearSolver::Direct};
  for (int m = 0; m < 2; ++m)
    for (bool forced : {false, true}) {
      Options o;
      o.max_passes = passes;
      o.stop_when_stretch_rises = !forced;
      o.solver.method = methods[m];
      o.solver.tolerance = tolerance;
      o.solver.residual_accepted = std::max(o.solver.residual_accepted, 10 * tolerance);
      std::vector<double> totals;
      std::vector<std::vector<PassMetrics>> all;
      Result r;
      for (int k = 0; k < runs; ++k) {
        r = parameterize(V, F, o);
        if (r.error) { std::printf("  %s\n", message(r.error).c_str()); return ""; }
        totals.push_back(r.seconds_total);
        all.push_back(r.passes);
      }
      const double total = median(totals);
      std::printf("  %s, max passes %d%s: %.3f s total (median of %d), %zu solves, kept pass %d, L2 %.4f, flips %d; %.2f x CHOLMOD\n",
                  to_string(methods[m]), passes, forced ? " forced" : " with the stop rule", total, runs, r.passes.size(),
                  r.chosen_pass, r.passes[size_t(r.chosen_pass)].l2_stretch, r.passes[size_t(r.chosen_pass)].flipped,
                  total / cholmod);
      (forced ? run[m].forced : run[m].stop) = total;
      (forced ? run[m].all_passes : run[m].stop_rule) = r;
      if (forced) continue;
      std::printf("    pass  assembly  setup/LU   solve  metrics    total   L2 stretch  solver\n");
      for (size_t p = 0; p < r.passes.size(); ++p) {
        std::vector<double> a, f, sv, mt, t;
        for (const auto& one : all)
          if (p < one.size()) {
            a.push_back(one[p].seconds_assembly);
            f.push_back(one[p].seconds_factorization);
            sv.push_back(one[p].seconds_solve);
            mt.push_back(one[p].seconds_metrics);
            t.push_back(one[p].seconds);
          }
        const PassMetrics& q = r.passes[p];
        std::printf("    %4zu %9.3f %9.3f %7.3f %8.3f %8.3f %12.4f  %s %d%s\n", p, median(a), median(f), median(sv), median(mt),
                    median(t), q.l2_stretch, to_string(q.solver), q.solver_iterations, q.solver_fell_back ? " (fell back)" : "");
      }
    }
  // Only the kept map is an output: multigrid's against the direct chain's, stop rule and forced.
  double uv_difference = 0, l2_difference = 0;
  for (const auto& both : {std::make_pair(&run[0].stop_rule, &run[1].stop_rule), std::make_pair(&run[0].all_passes, &run[1].all_passes)}) {
    const Result& amg = *both.first;
    const Result& direct = *both.second;
    uv_difference = std::max(uv_difference, (amg.uv - direct.uv).cwiseAbs().maxCoeff());
    const double l2_amg = amg.passes[size_t(amg.chosen_pass)].l2_stretch;
    const double l2_direct = direct.passes[size_t(direct.chosen_pass)].l2_stretch;
    l2_difference = std::max(l2_difference, std::abs(l2_amg - l2_direct) / l2_direct);
  }
  int fallbacks = 0, most_iterations = 0, amg_passes = 0;
  for (const Result* r : {&run[0].stop_rule, &run[0].all_passes})
    for (const PassMetrics& p : r->passes) {
      fallbacks += p.solver_fell_back;
      amg_passes += p.solver == LinearSolver::Amg;
      most_iterations = std::max(most_iterations, p.solver_iterations);
    }
  const bool same_choice = run[0].stop_rule.chosen_pass == run[1].stop_rule.chosen_pass &&
                           run[0].stop_rule.passes[size_t(run[0].stop_rule.chosen_pass)].flipped ==
                               run[1].stop_rule.passes[size_t(run[1].stop_rule.chosen_pass)].flipped;
  std::printf("  amg against direct, kept map: UV %.2e apart, L2 %.2e apart (relative), same kept pass and flips: %s; "
              "%d multigrid passes, at most %d iterations, %d fell back\n",
              uv_difference, l2_difference, same_choice ? "yes" : "NO", amg_passes, most_iterations, fallbacks);
  // What a fallback costs at worst: multigrid runs out of iterations in the first pass (an
  // unreachable tolerance), then the direct solve takes every pass. One run.
  Options starved;
  starved.max_passes = passes;
  starved.stop_when_stretch_rises = false;
  starved.solver.tolerance = starved.solver.residual_accepted = 1e-30;
  const Result worst = parameterize(V, F, starved);
  const double fallback_seconds = worst.error ? 0 : worst.seconds_total;
  std::printf("  every pass falling back (%d iterations in the first, then the direct solve): %.3f s\n",
              starved.solver.max_iterations, fallback_seconds);

  std::string mean_value = "skipped", authalic = "skipped";
  if (V.rows() > cgal_max_vertices) {
    std::printf("  CGAL skipped above %ld vertices (it takes minutes)\n", cgal_max_vertices);
  } else {
    mean_value = report_cgal("CGAL Mean_value_coordinates (square)", run_cgal(disk, [](SurfaceMesh& sm, auto border, auto uv) {
                  return SMP::parameterize(sm, SMP::Mean_value_coordinates_parameterizer_3<SurfaceMesh, Border>(), border, uv);
                }));
    authalic = report_cgal("CGAL Iterative_authalic (square)", run_cgal(disk, [](SurfaceMesh& sm, auto border, auto uv) {
                  SMP::Iterative_authalic_parameterizer_3<SurfaceMesh, Border> iterative;
                  return iterative.parameterize(sm, border, uv, 15u);
                }));
  }
  const double peak = peak_rss_mb();
  std::printf("  peak memory %.0f MB\n", peak);
  const PassMetrics& kept = run[0].stop_rule.passes[size_t(run[0].stop_rule.chosen_pass)];
  char row[768];
  std::snprintf(row, sizeof row,
                "| %s | %ld | %zu (%d) | %.3f | %.3f | %.3f | %.2f | %.3f | %.1f | %.1e / %.1e | %s | %d / %d | %.2f | %.3f | %d | %.0f | %s | %s |",
                base_name(path).c_str(), long(V.rows()), run[0].stop_rule.passes.size(), run[0].stop_rule.chosen_pass,
                run[0].stop, run[0].forced, run[1].forced, run[0].forced / run[1].forced, cholmod,
                run[0].forced / cholmod, uv_difference, l2_difference, same_choice ? "yes" : "NO", most_iterations, fallbacks,
                fallback_seconds, kept.l2_stretch, kept.flipped, peak, mean_value.c_str(), authalic.c_str());
  return row;
}

}  // namespace

int main(int argc, char** argv) {
  int runs = 5, passes = 4;
  double tolerance = SolverOptions().tolerance;
  long cgal_max_vertices = 50000;
  std::vector<std::string> meshes;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--runs" && i + 1 < argc) runs = std::max(1, std::atoi(argv[++i]));
    else if (a == "--passes" && i + 1 < argc) passes = std::max(0, std::atoi(argv[++i]));
    else if (a == "--tolerance" && i + 1 < argc) tolerance = std::atof(argv[++i]);
    else if (a == "--cgal-max-vertices" && i + 1 < argc) cgal_max_vertices = std::atol(argv[++i]);
    else meshes.push_back(a);
  }
  if (meshes.empty()) {
    std::fprintf(stderr, "usage: lowstretch_benchmark [--runs N] [--passes N] [--cgal-max-vertices N] [--tolerance T] MESH...\n");
    return 1;
  }
  // One child process per mesh, so that the peak memory it reports is that mesh's alone; the
  // child sends its summary row back through a pipe.
  std::vector<std::string> rows;
  for (const std::string& m : meshes) {
    std::fflush(stdout);
    int channel[2];
    if (pipe(channel) != 0) return 1;
    const pid_t child = fork();
    if (child == 0) {
      close(channel[0]);
      const std::string row = benchmark_mesh(m, runs, passes, cgal_max_vertices, tolerance);
      std::fflush(stdout);
      if (write(channel[1], row.data(), row.size()) < 0) _exit(1);
      _exit(0);
    }
    close(channel[1]);
    std::string row;
    char buffer[256];
    for (ssize_t got; (got = read(channel[0], buffer, sizeof buffer)) > 0;) row.append(buffer, size_t(got));
    close(channel[0]);
    int status = 0;
    waitpid(child, &status, 0);
    if (!row.empty()) rows.push_back(row);
  }
  std::printf("\nSummary (seconds are medians of %d runs; CGAL cells: seconds, L2 stretch, flipped/zero-area):\n\n", runs);
  std::printf("| mesh | V | solves (kept) | amg, stop rule | amg, %d passes forced | direct, forced | amg / direct | CHOLMOD | amg / CHOLMOD "
              "| kept map from the direct one: UV / L2 | same kept pass and flips | most iterations / fallbacks | all passes falling back "
              "| L2 | flips | peak MB | CGAL mean value | CGAL iterative authalic |\n", passes);
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (const std::string& row : rows) std::printf("%s\n", row.c_str());
  return 0;
}
