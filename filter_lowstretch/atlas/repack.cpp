#include "atlas/repack.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <limits>
#include <numeric>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "atlas/base/used_vertices.h"
#include "atlas/bound/cut_invalid_charts.h"
#include "atlas/bound/split_until_bounded.h"
#include "atlas/chart_map/boundary_crossing.h"
#include "atlas/chart_map/free_charts.h"
#include "atlas/charts.h"
#include "atlas/measure/atlas_result.h"
#include "atlas/measure/valid_as_stored.h"
#include "core/stretch.h"
#include "core/union_find.h"

namespace lowstretch {

namespace {

Eigen::Vector2d uv_at(const Eigen::MatrixXd& corner_uv, Eigen::Index f, int k) { return corner_uv.block(f, 2 * k, 1, 2).transpose(); }

// Indices in range, used vertices and every UV finite.
Error check_input(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const Eigen::MatrixXd& corner_uv) {
  if (F.rows() == 0) return {ErrorCode::NoFaces, V.rows(), ""};
  if (corner_uv.rows() != F.rows() || corner_uv.cols() != 6) return {ErrorCode::NoTextureCoordinates, F.rows(), ""};
  long long out_of_range = 0, non_finite = 0, without_uv = 0;
  for (Eigen::Index f = 0; f < F.rows(); ++f) {
    if ((F.row(f).array() < 0).any() || (F.row(f).array() >= V.rows()).any()) {
      ++out_of_range;
      continue;
    }
    for (int k = 0; k < 3; ++k) non_finite += !V.row(F(f, k)).allFinite();
    without_uv += !corner_uv.row(f).allFinite();
  }
  if (out_of_range) return {ErrorCode::IndexOutOfRange, out_of_range, ""};
  if (non_finite) return {ErrorCode::NonFiniteCoordinates, non_finite, ""};
  if (without_uv) return {ErrorCode::NoTextureCoordinates, without_uv, ""};
  return {};
}

// The charts: faces joined where an edge's two corners have the same UV on both sides. Each
// chart's faces in input order, the charts in order of their first face.
std::vector<std::vector<int>> charts_of_uv(const Eigen::MatrixXi& F, const Eigen::MatrixXd& corner_uv) {
  std::vector<std::tuple<int, int, int, int>> edges;  // (lower vertex, higher vertex, face, corner)
  edges.reserve(size_t(3 * F.rows()));
  for (Eigen::Index f = 0; f < F.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int a = F(f, k), b = F(f, (k + 1) % 3);
      edges.emplace_back(std::min(a, b), std::max(a, b), int(f), k);
    }
  std::sort(edges.begin(), edges.end());
  const auto uv_of = [&](int f, int vertex) {
    for (int k = 0; k < 3; ++k)
      if (F(f, k) == vertex) return uv_at(corner_uv, f, k);
    return Eigen::Vector2d(Eigen::Vector2d::Constant(-1));
  };
  UnionFind joined(int(F.rows()));
  for (size_t first = 0, last = 0; first < edges.size(); first = last) {
    while (last < edges.size() && std::get<0>(edges[last]) == std::get<0>(edges[first]) &&
           std::get<1>(edges[last]) == std::get<1>(edges[first]))
      ++last;
    const int a = std::get<0>(edges[first]), b = std::get<1>(edges[first]);
    for (size_t i = first; i < last; ++i)
      for (size_t j = i + 1; j < last; ++j) {
        const int f = std::get<2>(edges[i]), g = std::get<2>(edges[j]);
        if (uv_of(f, a) == uv_of(g, a) && uv_of(f, b) == uv_of(g, b)) joined.unite(f, g);
      }
  }
  std::vector<int> chart_of_root(size_t(F.rows()), -1);
  std::vector<std::vector<int>> charts;
  for (int f = 0; f < int(F.rows()); ++f) {
    int& chart = chart_of_root[size_t(joined.find(f))];
    if (chart < 0) chart = int(charts.size()), charts.emplace_back();
    charts[size_t(chart)].push_back(f);
  }
  return charts;
}

// Whether the chart's UV is mirrored: its faces turn clockwise in UV, by area (as xatlas stores some
// charts), where the method's run counter-clockwise. Each of them would count as flipped.
bool is_mirrored(const ChartMesh& mesh, const Eigen::MatrixXd& uv) {
  double signed_area = 0;
  for (Eigen::Index j = 0; j < mesh.F.rows(); ++j) {
    const auto at = [&](int k) { return Eigen::Vector2d(uv.row(mesh.F(j, k)).transpose()); };
    signed_area += signed_uv_area(at(0), at(1), at(2));
  }
  return signed_area < 0;
}

// One chart as its UV gives it: a vertex per distinct (vertex, UV) corner, the UV its map; mirrored
// back if it is mirrored (the same stretch; its texture is to be made again for the new layout).
SolvedChart chart_of_uv(const Eigen::MatrixXd& unit_V, const Eigen::MatrixXi& F, const Eigen::MatrixXd& corner_uv,
                        std::vector<int> faces, bool& mirrored) {
  std::vector<std::tuple<int, double, double, int>> corners;  // (vertex, u, v, 3 * local face + k)
  for (size_t j = 0; j < faces.size(); ++j)
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector2d uv = uv_at(corner_uv, faces[j], k);
      corners.emplace_back(F(faces[j], k), uv.x(), uv.y(), int(3 * j) + k);
    }
  std::sort(corners.begin(), corners.end());
  SolvedChart chart;
  ChartMesh& mesh = chart.mesh;
  mesh.F.resize(Eigen::Index(faces.size()), 3);
  std::vector<int> vertex;
  std::vector<Eigen::Vector2d> uv;
  for (size_t i = 0; i < corners.size(); ++i) {
    const int v = std::get<0>(corners[i]), corner = std::get<3>(corners[i]);
    const Eigen::Vector2d at(std::get<1>(corners[i]), std::get<2>(corners[i]));
    if (vertex.empty() || v != vertex.back() || at != uv.back()) {
      vertex.push_back(v);
      uv.push_back(at);
    }
    mesh.F(corner / 3, corner % 3) = int(vertex.size()) - 1;
  }
  mesh.V.resize(Eigen::Index(vertex.size()), 3);
  chart.map.uv.resize(Eigen::Index(vertex.size()), 2);
  for (size_t i = 0; i < vertex.size(); ++i) {
    mesh.V.row(Eigen::Index(i)) = unit_V.row(vertex[i]);
    chart.map.uv.row(Eigen::Index(i)) = uv[i].transpose();
  }
  mesh.input_face = faces;
  mirrored = is_mirrored(mesh, chart.map.uv);
  if (mirrored) chart.map.uv.col(0) *= -1;
  chart.faces = std::move(faces);
  chart.free_boundary = true;  // its own outline, as given
  chart.kept_whole = "its texture coordinates were given";
  chart.fit_box();
  chart.kept = measure_real_faces(mesh, chart.map.uv);
  chart.passes = {chart.kept};
  return chart;
}

// The charts of the texture coordinates as the packing takes them: mirrored ones mirrored back;
// those with no UV area, or that overlap themselves (their boundary crosses itself, though no face
// need be flipped: a peer's chart can), charted again as the atlas charts a mesh (cut where they
// stretch beyond the bound, mapped free where that stretches less), or where that fails a chart
// per face (a face of no UV area among the flat ones, which the last step, valid_as_stored, gives
// a triangle of its own); charts of no 3D area onto a point (`flat`). Counts what it changed.
struct ReadCharts {
  std::vector<SolvedChart> charts;
  std::vector<int> flat;       // faces of charts with no 3D area: each chart on a point
  int read = 0;               // charts in the texture coordinates
  int mirrored = 0, overlapping = 0;
  long long collapsed = 0;     // faces of charts with 3D area but none in UV: no shape to keep
  bool any_uv = false;         // whether any chart with 3D area has UV area: an atlas to pack again
};
void chart_again(const Eigen::MatrixXd& unit_V, const Eigen::MatrixXi& F, const Eigen::MatrixXd& corner_uv,
                 const ChartOptions& options, const std::vector<std::vector<int>>& parts, ReadCharts& read) {
  std::vector<SolvedChart> charted, uncut;
  std::vector<std::string> notes;
  if (!split_until_bounded(unit_V, F, parts, options, charted, uncut, notes)) {
    free_where_it_stretches_less(charted, options);
    for (SolvedChart& chart : charted) read.charts.push_back(std::move(chart));
    return;
  }
  for (const std::vector<int>& faces : parts)
    for (const int f : faces) {
      bool mirrored = false;
      SolvedChart face = chart_of_uv(unit_V, F, corner_uv, {f}, mirrored);
      if (face.kept.area_3d > 0 && face.uv_area() > 0) read.charts.push_back(std::move(face));
      else read.flat.push_back(f);
    }
}
ReadCharts read_charts(const Eigen::MatrixXd& unit_V, const Eigen::MatrixXi& F, const Eigen::MatrixXd& corner_uv,
                       const ChartOptions& options) {
  ReadCharts read;
  std::vector<std::vector<int>> again;
  for (std::vector<int>& faces : charts_of_uv(F, corner_uv)) {
    bool mirrored = false;
    SolvedChart chart = chart_of_uv(unit_V, F, corner_uv, std::move(faces), mirrored);
    ++read.read;
    read.mirrored += mirrored;
    if (!(chart.kept.area_3d > 0)) {
      read.flat.insert(read.flat.end(), chart.faces.begin(), chart.faces.end());
    } else if (!(chart.uv_area() > 0)) {
      read.collapsed += (long long)chart.faces.size();
      again.push_back(chart.faces);
    } else {
      read.any_uv = true;
      if (!uv_boundary_crosses_itself(chart.mesh.F, chart.map.uv, std::numeric_limits<int>::max())) {
        read.charts.push_back(std::move(chart));
      } else {
        ++read.overlapping;
        again.push_back(chart.faces);
      }
    }
  }
  if (read.any_uv && !again.empty()) chart_again(unit_V, F, corner_uv, options, again, read);
  return read;
}

// The layout as given, its charts' bounding square onto [0,1]^2, measured and stored as a packing
// is; false where a chart comes closer than the new gutter to another, or a face is invalid.
bool layout_as_given(const std::vector<SolvedChart>& charts, const std::vector<int>& flat, const Eigen::MatrixXd& corner_uv,
                     const Eigen::MatrixXd& unit_V, const Eigen::MatrixXi& F, double unit, int vertex_rows,
                     const ChartOptions& options, ChartsResult& result) {
  Eigen::AlignedBox2d box;
  for (const SolvedChart& chart : charts)
    for (const int f : chart.faces)
      for (int k = 0; k < 3; ++k) box.extend(uv_at(corner_uv, f, k));
  const double side = box.sizes().maxCoeff();
  if (!(side > 0)) return false;
  ChartsResult laid_out;
  laid_out.corner_uv = Eigen::MatrixXd::Zero(F.rows(), 6);
  laid_out.face_chart.assign(size_t(F.rows()), -1);
  for (size_t c = 0; c < charts.size(); ++c)
    for (const int f : charts[c].faces) {
      laid_out.face_chart[size_t(f)] = int(c);
      for (int k = 0; k < 3; ++k) laid_out.corner_uv.block(f, 2 * k, 1, 2) = ((uv_at(corner_uv, f, k) - box.min()) / side).transpose();
    }
  result = stored_layout(charts, flat, std::move(laid_out), unit_V, F, unit, vertex_rows, options);
  measure_gutter(options, result);
  // Within the float rounding of stored texture coordinates (a few ulps of 1, in texels).
  const double rounding = 4 * options.texture_size * double(std::numeric_limits<float>::epsilon());
  return !result.error && result.least_gutter >= options.gutter - rounding &&
         without_specks(unit_V, F, result.corner_uv, invalid_faces(unit_V, F, result.corner_uv)).empty();
}

}  // namespace

