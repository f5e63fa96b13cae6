#include "atlas/measure/atlas_result.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>

#include "atlas/base/tuning.h"
#include "atlas/bound/cut_invalid_charts.h"
#include "core/half_edges.h"
#include "atlas/pack/lay_out_charts.h"
#include "core/stretch.h"

namespace lowstretch {

namespace {

const double kInf = std::numeric_limits<double>::infinity();

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

// Moves a layout of [0,1]^2 uniformly into [g, 1 - g]^2, g = gutter / texture_size.
void keep_inside_gutter(const ChartOptions& o, Eigen::MatrixXd& corner_uv) {
  const double g = o.gutter / o.texture_size;
  corner_uv = (corner_uv.array() * (1 - 2 * g) + g).matrix();
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
  result.l2_of_valid = l2_stretch(s, true);
  result.face_stretch.resize(F.rows());
  for (Eigen::Index f = 0; f < F.rows(); ++f) result.face_stretch(f) = s.valid(f) ? s.normalization * s.sigma(f) : kInf;
  result.vertex_stretch = vertex_stretch(F, vertex_rows, s);
  std::vector<char> used(size_t(vertex_rows), 0);
  for (Eigen::Index f = 0; f < F.rows(); ++f)
    for (int k = 0; k < 3; ++k) used[size_t(F(f, k))] = 1;
  for (int v = 0; v < vertex_rows; ++v)
    if (!used[size_t(v)]) result.vertex_stretch(v) = 0;
  for (size_t c = 0; c < faces_of.size(); ++c) {
    double area_3d = 0, area_uv = 0, linf = 0;
    for (int f : faces_of[c]) {
      area_3d += s.area_3d(f);
      area_uv += std::abs(s.area_uv(f));
      linf = std::max(linf, s.valid(f) ? s.gamma(f) : kInf);
    }
    result.charts[c].l2_stretch = l2_stretch(s, faces_of[c]);
    result.charts[c].linf_stretch = area_3d > 0 ? std::sqrt(area_uv / area_3d) * linf : kInf;
  }
}

// "chart 3", "charts 1, 4, 9", "charts 1, 4, 9 and 812 more".
std::string charts_text(const std::vector<int>& charts) {
  std::string text = charts.size() == 1 ? "chart " : "charts ";
  for (size_t i = 0; i < charts.size() && i < 3; ++i) text += (i ? ", " : "") + std::to_string(charts[i]);
  if (charts.size() > 3) text += " and " + std::to_string(charts.size() - 3) + " more";
  return text;
}

}  // namespace

// 3D length of the edges whose two faces are in different charts.
double length_between_charts(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const std::vector<int>& face_chart) {
  const std::vector<int> twin = opposite_half_edges(F);
  double length = 0;
  for (int h = 0; h < int(twin.size()); ++h) {
    const int t = twin[size_t(h)];
    if (t > h && face_chart[size_t(h / 3)] != face_chart[size_t(t / 3)])
      length += (V.row(half_edge_tail(F, h)) - V.row(half_edge_head(F, h))).norm();
  }
  return length;
}

ChartsResult failed_result(Error error) {
  ChartsResult result;
  result.error = std::move(error);
  return result;
}

void copy_measures(const PassMetrics& from, PassMetrics& to) {
  to.l2_stretch = from.l2_stretch;
  to.linf_stretch = from.linf_stretch;
  to.edge_distortion = from.edge_distortion;
  to.angle_distortion = from.angle_distortion;
  to.area_distortion = from.area_distortion;
  to.flipped = from.flipped;
  to.degenerate = from.degenerate;
}

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
    result.float_collapsed += positive[size_t(f)] && !(area > 0) && !is_flat_face(unit_V, F, f);
  }
  if (result.float_collapsed > 0)
    result.notes.push_back(std::to_string(result.float_collapsed) +
                           " UV triangles flip or collapse when their texture coordinates are rounded to float, "
                           "as MeshLab stores them: the metrics count them");
  measure_layout(unit_V, F, vertex_rows, faces_of, result);
}

