#include "plugin_common/result_lines.h"

#include <cstdarg>
#include <cstdio>

namespace lowstretch {

std::string format(const char* f, ...) {
  char buffer[4096];  // as MeshLab's log, which formats with snprintf into 4096 bytes
  va_list args;
  va_start(args, f);
  std::vsnprintf(buffer, sizeof buffer, f, args);
  va_end(args);
  return buffer;
}

namespace {

// "multigrid, 8 iterations", "direct", or "direct (multigrid did not converge)".
std::string solver_text(const PassMetrics& p) {
  if (p.solver == LinearSolver::Amg) return format("multigrid, %d iterations", p.solver_iterations);
  return p.solver_fell_back ? "direct (multigrid did not converge)" : "direct";
}

// The map the mesh holds: float texture coordinates inside the gutter, as the metrics describe it.
std::string stored_line(const ChartsResult& result) {
  const PassMetrics& p = result.layout;
  return format("texture coordinates as stored (float): L2 stretch %.6g, Linf stretch %.6g, flipped %d, degenerate %d, "
                "coverage %.4f; %d UV triangles smaller than a texel of a 4096x4096 texture; charts %.4g texels or more "
                "apart and from the border",
                p.l2_stretch, p.linf_stretch, p.flipped, p.degenerate, result.coverage, result.subtexel_triangles,
                result.least_gutter);
}

std::vector<std::string> disk_lines(const ChartsResult& result) {
  std::vector<std::string> lines;
  for (const PassMetrics& p : result.disk_passes)
    lines.push_back(format("pass %d: L2 stretch %.6g, Linf stretch %.6g, edge distortion %.6g, angle distortion %.6g, "
                           "area distortion %.6g, flipped %d, degenerate %d, %.3f s, %s",
                           p.pass, p.l2_stretch, p.linf_stretch, p.edge_distortion, p.angle_distortion,
                           p.area_distortion, p.flipped, p.degenerate, p.seconds, solver_text(p).c_str()));
  const PassMetrics& kept = result.disk_passes.at(size_t(result.chosen_pass));
  lines.push_back(format("kept pass %d (L2 stretch %.6g); stop reason: %s; total %.3f s", kept.pass, kept.l2_stretch,
                         to_string(result.stop_reason), result.seconds_total));
  lines.push_back(stored_line(result));
  for (const std::string& note : result.notes) lines.push_back("note: " + note);
  return lines;
}

std::vector<std::string> chart_lines(const ChartsResult& result) {
  std::vector<std::string> lines;
  const size_t shown = 20;  // a mesh of many parts would flood the log
  for (size_t i = 0; i < result.charts.size() && i < shown; ++i) {
    const Chart& c = result.charts[i];
    lines.push_back(format("chart %zu: %d faces, %d holes closed, seam length %.6g, L2 stretch %.6g, Linf stretch %.6g, "
                           "kept pass %d of %d",
                           i, c.faces, c.closed_holes, c.seam_length, c.l2_stretch, c.linf_stretch, c.chosen_pass, c.passes - 1));
  }
  if (result.charts.size() > shown) lines.push_back(format("... and %zu more charts", result.charts.size() - shown));
  for (const LayoutPass& lp : result.passes)
    lines.push_back(format("pass %d over all charts (a chart that stopped counts with its kept pass): L2 stretch %.6g, "
                           "flipped %d, degenerate %d",
                           lp.pass, lp.l2_stretch, lp.flipped, lp.degenerate));
  const PassMetrics& p = result.layout;
  lines.push_back(format("%zu charts (largest chart L2 stretch %.6g), seam length %.6g, coverage %.4f, efficiency %.4f "
                         "(coverage / L2^2); whole layout: L2 stretch %.6g, Linf stretch %.6g, "
                         "edge distortion %.6g, angle distortion %.6g, area distortion %.6g, flipped %d, degenerate %d; "
                         "total %.3f s",
                         result.charts.size(), largest_chart_stretch(result), result.seam_length, result.coverage,
                         texture_efficiency(result), p.l2_stretch, p.linf_stretch,
                         p.edge_distortion, p.angle_distortion, p.area_distortion, p.flipped, p.degenerate,
                         result.seconds_total));
  lines.push_back(stored_line(result));
  for (const std::string& note : result.notes) lines.push_back("note: " + note);
  return lines;
}

}  // namespace

std::vector<std::string> result_lines(const ChartsResult& result) {
  return result.input_is_disk ? disk_lines(result) : chart_lines(result);
}

}  // namespace lowstretch
