// lowstretch: the low-stretch parameterization of a disk-like mesh (or of any manifold mesh cut
// into disk charts), from the command line.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

#include "atlas/charts.h"
#include "core/parameterize.h"
#include "plugin_common/result_lines.h"
#include "vcg_arrays/mesh_arrays.h"
#include "tool/mesh_io.h"
#include "tool/uv_svg.h"

namespace {

using namespace lowstretch;

const char* kUsage =
    "usage: lowstretch INPUT [-o OUTPUT.obj|.ply] [--boundary square|circle|natural]\n"
    "                  [--weights floater|meanvalue|harmonic] [--exponent E] [--max-passes N]\n"
    "                  [--all-passes] [--solver amg|direct] [--non-disk reject|charts] [--atlas]\n"
    "                  [--max-stretch S] [--texture-size N] [--gutter G] [--refine] [--json] [--svg UV.svg]\n"
    "Reads OFF, OBJ or PLY; writes per-corner texture coordinates and stretch as quality.\n"
    "Every texture coordinate stays G texels (default 2) inside the border of an N x N texture\n"
    "(default 1024), so that baking a texture of that size never addresses a texel outside it.\n"
    "A mesh that is not a disk (holes, closed, handles, several parts, non-manifold edges or\n"
    "vertices) gets an atlas (--non-disk charts, the default); --non-disk reject refuses it.\n"
    "A disk gets the paper's single chart, or an atlas if that map has a flipped or zero-area\n"
    "triangle. --atlas makes an atlas of any mesh: a chart whose L2\n"
    "stretch is above S (default 1.2) is cut in two and mapped again; every chart gets a rectangle\n"
    "and the rectangles tile the texture, G texels apart. A disk that meets S stays one chart.\n"
    "--all-passes runs max-passes passes even when the stretch stops falling (benchmarks).\n"
    "--refine then lowers the kept map's L2 stretch directly (at most 10 times the method's time).\n"
    "--solver amg (the default) solves each pass by algebraic multigrid, falling back to the sparse\n"
    "LU of --solver direct for a pass where it does not converge.\n"
    "Exit codes: 0 done, 1 bad arguments, 2 unreadable input, 3 mesh not usable, 4 cannot write.\n";

enum Exit { kDone = 0, kBadArguments = 1, kUnreadable = 2, kRejected = 3, kCannotWrite = 4 };

struct Arguments {
  std::string input, output, svg;
  bool json = false;
  ChartOptions charts;
};

bool parse_number(const char* text, double& value) {
  char* end = nullptr;
  value = std::strtod(text, &end);
  return end != text && *end == '\0' && std::isfinite(value);
}

bool parse_whole_number(const char* text, int& value) {
  double number = 0;
  if (!parse_number(text, number) || number != std::floor(number) || std::abs(number) > 1e9) return false;
  value = int(number);
  return true;
}

// Returns an empty string or the reason the arguments are wrong.
std::string parse(int argc, char** argv, Arguments& a) {
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const bool has_value = i + 1 < argc;
    auto value = [&]() { return std::string(argv[++i]); };
    if (arg == "--json") a.json = true;
    else if (arg == "--atlas") a.charts.non_disk = NonDisk::Atlas;
    else if (arg == "--refine") a.charts.disk.refine = true;
    else if (arg == "--all-passes") a.charts.disk.stop_when_stretch_rises = false;
    else if (arg == "-h" || arg == "--help") return "help";
    else if ((arg == "-o" || arg == "--svg" || arg == "--boundary" || arg == "--weights" || arg == "--exponent" ||
              arg == "--max-passes" || arg == "--non-disk" || arg == "--solver" || arg == "--texture-size" ||
              arg == "--gutter" || arg == "--max-stretch") && !has_value) return arg + " needs a value";
    else if (arg == "-o") a.output = value();
    else if (arg == "--svg") a.svg = value();
    else if (arg == "--non-disk") {
      const std::string v = value();
      if (v != "reject" && v != "charts") return "--non-disk takes reject or charts, not '" + v + "'";
      if (a.charts.non_disk == NonDisk::Atlas) continue;  // --atlas covers non-disks too
      a.charts.non_disk = v == "reject" ? NonDisk::Reject : NonDisk::Charts;
    }
    else if (arg == "--solver") {
      const std::string v = value();
      if (v == "amg") a.charts.disk.solver.method = LinearSolver::Amg;
      else if (v == "direct") a.charts.disk.solver.method = LinearSolver::Direct;
      else return "--solver takes amg or direct, not '" + v + "'";
    }
    else if (arg == "--boundary") {
      const std::string v = value();
      if (v == "square") a.charts.disk.boundary = BoundaryShape::Square;
      else if (v == "circle") a.charts.disk.boundary = BoundaryShape::Circle;
      else if (v == "natural") a.charts.disk.boundary = BoundaryShape::Natural;
      else return "--boundary takes square, circle or natural, not '" + v + "'";
    } else if (arg == "--weights") {
      const std::string v = value();
      if (v == "floater") a.charts.disk.weights = InitialWeights::Floater;
      else if (v == "meanvalue") a.charts.disk.weights = InitialWeights::MeanValue;
      else if (v == "harmonic") a.charts.disk.weights = InitialWeights::Harmonic;
      else return "--weights takes floater, meanvalue or harmonic, not '" + v + "'";
    } else if (arg == "--exponent") {
      if (!parse_number(argv[++i], a.charts.disk.exponent)) return "--exponent takes a number";
    } else if (arg == "--max-passes") {  // the core checks the ranges (flag_of names them)
      if (!parse_whole_number(argv[++i], a.charts.disk.max_passes)) return "--max-passes takes a whole number";
    } else if (arg == "--texture-size") {
      if (!parse_whole_number(argv[++i], a.charts.texture_size)) return "--texture-size takes a whole number";
    } else if (arg == "--max-stretch") {
      if (!parse_number(argv[++i], a.charts.max_stretch)) return "--max-stretch takes a number";
    } else if (arg == "--gutter") {
      if (!parse_number(argv[++i], a.charts.gutter)) return "--gutter takes a number";
    } else if (!arg.empty() && arg[0] == '-') return "unknown option " + arg;
    else if (a.input.empty()) a.input = arg;
    else return "more than one input file: " + arg;
  }
  if (a.input.empty()) return "no input file";
  return "";
}

