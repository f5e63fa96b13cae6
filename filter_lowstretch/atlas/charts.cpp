#include "charts.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include "boundary_loops.h"
#include "close_holes.h"
#include "cut_graph.h"
#include "cut_mesh.h"
#include "disk_mesh.h"
#include "half_edges.h"
#include "mesh_components.h"
#include "stretch.h"

namespace lowstretch {

namespace {

using Clock = std::chrono::steady_clock;
const double kInf = std::numeric_limits<double>::infinity();

// The problems that charts solve; anything else (non-manifold, non-orientable, bad indices or
// coordinates) stays an error.
bool charts_can_fix(ErrorCode code) {
  return code == ErrorCode::SeveralComponents || code == ErrorCode::Closed || code == ErrorCode::SeveralBoundaryLoops ||
         code == ErrorCode::NotGenusZero;
}

// The used vertices moved into make_disk_mesh's unit box, so that huge coordinates do not
// overflow lengths and areas; `unit` converts lengths back to the input's units.
Eigen::MatrixXd unit_box_of_used(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, double& unit) {
  std::vector<char> used(static_cast<size_t>(V.rows()), 0);
  std::vector<int> rows;
  for (Eigen::Index f = 0; f < F.rows(); ++f)
    for (int k = 0; k < 3; ++k)
      if (!used[size_t(F(f, k))]) {
        used[size_t(F(f, k))] = 1;
        rows.push_back(F(f, k));
      }
  Eigen::MatrixXd points(Eigen::Index(rows.size()), 3);
  for (size_t i = 0; i < rows.size(); ++i) points.row(Eigen::Index(i)) = V.row(rows[i]);
  const UnitBox box = unit_box(points);
  unit = box.unit();
  Eigen::MatrixXd scaled = Eigen::MatrixXd::Zero(V.rows(), 3);
  for (int r : rows) scaled.row(r) = box.map(V.row(r));
  return scaled;
}

double triangle_area(const Eigen::MatrixXd& V, int a, int b, int c) {
  const Eigen::Vector3d p = V.row(a), q = V.row(b), r = V.row(c);
  return 0.5 * (q - p).cross(r - p).norm();
}

// One component made into a disk: its faces first (in input order), then the virtual faces
// that close its holes.
struct ChartMesh {
  Eigen::MatrixXd V;
  Eigen::MatrixXi F;
  std::vector<int> input_face;  // real face -> input face
  int closed_holes = 0;
  double seam_length = 0;       // in unit-box lengths
};

// local_of: -1 for every vertex, and left so (one array for all components keeps many small
// components linear in time).
Error make_chart_mesh(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const std::vector<int>& faces,
                      std::vector<int>& local_of, ChartMesh& chart) {
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
  const Error e = make_disk_mesh(local_V, local_F, check);
  if (e && !charts_can_fix(e.code)) return e;

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
  return {};
}

// A solved chart, scaled so that its UV area equals its 3D area (uniform texel density).
struct SolvedChart {
  std::vector<Eigen::Vector2d> corners;  // 3 per real face
  Eigen::AlignedBox2d box;
};

SolvedChart scale_by_area(const ChartMesh& chart, const Result& r) {
  SolvedChart solved;
  double area_3d = 0, area_uv = 0;
  for (size_t j = 0; j < chart.input_face.size(); ++j) {
    const int a = chart.F(Eigen::Index(j), 0), b = chart.F(Eigen::Index(j), 1), c = chart.F(Eigen::Index(j), 2);
    area_3d += triangle_area(chart.V, a, b, c);
    area_uv += std::abs(signed_uv_area(r.uv.row(a), r.uv.row(b), r.uv.row(c)));
    for (int v : {a, b, c}) solved.corners.push_back(r.uv.row(v).transpose());
  }
  const double scale = area_uv > 0 && area_3d > 0 ? std::sqrt(area_3d / area_uv) : 1.0;
  for (Eigen::Vector2d& p : solved.corners) {
    p *= scale;
    solved.box.extend(p);
  }
  return solved;
}

// One pass of one chart, over its real faces (the faces closing holes are not the mesh's).
struct ChartPass {
  double area_3d = 0, l2_stretch = 0;
  int flipped = 0, degenerate = 0;
};
ChartPass measure_real_faces(const ChartMesh& chart, const Eigen::MatrixXd& uv) {
  const Eigen::Index real = Eigen::Index(chart.input_face.size());
  const FaceStretch s = face_stretch(chart.V, chart.F.topRows(real), uv);
  return {s.area_3d.sum(), l2_stretch(s), s.flipped, s.degenerate};
}

// L2 stretch of the whole layout from the charts' own: with every chart at one texel density,
// L2^2 is the 3D-area-weighted mean of the charts' normalized L2^2.
std::vector<LayoutPass> layout_passes(const std::vector<std::vector<ChartPass>>& passes, const std::vector<int>& kept) {
  size_t most = 0;
  for (const auto& p : passes) most = std::max(most, p.size());
  std::vector<LayoutPass> layout(most);
  for (size_t k = 0; k < most; ++k) {
    double weighted = 0, area = 0;
    layout[k].pass = int(k);
    for (size_t c = 0; c < passes.size(); ++c) {
      const ChartPass& p = k < passes[c].size() ? passes[c][k] : passes[c][size_t(kept[c])];
      layout[k].flipped += p.flipped;
      layout[k].degenerate += p.degenerate;
      weighted += p.area_3d * p.l2_stretch * p.l2_stretch;
      area += p.area_3d;
    }
    const bool bad = layout[k].flipped + layout[k].degenerate > 0 || !(area > 0);
    layout[k].l2_stretch = bad ? kInf : std::sqrt(weighted / area);
  }
  return layout;
}

Error check_texture_options(const ChartOptions& o) {
  if (o.texture_size < 8 || o.texture_size > 65536)
    return {ErrorCode::InvalidOption, 0, "must be from 8 to 65536, got " + std::to_string(o.texture_size), "texture_size"};
  if (!(o.gutter >= 0.5 && o.gutter <= o.texture_size / 8.0))
    return {ErrorCode::InvalidOption, 0, "must be from 0.5 to an eighth of the texture size (" +
                                             number_text(o.texture_size / 8.0) + "), got " + number_text(o.gutter),
            "gutter"};
  return {};
}

// Moves a layout of [0,1]^2 uniformly into [g, 1 - g]^2, g = gutter / texture_size.
void keep_inside_gutter(const ChartOptions& o, Eigen::MatrixXd& corner_uv) {
  const double g = o.gutter / o.texture_size;
  corner_uv = (corner_uv.array() * (1 - 2 * g) + g).matrix();
}

ChartsResult failed(Error error) {
  ChartsResult result;
  result.error = std::move(error);
  return result;
}

// A disk as one chart: parameterize's map and pass history; measured later, like a layout.
ChartsResult from_disk(const Eigen::MatrixXi& F, Result disk) {
  ChartsResult result;
  result.input_is_disk = true;
  result.corner_uv.resize(F.rows(), 6);
  for (Eigen::Index f = 0; f < F.rows(); ++f)
    for (int k = 0; k < 3; ++k) result.corner_uv.block(f, 2 * k, 1, 2) = disk.uv.row(F(f, k));
  result.face_chart.assign(size_t(F.rows()), 0);
  for (const PassMetrics& p : disk.passes) result.passes.push_back({p.pass, p.l2_stretch, p.flipped, p.degenerate});
  Chart chart;
  chart.faces = int(F.rows());
  chart.chosen_pass = disk.chosen_pass;
  chart.passes = int(disk.passes.size());
  result.charts.push_back(chart);
  result.seconds_total = disk.seconds_total;
  result.notes = std::move(disk.notes);
  result.disk_passes = std::move(disk.passes);
  result.chosen_pass = disk.chosen_pass;
  result.stop_reason = disk.stop_reason;
  return result;
}

// Every component as a chart: its mesh (holes closed, cut open), the method on it, every pass
// measured over its real faces; fills result.charts, seam_length, notes and passes.
Error solve_charts(const Eigen::MatrixXd& unit_V, const Eigen::MatrixXi& F, double unit,
                   const std::vector<std::vector<int>>& faces_of, const Options& disk_options,
                   std::vector<SolvedChart>& solved, ChartsResult& result) {
  const int count = int(faces_of.size());
  std::vector<int> local_of(static_cast<size_t>(unit_V.rows()), -1);
  std::vector<std::vector<ChartPass>> chart_passes(static_cast<size_t>(count));
  std::vector<int> kept;
  for (int c = 0; c < count; ++c) {
    ChartMesh mesh;
    if (Error e = make_chart_mesh(unit_V, F, faces_of[size_t(c)], local_of, mesh)) return e;
    Options chart_options = disk_options;
    if (disk_options.progress)
      chart_options.progress = [&disk_options, c, count](double fraction, const char* stage) {
        return disk_options.progress((c + fraction) / (count + 0.1), stage);
      };
    std::vector<ChartPass>& passes = chart_passes[size_t(c)];
    chart_options.pass_uv = [&mesh, &passes](int, const Eigen::MatrixXd& uv) { passes.push_back(measure_real_faces(mesh, uv)); };
    const Result r = parameterize(mesh.V, mesh.F, chart_options);
    if (r.error) return r.error;
    kept.push_back(r.chosen_pass);
    solved.push_back(scale_by_area(mesh, r));
    Chart chart;
    chart.faces = int(mesh.input_face.size());
    chart.closed_holes = mesh.closed_holes;
    chart.seam_length = mesh.seam_length * unit;
    chart.chosen_pass = r.chosen_pass;
    chart.passes = int(r.passes.size());
    result.charts.push_back(chart);
    result.seam_length += chart.seam_length;
    for (const std::string& note : r.notes) result.notes.push_back("chart " + std::to_string(c) + ": " + note);
  }
  result.passes = layout_passes(chart_passes, kept);
  return {};
}

// Packs the charts' boxes, places every corner, then moves and scales the whole layout uniformly
// into [0,1]^2; fills result.corner_uv and face_chart.
Error lay_out(std::vector<SolvedChart>& solved, const std::vector<std::vector<int>>& faces_of, Eigen::Index face_count,
              const ChartPacker& pack, ChartsResult& result) {
  std::vector<Eigen::AlignedBox2d> boxes;
  for (const SolvedChart& s : solved) boxes.push_back(s.box);
  std::vector<ChartPlacement> placements;
  if (!pack(boxes, placements) || placements.size() != boxes.size())
    return {ErrorCode::ChartsNotPacked, static_cast<long long>(boxes.size()), ""};
  Eigen::AlignedBox2d layout_box;
  for (size_t c = 0; c < solved.size(); ++c)
    for (Eigen::Vector2d& p : solved[c].corners) {
      p = placements[c].scale * p + placements[c].offset;
      layout_box.extend(p);
    }
  const double side = layout_box.sizes().maxCoeff();
  result.corner_uv.resize(face_count, 6);
  result.face_chart.assign(size_t(face_count), 0);
  for (size_t c = 0; c < solved.size(); ++c)
    for (size_t j = 0; j < faces_of[c].size(); ++j) {
      const int f = faces_of[c][j];
      result.face_chart[size_t(f)] = int(c);
      for (int k = 0; k < 3; ++k) {
        const Eigen::Vector2d p = (solved[c].corners[3 * j + size_t(k)] - layout_box.min()) / (side > 0 ? side : 1);
        result.corner_uv.block(f, 2 * k, 1, 2) = p.cwiseMax(0.0).cwiseMin(1.0).transpose();
      }
    }
  return {};
}

// The layout measured like a disk's pass, as a mesh of its own: three vertices per face, and an
// edge for every pair of corners that is one edge of the input and one edge of the layout.
void measure_layout(const Eigen::MatrixXd& unit_V, const Eigen::MatrixXi& F, int vertex_rows,
                    const std::vector<std::vector<int>>& faces_of, ChartsResult& result) {
  Eigen::MatrixXd corner_V(3 * F.rows(), 3), corner_uv(3 * F.rows(), 2);
  Eigen::MatrixXi corner_F(F.rows(), 3);
  for (Eigen::Index f = 0; f < F.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      corner_V.row(3 * f + k) = unit_V.row(F(f, k));
      corner_F(f, k) = int(3 * f + k);
      corner_uv.row(3 * f + k) = result.corner_uv.block(f, 2 * k, 1, 2);
    }
  std::vector<std::array<int, 2>> edges;
  const std::vector<int> twin = opposite_half_edges(F);
  for (int h = 0; h < int(twin.size()); ++h) {
    const int t = twin[size_t(h)];
    const bool joined = t >= 0 && result.face_chart[size_t(h / 3)] == result.face_chart[size_t(t / 3)] &&
                        corner_uv.row(h) == corner_uv.row(next_half_edge(t)) &&
                        corner_uv.row(next_half_edge(h)) == corner_uv.row(t);
    if (!joined || h < t) edges.push_back({h, next_half_edge(h)});
  }
  Eigen::MatrixXi corner_edges(Eigen::Index(edges.size()), 2);
  for (size_t e = 0; e < edges.size(); ++e) corner_edges.row(Eigen::Index(e)) << edges[e][0], edges[e][1];
  const FaceStretch s = face_stretch(corner_V, corner_F, corner_uv);
  result.layout = measure(corner_V, corner_F, corner_edges, corner_uv, s);
  result.coverage = s.area_uv.cwiseAbs().sum();
  result.face_stretch.resize(F.rows());
  for (Eigen::Index f = 0; f < F.rows(); ++f) result.face_stretch(f) = s.valid(f) ? s.normalization * s.sigma(f) : kInf;
  result.vertex_stretch = vertex_stretch(F, vertex_rows, s);
  std::vector<char> used(size_t(vertex_rows), 0);
  for (Eigen::Index f = 0; f < F.rows(); ++f)
    for (int k = 0; k < 3; ++k) used[size_t(F(f, k))] = 1;
  for (int v = 0; v < vertex_rows; ++v)
    if (!used[size_t(v)]) result.vertex_stretch(v) = 0;
  for (size_t c = 0; c < faces_of.size(); ++c) result.charts[c].l2_stretch = l2_stretch(s, faces_of[c]);
}

// The measures of `from` (stretch, distortions, flips) into `to`, whose pass and timings stay.
void copy_measures(const PassMetrics& from, PassMetrics& to) {
  to.l2_stretch = from.l2_stretch;
  to.linf_stretch = from.linf_stretch;
  to.edge_distortion = from.edge_distortion;
  to.angle_distortion = from.angle_distortion;
  to.area_distortion = from.area_distortion;
  to.flipped = from.flipped;
  to.degenerate = from.degenerate;
}

double corner_area(const Eigen::MatrixXd& corner_uv, Eigen::Index f) {
  const auto c = [&](int k) { return Eigen::Vector2d(corner_uv.block(f, 2 * k, 1, 2).transpose()); };
  return signed_uv_area(c(0), c(1), c(2));
}

// The layout as MeshLab stores it: inside the gutter, rounded to float, then measured; counts
// the triangles no texture shows (smaller than a texel of 4096^2) and those that rounding flips or
// collapses (a note).
void store(const Eigen::MatrixXd& unit_V, const Eigen::MatrixXi& F, int vertex_rows,
           const std::vector<std::vector<int>>& faces_of, const ChartOptions& options, ChartsResult& result) {
  keep_inside_gutter(options, result.corner_uv);
  std::vector<char> positive(size_t(F.rows()));
  for (Eigen::Index f = 0; f < F.rows(); ++f) positive[size_t(f)] = corner_area(result.corner_uv, f) > 0;
  result.corner_uv = result.corner_uv.cast<float>().cast<double>();
  const double texel = 1.0 / (4096.0 * 4096.0);
  for (Eigen::Index f = 0; f < F.rows(); ++f) {
    const double area = corner_area(result.corner_uv, f);
    result.subtexel_triangles += std::abs(area) < texel;
    result.float_collapsed += positive[size_t(f)] && !(area > 0);
  }
  if (result.float_collapsed > 0)
    result.notes.push_back(std::to_string(result.float_collapsed) +
                           " UV triangles flip or collapse when their texture coordinates are rounded to float, "
                           "as MeshLab stores them: the metrics count them");
  measure_layout(unit_V, F, vertex_rows, faces_of, result);
}

}  // namespace

ChartsResult parameterize_charts(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const ChartOptions& options,
                                 const ChartPacker& pack) {
  const Clock::time_point start = Clock::now();
  if (Error e = check_texture_options(options)) return failed(e);
  Result whole = parameterize(V, F, options.disk);
  if (!whole.error) {
    ChartsResult result = from_disk(F, std::move(whole));
    double unit = 1;
    std::vector<int> all(static_cast<size_t>(F.rows()));
    for (Eigen::Index f = 0; f < F.rows(); ++f) all[size_t(f)] = int(f);
    store(unit_box_of_used(V, F, unit), F, int(V.rows()), {all}, options, result);
    // The layout is the kept pass, as stored: its number, timings and solver stay.
    const PassMetrics measured = result.layout;
    result.layout = result.disk_passes.at(size_t(result.chosen_pass));
    copy_measures(measured, result.layout);
    result.seconds_total = std::chrono::duration<double>(Clock::now() - start).count();
    return result;
  }
  if (options.non_disk == NonDisk::Reject || !charts_can_fix(whole.error.code)) return failed(whole.error);
  if (!pack) return failed({ErrorCode::InvalidOption, 0, "charts need a packer"});

  // parameterize checked indices, coordinates, edges and orientation of the whole mesh before it
  // found the topology wrong; vertex fans are checked per component and between components.
  int count = 0;
  const std::vector<int> component = face_components(F, count);
  if (const int shared = vertices_shared_by_components(F, int(V.rows()), component))
    return failed({ErrorCode::NonManifoldVertices, shared, ""});
  std::vector<std::vector<int>> faces_of(static_cast<size_t>(count));
  for (Eigen::Index f = 0; f < F.rows(); ++f) faces_of[size_t(component[size_t(f)])].push_back(int(f));

  double unit = 1;
  const Eigen::MatrixXd unit_V = unit_box_of_used(V, F, unit);
  ChartsResult result;
  std::vector<SolvedChart> solved;
  if (Error e = solve_charts(unit_V, F, unit, faces_of, options.disk, solved, result)) return failed(e);
  if (Error e = lay_out(solved, faces_of, F.rows(), pack, result)) return failed(e);
  store(unit_V, F, int(V.rows()), faces_of, options, result);
  result.seconds_total = std::chrono::duration<double>(Clock::now() - start).count();
  result.layout.seconds = result.seconds_total;
  return result;
}

const char* to_string(NonDisk non_disk) {
  switch (non_disk) {
    case NonDisk::Reject: return "reject";
    case NonDisk::Charts: return "charts";
  }
  return "?";
}

}  // namespace lowstretch