ChartsResult repack_atlas(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const Eigen::MatrixXd& corner_uv,
                          const ChartOptions& options) {
  const Clock::time_point start = Clock::now();
  if (Error e = check_chart_options(options)) return failed_result(e);
  if (Error e = check_input(V, F, corner_uv)) return failed_result(e);
  double unit = 1;
  const Eigen::MatrixXd unit_V = unit_box_of_used(V, F, unit);
  ReadCharts read = read_charts(unit_V, F, corner_uv, options);
  std::vector<SolvedChart>& charts = read.charts;
  std::vector<int>& flat = read.flat;
  if (!read.any_uv) return failed_result({ErrorCode::NoTextureCoordinates, read.collapsed, ""});
  std::vector<StageSeconds> stages = {{"charts from texture coordinates", seconds_since(start)}};
  Clock::time_point stage = Clock::now();
  std::vector<int> all(charts.size());
  std::iota(all.begin(), all.end(), 0);
  ChartsResult as_given;
  // Not where a chart was charted again: the given layout holds its overlap or its collapse.
  const bool keeps_gutter = read.overlapping == 0 && read.collapsed == 0 &&
                            layout_as_given(charts, flat, corner_uv, unit_V, F, unit, int(V.rows()), options, as_given);
  ChartsResult result = atlas_of(std::move(charts), std::move(all), unit_V, F, unit, int(V.rows()), options, std::move(flat));
  if (result.error) return result;
  stages.push_back({"charts packed by outline", seconds_since(stage)});
  const std::string read_note = std::to_string(read.read) + " charts read from the texture coordinates";
  if (keeps_gutter && texture_efficiency(as_given) >= texture_efficiency(result)) {
    as_given.notes.insert(as_given.notes.begin(), read_note + " kept where they are, scaled: efficiency " +
                                                      number_text(texture_efficiency(as_given)) + " (coverage / L2^2) against " +
                                                      number_text(texture_efficiency(result)) + " packed again");
    result = std::move(as_given);
  } else {
    result.notes.insert(result.notes.begin(), read_note + " packed again");
  }
  const auto note = [&](long long count, const char* one, const char* many, const char* done) {
    if (count > 0) result.notes.insert(result.notes.begin() + 1, std::to_string(count) + (count == 1 ? one : many) + done);
  };
  note(read.collapsed, " face", " faces", " of charts with no area in the texture coordinates: charted again");
  note(read.overlapping, " chart overlapped itself", " charts overlapped themselves", " in the texture coordinates: charted again");
  note(read.mirrored, " chart was mirrored in the texture coordinates (its faces clockwise)",
       " charts were mirrored in the texture coordinates (their faces clockwise)", ": mirrored back");
  stage = Clock::now();
  result = valid_as_stored(unit_V, F, unit, int(V.rows()), options, std::move(result));
  measure_gutter(options, result);
  stages.push_back({"valid as stored", seconds_since(stage)});
  result.stage_seconds = std::move(stages);
  result.seconds_total = seconds_since(start);
  return result;
}

}  // namespace lowstretch