namespace {

// A chart's summary before it is measured in the layout.
Chart chart_summary(const SolvedChart& c, double unit) {
  Chart chart;
  chart.kept_whole = c.kept_whole ? c.kept_whole : "its cell's shape stretched it";
  chart.faces = int(c.faces.size());
  chart.closed_holes = c.mesh.closed_holes;
  chart.seam_length = c.mesh.seam_length * unit;
  chart.chosen_pass = c.map.chosen_pass;
  chart.passes = int(c.map.passes.size());
  return chart;
}

// One note for all counts and measures: "6 interior edges ..." -> "some interior edges ...", and
// parameterize's "refined: L2 stretch 1.3 -> 1.2 in ..." -> "refined: L2 stretch lowered".
std::string without_count(const std::string& note) {
  if (note.rfind("refined: ", 0) == 0) return "refined: L2 stretch lowered";
  const size_t digits = note.find_first_not_of("0123456789");
  return digits > 0 && digits != std::string::npos && note[digits] == ' ' ? "some" + note.substr(digits) : note;
}

// Notes, each once with the charts it was given for.
struct NoteGroups {
  std::vector<std::string> notes;
  std::vector<std::vector<int>> charts;
  void add(const std::string& note, int chart) {
    const size_t k = size_t(std::find(notes.begin(), notes.end(), note) - notes.begin());
    if (k == notes.size()) {
      notes.push_back(note);
      charts.emplace_back();
    }
    charts[k].push_back(chart);
  }
};

// Every chart above the bound is one note while they are few; past that, one note per reason.
void note_charts_above_bound(size_t chart_count, double max_stretch, ChartsResult& result) {
  std::vector<int> above;
  for (size_t c = 0; c < chart_count; ++c) {
    Chart& chart = result.charts[c];
    chart.above_bound = !(chart.l2_stretch <= max_stretch);
    if (chart.above_bound) above.push_back(int(c));
  }
  const size_t listed = 10;
  for (size_t k = 0; k < above.size() && (above.size() <= listed || k < listed); ++k) {
    const Chart& chart = result.charts[size_t(above[k])];
    result.notes.push_back("chart " + std::to_string(above[k]) + " (" + std::to_string(chart.faces) + " faces) keeps L2 stretch " +
                           number_text(chart.l2_stretch) + " above " + number_text(max_stretch) + ": " + chart.kept_whole);
  }
  if (above.size() <= listed) return;
  NoteGroups reasons;
  for (int c : above) reasons.add(result.charts[size_t(c)].kept_whole, c);
  for (size_t k = 0; k < reasons.notes.size(); ++k)
    result.notes.push_back(charts_text(reasons.charts[k]) + " keep an L2 stretch above " + number_text(max_stretch) + ": " +
                           reasons.notes[k]);
}

// One layout of the charts, measured (stored_layout). After a cut, a layout by outline keeps the
// charts that were not cut where the last one put them (last_uv, was: lay_out_around) if the
// pieces find room: a whole packing searches its density again. Each layout by outline is kept in
// last_uv.
ChartsResult lay_out_and_store(std::vector<SolvedChart>& charts, const std::vector<int>& guests, const std::vector<int>& flat,
                               const Eigen::MatrixXd& unit_V, const Eigen::MatrixXi& F, double unit, int vertex_rows,
                               const ChartOptions& options, double& outline_density, Eigen::MatrixXd& last_uv,
                               const std::vector<int>& was) {
  ChartsResult result;
  const bool by_outline = !charts.empty() && guests.size() == charts.size();
  const bool around = by_outline && last_uv.rows() == F.rows() && was.size() == charts.size() &&
                      lay_out_around(charts, options, last_uv, was, result);
  if (!around)
    if (Error e = lay_out(charts, options, F.rows(), guests, result, outline_density)) return failed_result(e);
  if (by_outline) last_uv = result.corner_uv;
  return stored_layout(charts, flat, std::move(result), unit_V, F, unit, vertex_rows, options);
}

}  // namespace

