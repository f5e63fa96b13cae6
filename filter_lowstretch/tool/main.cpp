// lowstretch: the low-stretch parameterization of a disk-like mesh (or of any manifold mesh cut
// into disk charts), from the command line.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iostream>
#include <sstream>
#include <nlohmann/json.hpp>
#include <string>

#include "atlas/charts.h"
#include "atlas/repack.h"
#include "core/parameterize.h"
#include "plugin_common/option_table.h"
#include "plugin_common/result_lines.h"
#include "plugin_common/result_table.h"
#include "plugin_common/one_blas_thread.h"
#include "vcg_arrays/mesh_arrays.h"
#include "tool/mesh_counts.h"
#include "tool/mesh_io.h"
#include "tool/uv_svg.h"

namespace {

using namespace lowstretch;

const char* kDescription =
    "lowstretch: low-stretch texture coordinates for a mesh (OFF, OBJ or PLY), written per corner with the\n"
    "stretch as quality. A disk gets the paper's single chart; any other mesh (or, with --atlas, any mesh)\n"
    "an atlas of charts on rectangles tiling the texture. Every coordinate stays --gutter texels inside\n"
    "a --texture-size texture.\n"
    "Exit codes: 0 done, 1 bad arguments, 2 unreadable input, 3 mesh not usable, 4 cannot write.";

enum Exit { kDone = 0, kBadArguments = 1, kUnreadable = 2, kRejected = 3, kCannotWrite = 4 };

struct Arguments {
  std::string input, output, svg;
  bool json = false;
  ChartOptions charts;
};

// The command line from the option table (option_table.h), plus the tool's own input and outputs.
void describe_arguments(CLI::App& app, Arguments& a) {
  app.add_option("input", a.input, "the mesh: OFF, OBJ or PLY")->required();
  app.add_option("-o,--output", a.output, "write the mesh with texture coordinates (.obj or .ply)");
  app.add_option("--svg", a.svg, "draw the texture coordinates coloured by stretch");
  app.add_flag("--json", a.json, "print the metrics as JSON");
  CLI::Option* non_disk = nullptr;
  for (const OptionRow& row : option_table()) {
    ChartOptions& options = a.charts;
    const OptionRow* r = &row;
    CLI::Option* option = nullptr;
    const std::string help = std::string(row.help) + " Default: " + default_text(row) + ".";
    switch (row.kind) {
      case OptionKind::Choice: {
        const std::vector<std::string> words(row.words.begin(), row.words.end());
        option = app.add_option_function<std::string>(
                        row.flag,
                        [&options, r, words](const std::string& word) {
                          r->set(options, double(std::find(words.begin(), words.end(), word) - words.begin()));
                        },
                        help)
                     ->check(CLI::IsMember(words));
        break;
      }
      case OptionKind::Real:
        option = app.add_option_function<double>(row.flag, [&options, r](double v) { r->set(options, v); }, help);
        break;
      case OptionKind::Whole:
        option = app.add_option_function<int>(row.flag, [&options, r](int v) { r->set(options, v); }, help);
        break;
      case OptionKind::Switch:
        option = app.add_flag_callback(row.flag, [&options, r]() { r->set(options, 1); }, help);
        break;
    }
    if (std::string(row.name) == "non_disk") non_disk = option;
  }
  app.add_flag_callback("--atlas", [&a]() { a.charts.non_disk = NonDisk::Atlas; }, "the same as --non-disk atlas")
      ->excludes(non_disk);
}

// The tool's flag for an option the core names in an InvalidOption error.
std::string flag_of(const std::string& option) {
  const OptionRow* row = option_named(option);
  return row != nullptr ? row->flag : option;
}

// JSON has no infinity: a flipped map's stretch is written as null (nlohmann writes non-finite
// numbers as null).
nlohmann::ordered_json pass_json(const PassMetrics& p) {
  return {{"pass", p.pass}, {"l2_stretch", p.l2_stretch}, {"linf_stretch", p.linf_stretch},
          {"edge_distortion", p.edge_distortion}, {"angle_distortion", p.angle_distortion},
          {"area_distortion", p.area_distortion}, {"flipped", p.flipped}, {"degenerate", p.degenerate},
          {"seconds", p.seconds}, {"seconds_assembly", p.seconds_assembly},
          {"seconds_factorization", p.seconds_factorization}, {"seconds_solve", p.seconds_solve},
          {"seconds_metrics", p.seconds_metrics}, {"solver", to_string(p.solver)},
          {"solver_fell_back", p.solver_fell_back}, {"solver_iterations", p.solver_iterations},
          {"solver_residual", p.solver_residual}};
}

nlohmann::ordered_json chart_json(const Chart& c) {
  nlohmann::ordered_json chart = {{"faces", c.faces}, {"closed_holes", c.closed_holes}, {"seam_length", c.seam_length},
                                  {"l2_stretch", c.l2_stretch}, {"linf_stretch", c.linf_stretch},
                                  {"above_bound", c.above_bound}};
  if (c.above_bound) chart["kept_whole"] = c.kept_whole;
  chart["chosen_pass"] = c.chosen_pass;
  chart["passes"] = c.passes;
  return chart;
}

// The input, every option (by its core name), a disk's passes, the map as written, the summary of
// result_table.h, each chart and each pass over all charts.
void print_json(const Arguments& a, const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const ChartsResult& c) {
  nlohmann::ordered_json o = {{"input", a.input}, {"vertices", V.rows()}, {"faces", F.rows()}};
  for (const OptionRow& row : option_table()) {
    const double value = row.get(a.charts);
    if (row.kind == OptionKind::Choice) o[row.name] = row.words.at(size_t(value));
    else if (row.kind == OptionKind::Switch) o[row.name] = value != 0;
    else if (row.kind == OptionKind::Whole) o[row.name] = int(value);
    else o[row.name] = value;
  }
  o["input_is_disk"] = c.input_is_disk;
  if (c.input_is_disk) {
    nlohmann::ordered_json passes = nlohmann::ordered_json::array();
    for (const PassMetrics& p : c.disk_passes) passes.push_back(pass_json(p));
    o["passes"] = passes;
    o["chosen_pass"] = c.chosen_pass;
    o["stop_reason"] = to_string(c.stop_reason);
  }
  o["layout"] = pass_json(c.layout);
  for (const ResultRow& row : result_table()) {
    if (row.json_key == nullptr) continue;
    const double value = row.get(c);
    if (row.is_int) o[row.json_key] = static_cast<long long>(value);
    else o[row.json_key] = value;
  }
  {
    nlohmann::ordered_json charts = nlohmann::ordered_json::array(), passes = nlohmann::ordered_json::array();
    for (const Chart& chart : c.charts) charts.push_back(chart_json(chart));
    for (const LayoutPass& p : c.passes)
      passes.push_back({{"pass", p.pass}, {"l2_stretch", p.l2_stretch}, {"flipped", p.flipped}, {"degenerate", p.degenerate}});
    o["charts"] = charts;
    o["layout_passes"] = passes;
  }
  nlohmann::ordered_json stages = nlohmann::ordered_json::object();
  for (const StageSeconds& stage : c.stage_seconds) stages[stage.stage] = stage.seconds;
  o["stage_seconds"] = stages;
  o["notes"] = c.notes;
  std::cout << o.dump(1) << "\n";
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

// The texture coordinates drawn as SVG, coloured by stretch, three rows per face so that seams
// show as they are.
bool draw_svg(const Arguments& args, const Eigen::MatrixXi& F, const ChartsResult& result, std::string& error) {
  std::ostringstream title;
  title << args.input.substr(args.input.find_last_of('/') + 1) << ": " << to_string(args.charts.disk.boundary);
  if (result.input_is_disk) title << ", pass " << result.chosen_pass;
  else title << ", " << result.charts.size() << " charts";
  title << ", L2 stretch " << result.layout.l2_stretch;
  Eigen::MatrixXd corner_uv(3 * F.rows(), 2);
  Eigen::MatrixXi corner_faces(F.rows(), 3);
  for (Eigen::Index f = 0; f < F.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      corner_uv.row(3 * f + k) = result.corner_uv.block(f, 2 * k, 1, 2);
      corner_faces(f, k) = int(3 * f + k);
    }
  return write_uv_svg(args.svg, corner_uv, corner_faces, result.face_stretch, title.str(), error);
}

}  // namespace

int main(int argc, char** argv) {
  Arguments args;
  CLI::App app(kDescription, "lowstretch");
  describe_arguments(app, args);
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& help) {
    std::cout << app.help();
    return kDone;
  } catch (const CLI::ParseError& e) {
    std::cerr << "lowstretch: " << e.what() << "\n(lowstretch --help lists the options)\n";
    return kBadArguments;
  }

