// lowstretch: the low-stretch parameterization of a disk-like mesh, from the command line.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

#include "../core/parameterize.h"
#include "../vcg/mesh_arrays.h"
#include "mesh_io.h"
#include "uv_svg.h"

namespace {

using namespace lowstretch;

const char* kUsage =
    "usage: lowstretch INPUT [-o OUTPUT.obj|.ply] [--boundary square|circle|natural]\n"
    "                  [--weights floater|meanvalue|harmonic] [--exponent E] [--max-passes N]\n"
    "                  [--all-passes] [--json] [--svg UV.svg]\n"
    "Reads OFF, OBJ or PLY; writes per-corner texture coordinates and stretch as quality.\n"
    "--all-passes runs max-passes passes even when the stretch stops falling (benchmarks).\n"
    "Exit codes: 0 done, 1 bad arguments, 2 unreadable input, 3 mesh not usable, 4 cannot write.\n";

enum Exit { kDone = 0, kBadArguments = 1, kUnreadable = 2, kRejected = 3, kCannotWrite = 4 };

struct Arguments {
  std::string input, output, svg;
  bool json = false;
  Options options;
};

bool parse_number(const char* text, double& value) {
  char* end = nullptr;
  value = std::strtod(text, &end);
  return end != text && *end == '\0' && std::isfinite(value);
}

// Returns an empty string or the reason the arguments are wrong.
std::string parse(int argc, char** argv, Arguments& a) {
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const bool has_value = i + 1 < argc;
    auto value = [&]() { return std::string(argv[++i]); };
    if (arg == "--json") a.json = true;
    else if (arg == "--all-passes") a.options.stop_when_stretch_rises = false;
    else if (arg == "-h" || arg == "--help") return "help";
    else if ((arg == "-o" || arg == "--svg" || arg == "--boundary" || arg == "--weights" || arg == "--exponent" ||
              arg == "--max-passes") && !has_value) return arg + " needs a value";
    else if (arg == "-o") a.output = value();
    else if (arg == "--svg") a.svg = value();
    else if (arg == "--boundary") {
      const std::string v = value();
      if (v == "square") a.options.boundary = BoundaryShape::Square;
      else if (v == "circle") a.options.boundary = BoundaryShape::Circle;
      else if (v == "natural") a.options.boundary = BoundaryShape::Natural;
      else return "--boundary takes square, circle or natural, not '" + v + "'";
    } else if (arg == "--weights") {
      const std::string v = value();
      if (v == "floater") a.options.weights = InitialWeights::Floater;
      else if (v == "meanvalue") a.options.weights = InitialWeights::MeanValue;
      else if (v == "harmonic") a.options.weights = InitialWeights::Harmonic;
      else return "--weights takes floater, meanvalue or harmonic, not '" + v + "'";
    } else if (arg == "--exponent") {
      if (!parse_number(argv[++i], a.options.exponent)) return "--exponent takes a number in (0, 1]";
    } else if (arg == "--max-passes") {
      double passes = 0;
      if (!parse_number(argv[++i], passes) || passes != std::floor(passes) || passes < 0 || passes > 1000)
        return "--max-passes takes a whole number from 0 to 1000";
      a.options.max_passes = int(passes);
    } else if (!arg.empty() && arg[0] == '-') return "unknown option " + arg;
    else if (a.input.empty()) a.input = arg;
    else return "more than one input file: " + arg;
  }
  if (a.input.empty()) return "no input file";
  return "";
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

void print_json(const Arguments& a, const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const Result& r) {
  std::ostringstream o;
  o << "{\"input\": " << quoted(a.input) << ", \"vertices\": " << V.rows() << ", \"faces\": " << F.rows()
    << ", \"boundary\": \"" << to_string(a.options.boundary) << "\", \"weights\": \"" << to_string(a.options.weights)
    << "\", \"exponent\": " << number(a.options.exponent) << ", \"max_passes\": " << a.options.max_passes
    << ",\n \"passes\": [";
  for (size_t i = 0; i < r.passes.size(); ++i) {
    const PassMetrics& p = r.passes[i];
    o << (i ? ",\n  " : "\n  ") << "{\"pass\": " << p.pass << ", \"l2_stretch\": " << number(p.l2_stretch)
      << ", \"linf_stretch\": " << number(p.linf_stretch) << ", \"edge_distortion\": " << number(p.edge_distortion)
      << ", \"angle_distortion\": " << number(p.angle_distortion) << ", \"area_distortion\": " << number(p.area_distortion)
      << ", \"flipped\": " << p.flipped << ", \"degenerate\": " << p.degenerate << ", \"seconds\": " << number(p.seconds)
      << ", \"seconds_assembly\": " << number(p.seconds_assembly) << ", \"seconds_factorization\": " << number(p.seconds_factorization)
      << ", \"seconds_solve\": " << number(p.seconds_solve) << ", \"seconds_metrics\": " << number(p.seconds_metrics) << "}";
  }
  o << "],\n \"chosen_pass\": " << r.chosen_pass << ", \"stop_reason\": " << quoted(to_string(r.stop_reason))
    << ", \"seconds_total\": " << number(r.seconds_total) << ", \"notes\": [";
  for (size_t i = 0; i < r.notes.size(); ++i) o << (i ? ", " : "") << quoted(r.notes[i]);
  o << "]}\n";
  std::cout << o.str();
}

void print_table(const Result& r) {
  std::printf("pass   L2 stretch  Linf stretch   edge    angle    area   flips  zero-area  seconds\n");
  for (const PassMetrics& p : r.passes)
    std::printf("%4d %12.4f %12.4g %7.4f %7.4f %7.4f %7d %9d %8.3f%s\n", p.pass, p.l2_stretch, p.linf_stretch,
                p.edge_distortion, p.angle_distortion, p.area_distortion, p.flipped, p.degenerate, p.seconds,
                p.pass == r.chosen_pass ? "  <- kept" : "");
  std::printf("kept pass %d (%s); %.3f s\n", r.chosen_pass, to_string(r.stop_reason), r.seconds_total);
  for (const std::string& note : r.notes) std::printf("note: %s\n", note.c_str());
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

  const Result result = parameterize(V, F, args.options);
  if (result.error) {
    std::cerr << "lowstretch: " << args.input << ": " << message(result.error) << "\n";
    return kRejected;
  }
  if (args.json) print_json(args, V, F, result);
  else print_table(result);

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
    title << args.input.substr(args.input.find_last_of('/') + 1) << ": " << to_string(args.options.boundary) << ", pass " << result.chosen_pass << ", L2 stretch "
          << result.passes[size_t(result.chosen_pass)].l2_stretch;
    if (!write_uv_svg(args.svg, result.uv, F, result.face_stretch, title.str(), error)) {
      std::cerr << "lowstretch: " << error << "\n";
      return kCannotWrite;
    }
  }
  return kDone;
}