ChartsResult stored_layout(const std::vector<SolvedChart>& charts, const std::vector<int>& flat, ChartsResult result,
                           const Eigen::MatrixXd& unit_V, const Eigen::MatrixXi& F, double unit, int vertex_rows,
                           const ChartOptions& options) {
  std::vector<std::vector<int>> faces_of;
  std::vector<std::vector<ChartPass>> passes;
  std::vector<int> kept;
  NoteGroups chart_notes;
  for (const SolvedChart& c : charts) {
    result.charts.push_back(chart_summary(c, unit));
    result.seam_length += result.charts.back().seam_length;
    for (const std::string& note : c.map.notes) chart_notes.add(without_count(note), int(faces_of.size()));
    faces_of.push_back(c.faces);
    passes.push_back(c.passes);
    kept.push_back(c.map.chosen_pass);
  }
  if (!flat.empty()) {
    Chart points;
    points.faces = int(flat.size());
    for (const int f : flat) {
      result.face_chart[size_t(f)] = int(result.charts.size());
      result.corner_uv.row(f).setZero();
    }
    result.charts.push_back(points);
  }
  result.passes = layout_passes(passes, kept);
  result.seam_length += unit * length_between_charts(unit_V, F, result.face_chart);
  store(unit_V, F, vertex_rows, faces_of, options, result);
  for (size_t k = 0; k < chart_notes.notes.size(); ++k)
    result.notes.push_back(charts_text(chart_notes.charts[k]) + ": " + chart_notes.notes[k]);
  note_charts_above_bound(faces_of.size(), options.max_stretch, result);
  return result;
}

ChartsResult atlas_of(std::vector<SolvedChart> charts, std::vector<int> guests, const Eigen::MatrixXd& unit_V,
                      const Eigen::MatrixXi& F, double unit, int vertex_rows, const ChartOptions& options,
                      std::vector<int> flat) {
  size_t cut = 0;  // charts cut where their map was invalid
  double outline_density = 0;  // a round after a cut starts packing at the last round's density
  Eigen::MatrixXd last_uv;     // the last layout by outline, and each chart's index in it
  std::vector<int> was;
  for (int round = 0;; ++round) {
    ChartsResult result = lay_out_and_store(charts, guests, flat, unit_V, F, unit, vertex_rows, options, outline_density,
                                            last_uv, was);
    const std::vector<int> invalid =
        result.error ? std::vector<int>() : without_specks(unit_V, F, result.corner_uv, invalid_faces(unit_V, F, result.corner_uv));
    // Charts to cut in two: pieces far above the bound, and charts whose map folds a face that
    // closes a hole (real faces then overlap near it, none of them flipped).
    std::vector<int> stretched;
    for (size_t c = 0; c < charts.size() && !result.error; ++c) {
      const SolvedChart& chart = charts[c];
      const bool far_above = chart.cut_for_validity && !(result.charts[c].l2_stretch <= kTuning.piece_far_above * options.max_stretch);
      const bool folds = !chart.map.passes.empty() && chart.map.passes.at(size_t(chart.map.chosen_pass)).flipped > 0;
      if (chart.faces.size() > 1 && (far_above || folds)) stretched.push_back(int(c));
    }
    if ((invalid.empty() && stretched.empty()) || round == kTuning.most_repair_rounds) {
      if (cut > 0)
        result.notes.push_back(std::to_string(cut) + (cut == 1 ? " chart" : " charts") +
                               " with flipped or zero-area triangles cut smaller and laid out again");
      return result;
    }
    cut += size_t(cut_invalid_charts(charts, guests, result.face_chart, invalid, stretched, unit_V, F, options, flat, was));
  }
}

}  // namespace lowstretch