  ToolMesh mesh;
  std::string error;
  if (!read_mesh(args.input, mesh, error)) { std::cerr << "lowstretch: " << error << "\n"; return kUnreadable; }
  Eigen::MatrixXd V;
  Eigen::MatrixXi F;
  const ArrayRows rows = mesh_to_arrays(mesh, V, F);
  const Eigen::MatrixXd corner_uv = args.charts.repack ? wedge_texcoords(mesh, rows) : Eigen::MatrixXd();
  // The readers make every vertex and face live, so V and F hold the whole mesh: it is made again
  // from them for writing, and held no memory during the run (430 MB at 2M vertices).
  std::vector<ToolVertex>().swap(mesh.vert);
  std::vector<ToolFace>().swap(mesh.face);
  mesh.Clear();

  // The atlas solves charts on the thread pool, where OpenBLAS's own threads would only spin.
  const OneBlasThread one_blas_thread;
  const ChartsResult result = args.charts.repack ? repack_atlas(V, F, corner_uv, args.charts) : parameterize_charts(V, F, args.charts);
  if (result.error) {
    // An option value that the core refuses is a bad argument, as the usage says.
    if (result.error.code == ErrorCode::InvalidOption) {
      std::cerr << "lowstretch: " << message(result.error, flag_of) << "\n";
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
    std::vector<vcg::Point3d> points(size_t(V.rows()));
    for (Eigen::Index i = 0; i < V.rows(); ++i) points[size_t(i)] = vcg::Point3d(V(i, 0), V(i, 1), V(i, 2));
    std::vector<int> corners(size_t(F.size()));
    for (Eigen::Index f = 0; f < F.rows(); ++f)
      for (int k = 0; k < 3; ++k) corners[size_t(3 * f + k)] = F(f, k);
    fill_tool_mesh(points, corners, mesh);
    write_parameterization(mesh, rows, result);
    if (!write_mesh(args.output, mesh, kTexture, error)) {
      std::cerr << "lowstretch: " << error << "\n";
      return kCannotWrite;
    }
    place_texture(args.output);
  }
  if (!args.svg.empty() && !draw_svg(args, F, result, error)) {
    std::cerr << "lowstretch: " << error << "\n";
    return kCannotWrite;
  }
  return kDone;
}
