#include "atlas/chart_map/solved_chart.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "atlas/base/tuning.h"
#include "atlas/chart_map/chart_rectangle.h"
#include "core/boundary_loops.h"
#include "atlas/cut/close_holes.h"
#include "atlas/cut/cut_graph.h"
#include "atlas/cut/cut_mesh.h"
#include "core/disk_mesh.h"
#include "core/half_edges.h"
#include "atlas/cut/split_vertex_fans.h"
#include "core/stretch.h"

namespace lowstretch {

namespace {

const double kInf = std::numeric_limits<double>::infinity();

// Fewer flipped and zero-area triangles first, then lower L2 stretch (as parameterize ranks passes).
bool better_pass(const ChartPass& a, const ChartPass& b) {
  return std::make_pair(a.flipped + a.degenerate, a.l2_stretch) < std::make_pair(b.flipped + b.degenerate, b.l2_stretch);
}

}  // namespace

void SolvedChart::fit_box() {
  box.setEmpty();
  for (size_t j = 0; j < faces.size(); ++j)
    for (int k = 0; k < 3; ++k) box.extend(map.uv.row(mesh.F(Eigen::Index(j), k)).transpose());
}

double SolvedChart::uv_area() const {
  double area = 0;
  for (size_t j = 0; j < faces.size(); ++j) {
    const auto corner = [&](int k) { return Eigen::Vector2d(map.uv.row(mesh.F(Eigen::Index(j), k)).transpose()); };
    area += std::abs(signed_uv_area(corner(0), corner(1), corner(2)));
  }
  return area;
}

double SolvedChart::fill() const { return box.volume() > 0 ? std::min(1.0, uv_area() / box.volume()) : 0; }

bool cutting_into_disks_fixes(ErrorCode code) {
  return code == ErrorCode::SeveralComponents || code == ErrorCode::Closed || code == ErrorCode::SeveralBoundaryLoops ||
         code == ErrorCode::NotGenusZero;
}

Error make_chart_mesh(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const std::vector<int>& faces,
                      std::vector<int>& local_of, ChartMesh& chart) {
  chart.prepared.reset();
  std::vector<int> input_vertex;
  Eigen::MatrixXi local_F(Eigen::Index(faces.size()), 3);
  for (size_t j = 0; j < faces.size(); ++j)
    for (int k = 0; k < 3; ++k) {
      int& l = local_of[size_t(F(faces[j], k))];
      if (l < 0) {
        l = int(input_vertex.size());
        input_vertex.push_back(F(faces[j], k));
      }
      local_F(Eigen::Index(j), k) = l;
    }
  Eigen::MatrixXd local_V(Eigen::Index(input_vertex.size()), 3);
  for (size_t i = 0; i < input_vertex.size(); ++i) {
    local_V.row(Eigen::Index(i)) = V.row(input_vertex[i]);
    local_of[size_t(input_vertex[i])] = -1;
  }

  DiskMesh check;
  Error e = make_disk_mesh(local_V, local_F, check);
  if (e.code == ErrorCode::NonManifoldVertices) {
    // A cut that passes a hole can leave faces that meet at one vertex only: each fan gets its
    // own copy of it, or a chart with many small holes may find no cut into disks. Parts held
    // together by that vertex alone stay refused.
    SplitFans split = split_vertex_fans(local_V, local_F);
    local_V = std::move(split.V);
    local_F = std::move(split.F);
    e = make_disk_mesh(local_V, local_F, check);
    if (e.code == ErrorCode::SeveralComponents) return e;
  }
  if (e && !cutting_into_disks_fixes(e.code)) return e;

  const int real_vertices = int(local_V.rows());
  const std::vector<std::vector<int>> loops = boundary_loops(local_F, opposite_half_edges(local_F), real_vertices);
  std::vector<int> outer;
  if (!loops.empty()) {
    const size_t keep = longest_loop(local_V, loops);
    outer = loops[keep];
    close_holes(local_V, local_F, loops, keep);
    chart.closed_holes = int(loops.size()) - 1;
  }
  const std::vector<std::array<int, 2>> seams = cut_graph(local_V, local_F, outer);
  for (const auto& s : seams)
    if (s[0] < real_vertices && s[1] < real_vertices) chart.seam_length += (local_V.row(s[0]) - local_V.row(s[1])).norm();
  const CutMesh cut = cut_along(local_F, seams);
  chart.F = cut.F;
  chart.V.resize(Eigen::Index(cut.original_vertex.size()), 3);
  for (size_t i = 0; i < cut.original_vertex.size(); ++i) chart.V.row(Eigen::Index(i)) = local_V.row(cut.original_vertex[i]);
  chart.input_face = faces;
  chart.prepared = std::make_shared<LazyPreparedDisk>();
  return {};
}

ChartPass measure_real_faces(const ChartMesh& chart, const Eigen::MatrixXd& uv) {
  const Eigen::Index real = Eigen::Index(chart.input_face.size());
  const FaceStretch s = face_stretch(chart.V, chart.F.topRows(real), uv);
  return {s.area_3d.sum(), l2_stretch(s), s.flipped, s.degenerate, l2_stretch(s, true)};
}

double texture_cost(const SolvedChart& chart) {
  const ChartPass& p = chart.kept;
  const double fill = chart.mesh.closed_holes > 0 ? chart.fill() : 1;
  return p.flipped + p.degenerate > 0 || !(fill > 0) ? kInf : p.area_3d * p.l2_stretch * p.l2_stretch / fill;
}

bool needs_split(const ChartPass& p, double max_stretch) {
  return p.flipped + p.degenerate > 0 || !(p.l2_stretch <= max_stretch);
}

bool bound_cuts(const SolvedChart& chart, double max_stretch) {
  return needs_split(chart.kept, max_stretch) || texture_cost(chart) > chart.kept.area_3d * max_stretch * max_stretch;
}

namespace {

// The method on the chart's mesh: onto its rectangle (chart_rectangle.h), or with the natural
// boundary. The rectangle's notes come first, where the core's square puts its own.
Result map_chart(const ChartMesh& mesh, Options options, double aspect, bool free_boundary) {
  Result map;
  PreparedDisk own;
  const PreparedDisk& prepared = mesh.prepared ? mesh.prepared->get(mesh.V, mesh.F, options.weights, map.error) : own;
  if (!mesh.prepared) map.error = prepare_disk(mesh.V, mesh.F, options.weights, own);
  if (map.error) return map;
  const DiskMesh& disk = prepared.disk;
  std::vector<std::string> notes;
  if (free_boundary) {
    options.boundary = BoundaryShape::Natural;
  } else {
    const Eigen::MatrixXd loop_uv = chart_rectangle(disk, {aspect, kTuning.ear_bulge}, notes);
    options.boundary = BoundaryShape::Given;
    options.given_boundary = Eigen::MatrixXd::Zero(mesh.V.rows(), 2);
    for (size_t i = 0; i < disk.boundary.size(); ++i)
      options.given_boundary.row(disk.input_vertex[size_t(disk.boundary[i])]) = loop_uv.row(Eigen::Index(i));
  }
  map = parameterize(prepared, mesh.V.rows(), options);
  if (!map.error) map.notes.insert(map.notes.begin(), notes.begin(), notes.end());
  return map;
}

}  // namespace

void solve_onto(SolvedChart& chart, Options options, double aspect, bool free_boundary) {
  options.progress = nullptr;  // called from worker threads: the caller reports between rounds
  options.solver.amg_minimum_rows = std::max(options.solver.amg_minimum_rows, kTuning.chart_amg_minimum_rows);
  chart.free_boundary = free_boundary;
  chart.deciding_map = false;
  chart.passes.clear();
  options.pass_uv = [&chart](int, const Eigen::MatrixXd& uv) { chart.passes.push_back(measure_real_faces(chart.mesh, uv)); };
  options.measure_distortions = false;  // the passes are measured over the real faces above
  chart.map = map_chart(chart.mesh, options, aspect, free_boundary);
  if (chart.map.error) return;
  // A refined map is none of the passes: measured on its own.
  if (options.refine) chart.passes.at(size_t(chart.map.chosen_pass)) = measure_real_faces(chart.mesh, chart.map.uv);
  chart.kept = chart.passes.at(size_t(chart.map.chosen_pass));
  chart.fit_box();
}

void solve_chart(SolvedChart& chart, const Options& options, double aspect, double square_below) {
  solve_onto(chart, options, aspect);
  if (chart.map.error.code == ErrorCode::SolverFailed && options.max_passes > 0) {
    // A pass whose weights overflow on a tiny part: the initial map, which no weight breaks.
    Options initial = options;
    initial.max_passes = 0;
    solve_onto(chart, initial, aspect);
  }
  if (aspect != 0 || chart.map.error || std::abs(std::log(chart.aspect())) < 0.02) return;
  if (!(chart.kept.l2_stretch <= square_below)) return;
  SolvedChart square;
  square.mesh = chart.mesh;  // small beside the solve
  square.faces = chart.faces;
  solve_onto(square, options, 1);
  if (!square.map.error && better_pass(square.kept, chart.kept)) chart = std::move(square);
}

}  // namespace lowstretch