// The tool's flag for an option the core names in an InvalidOption error.
std::string flag_of(const std::string& option) {
  if (option == "exponent") return "--exponent";
  if (option == "max_passes") return "--max-passes";
  if (option == "texture_size") return "--texture-size";
  if (option == "gutter") return "--gutter";
  if (option == "max_stretch") return "--max-stretch";
  return option;
}

// JSON has no infinity: a flipped map's stretch is written as null.
std::string number(double v) {
  if (!std::isfinite(v)) return "null";
  std::ostringstream s;
  s.precision(10);
  s << v;
  return s.str();
}

std::string quoted(const std::string& text) {
  std::string out = "\"";
  for (char c : text) {
    if (c == '"' || c == '\\') out += '\\';
    if (c == '\n') { out += "\\n"; continue; }
    out += c;
  }
  return out + "\"";
}

std::string pass_json(const PassMetrics& p) {
  std::ostringstream o;
  o << "{\"pass\": " << p.pass << ", \"l2_stretch\": " << number(p.l2_stretch)
    << ", \"linf_stretch\": " << number(p.linf_stretch) << ", \"edge_distortion\": " << number(p.edge_distortion)
    << ", \"angle_distortion\": " << number(p.angle_distortion) << ", \"area_distortion\": " << number(p.area_distortion)
    << ", \"flipped\": " << p.flipped << ", \"degenerate\": " << p.degenerate << ", \"seconds\": " << number(p.seconds)
    << ", \"seconds_assembly\": " << number(p.seconds_assembly) << ", \"seconds_factorization\": " << number(p.seconds_factorization)
    << ", \"seconds_solve\": " << number(p.seconds_solve) << ", \"seconds_metrics\": " << number(p.seconds_metrics)
    << ", \"solver\": \"" << to_string(p.solver) << "\", \"solver_fell_back\": " << (p.solver_fell_back ? "true" : "false")
    << ", \"solver_iterations\": " << p.solver_iterations << ", \"solver_residual\": " << number(p.solver_residual) << "}";
  return o.str();
}

// A disk's passes; always the map as written (layout, coverage, tiny triangles); with
// --non-disk charts also the charts.
void print_json(const Arguments& a, const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const ChartsResult& c) {
  std::ostringstream o;
  o << "{\"input\": " << quoted(a.input) << ", \"vertices\": " << V.rows() << ", \"faces\": " << F.rows()
    << ", \"boundary\": \"" << to_string(a.charts.disk.boundary) << "\", \"weights\": \"" << to_string(a.charts.disk.weights)
    << "\", \"exponent\": " << number(a.charts.disk.exponent)
    << ", \"solver\": \"" << to_string(a.charts.disk.solver.method) << "\", \"max_passes\": " << a.charts.disk.max_passes;
  if (c.input_is_disk) {
    o << ",\n \"passes\": [";
    for (size_t i = 0; i < c.disk_passes.size(); ++i) o << (i ? ",\n  " : "\n  ") << pass_json(c.disk_passes[i]);
    o << "],\n \"chosen_pass\": " << c.chosen_pass << ", \"stop_reason\": " << quoted(to_string(c.stop_reason));
  }
  // The map as written (float texture coordinates inside the gutter), disk or charts.
  o << ",\n \"texture_size\": " << a.charts.texture_size << ", \"gutter\": " << number(a.charts.gutter)
    << ", \"coverage\": " << number(c.coverage) << ", \"subtexel_triangles\": " << c.subtexel_triangles
    << ", \"float_collapsed\": " << c.float_collapsed << ",\n \"layout\": " << pass_json(c.layout);
  if (a.charts.non_disk != NonDisk::Reject) {
    o << ",\n \"non_disk\": \"" << to_string(a.charts.non_disk) << "\", \"input_is_disk\": " << (c.input_is_disk ? "true" : "false")
      << ", \"max_stretch\": " << number(a.charts.max_stretch) << ", \"chart_count\": " << c.charts.size()
      << ", \"seam_length\": " << number(c.seam_length) << ", \"efficiency\": " << number(texture_efficiency(c))
      << ", \"max_chart_stretch\": " << number(largest_chart_stretch(c)) << ",\n \"charts\": [";
    for (size_t i = 0; i < c.charts.size(); ++i) {
      const Chart& ch = c.charts[i];
      o << (i ? ",\n  " : "\n  ") << "{\"faces\": " << ch.faces << ", \"closed_holes\": " << ch.closed_holes
        << ", \"seam_length\": " << number(ch.seam_length) << ", \"l2_stretch\": " << number(ch.l2_stretch)
        << ", \"linf_stretch\": " << number(ch.linf_stretch) << ", \"above_bound\": " << (ch.above_bound ? "true" : "false")
        << (ch.above_bound ? ", \"kept_whole\": " + quoted(ch.kept_whole) : std::string())
        << ", \"chosen_pass\": " << ch.chosen_pass << ", \"passes\": " << ch.passes << "}";
    }
    o << "],\n \"layout_passes\": [";
    for (size_t i = 0; i < c.passes.size(); ++i)
      o << (i ? ", " : "") << "{\"pass\": " << c.passes[i].pass << ", \"l2_stretch\": " << number(c.passes[i].l2_stretch)
        << ", \"flipped\": " << c.passes[i].flipped << ", \"degenerate\": " << c.passes[i].degenerate << "}";
    o << "]";
  }
  o << ",\n \"seconds_total\": " << number(c.seconds_total) << ", \"notes\": [";
  for (size_t i = 0; i < c.notes.size(); ++i) o << (i ? ", " : "") << quoted(c.notes[i]);
  o << "]}\n";
  std::cout << o.str();
}

// The texture the output names: the project's checkerboard, copied beside the output once the
// mesh is written.
const char* kTexture = "checkerboard.png";
void place_texture(const std::string& output) {
  const size_t slash = output.find_last_of('/');
  const std::string target = (slash == std::string::npos ? std::string() : output.substr(0, slash + 1)) + kTexture;
  if (std::ifstream(target)) return;
  std::ifstream in(LOWSTRETCH_RESOURCES_DIR "/checkerboard.png", std::ios::binary);
  if (in) std::ofstream(target, std::ios::binary) << in.rdbuf();
}

}  // namespace

int main(int argc, char** argv) {
  Arguments args;
  const std::string problem = parse(argc, argv, args);
  if (problem == "help") { std::cout << kUsage; return kDone; }
  if (!problem.empty()) { std::cerr << "lowstretch: " << problem << "\n" << kUsage; return kBadArguments; }

  ToolMesh mesh;
  std::string error;
  if (!read_mesh(args.input, mesh, error)) { std::cerr << "lowstretch: " << error << "\n"; return kUnreadable; }
  Eigen::MatrixXd V;
  Eigen::MatrixXi F;
  const ArrayRows rows = mesh_to_arrays(mesh, V, F);

  const ChartsResult result = parameterize_charts(V, F, args.charts);
  if (result.error) {
    // An option value that the core refuses is a bad argument, as the usage says.
    if (result.error.code == ErrorCode::InvalidOption) {
      std::cerr << "lowstretch: " << message(result.error, flag_of) << "\n" << kUsage;
      return kBadArguments;
    }
    std::cerr << "lowstretch: " << args.input << ": " << message(result.error)
              << (charts_would_help(result.error.code) ? " (--non-disk charts)" : "") << "\n";
    return kRejected;
  }
  if (args.json) print_json(args, V, F, result);
  else
    for (const std::string& line : result_lines(result)) std::printf("%s\n", line.c_str());

  if (!args.output.empty()) {
    write_parameterization(mesh, rows, result);
    if (!write_mesh(args.output, mesh, kTexture, error)) {
      std::cerr << "lowstretch: " << error << "\n";
      return kCannotWrite;
    }
    place_texture(args.output);
  }
  if (!args.svg.empty()) {
    std::ostringstream title;
    title << args.input.substr(args.input.find_last_of('/') + 1) << ": " << to_string(args.charts.disk.boundary);
    if (result.input_is_disk) title << ", pass " << result.chosen_pass;
    else title << ", " << result.charts.size() << " charts";
    title << ", L2 stretch " << result.layout.l2_stretch;
    // Three UV rows per face, so that seams show as they are.
    Eigen::MatrixXd corner_uv(3 * F.rows(), 2);
    Eigen::MatrixXi corner_faces(F.rows(), 3);
    for (Eigen::Index f = 0; f < F.rows(); ++f)
      for (int k = 0; k < 3; ++k) {
        corner_uv.row(3 * f + k) = result.corner_uv.block(f, 2 * k, 1, 2);
        corner_faces(f, k) = int(3 * f + k);
      }
    if (!write_uv_svg(args.svg, corner_uv, corner_faces, result.face_stretch, title.str(), error)) {
      std::cerr << "lowstretch: " << error << "\n";
      return kCannotWrite;
    }
  }
  return kDone;
}
