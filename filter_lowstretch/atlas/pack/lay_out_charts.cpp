#include "atlas/pack/lay_out_charts.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

#include "atlas/base/tuning.h"
#include "atlas/chart_map/chart_threads.h"
#include "atlas/pack/empty_texels.h"
#include "atlas/pack/rectangle_layout.h"

namespace lowstretch {

namespace {

// A free chart stretched along its box's sides to the box's width / height `aspect` (a map the
// method made is scaled, not solved again), and measured again.
void stretch_to_aspect(SolvedChart& chart, double aspect) {
  const double by = aspect / chart.aspect();
  chart.map.uv.col(0) *= std::sqrt(by);
  chart.map.uv.col(1) /= std::sqrt(by);
  chart.fit_box();
  chart.kept = measure_real_faces(chart.mesh, chart.map.uv);
  chart.passes.at(size_t(chart.map.chosen_pass)) = chart.kept;
}

}  // namespace

void map_at_own_shape(SolvedChart& chart, const Options& options) {
  if (chart.deciding_map && chart.free_boundary) solve_onto(chart, options, 0, true);
  else if (chart.deciding_map) solve_chart(chart, options, chart.aspect());
}

void map_all_at_own_shape(std::vector<SolvedChart>& charts, const ChartOptions& options) {
  const size_t faces = faces_in(charts, 0, charts.size());
  for_each_index(int(charts.size()), [&](int i, int) {
    map_at_own_shape(charts[size_t(i)], for_share(options.disk, charts[size_t(i)].faces.size(), faces));
  }, largest_first(charts, 0, charts.size()));
}

std::vector<double> cell_areas(const std::vector<SolvedChart>& charts) {
  // A chart that does not fill its box (a free chart, a rectangle with closed holes) gets a cell
  // that holds its box at the texel density of the others.
  std::vector<double> own_area;
  for (const SolvedChart& c : charts)
    own_area.push_back(c.leaves_box_empty() ? c.kept.area_3d / std::max(c.fill(), 0.05) : c.kept.area_3d);
  return own_area;
}

namespace {

// The tiled charts' cells (an empty box for the others), each at least a few texels wide inside
// its gutter, and a note when tiny charts take much of the texture.
Error tile(const std::vector<SolvedChart>& charts, const std::vector<char>& tiled, const ChartOptions& options,
           std::vector<Eigen::AlignedBox2d>& cells, std::vector<std::string>& notes) {
  const double g = options.gutter / options.texture_size, inset = 0.5 * g / (1 - 2 * g);
  const std::vector<double> all_areas = cell_areas(charts);
  std::vector<double> own_area, preferred;
  double total = 0;
  for (size_t i = 0; i < charts.size(); ++i) {
    if (!tiled[i]) continue;
    own_area.push_back(all_areas[i]);
    total += own_area.back();
    // Cells no longer than four times their width, whatever the chart: a long thin cell has no
    // room for its gutter (the chart then fills part of it, kTuning.most_cell_mismatch).
    preferred.push_back(std::min(4.0, std::max(0.25, charts[i].aspect())));
  }
  // Every cell at least a few texels wide inside its gutter, whatever its chart's area: tiny
  // charts get a floor of area, raised until no cell is thinner than that (rows of many tiny
  // charts can be thin).
  std::vector<Eigen::AlignedBox2d> tiles;
  double least = 0, floored_share = 0;
  int floored = 0;
  for (double texels = 2 * options.gutter + 4;; texels *= 1.5) {
    least = total * texels * texels / (double(options.texture_size) * options.texture_size);
    std::vector<double> areas;
    for (const double area : own_area) areas.push_back(std::max({area, least, 1e-300}));
    tiles = slice_unit_square(areas, preferred);
    double thinnest = 1;
    for (const Eigen::AlignedBox2d& cell : tiles) thinnest = std::min(thinnest, cell.sizes().minCoeff());
    floored = int(std::count_if(own_area.begin(), own_area.end(), [&](double a) { return a < least; }));
    floored_share = floored * least / std::accumulate(areas.begin(), areas.end(), 0.0);
    if (thinnest > 2 * inset + 2.0 / options.texture_size) break;
    if (least * double(own_area.size()) > total) return {ErrorCode::ChartsNotPacked, static_cast<long long>(charts.size()), ""};
  }
  // Debris: many tiny parts, each given a cell it cannot fill, leave the rest of the mesh little
  // texture.
  if (floored_share > kTuning.most_floored_share)
    notes.push_back(std::to_string(floored) + " charts too small for the " + std::to_string(options.texture_size) +
                    "-texel texture take " + std::to_string(int(std::lround(100 * floored_share))) +
                    "% of it: remove tiny parts (MeshLab: Cleaning and Repairing > Remove Isolated pieces) "
                    "or use a larger texture");
  cells.assign(charts.size(), Eigen::AlignedBox2d());
  for (size_t i = 0, t = 0; i < charts.size(); ++i)
    if (tiled[i]) cells[i] = tiles[t++];
  return {};
}

// Every tiled chart mapped again onto its cell's shape (or stretched to it, if free), turned a
// quarter where that fits better; every other chart keeps its shape, with a full map.
void fit_to_cells(std::vector<SolvedChart>& charts, const std::vector<char>& tiled, const std::vector<Eigen::AlignedBox2d>& cells,
                  const ChartOptions& options, std::vector<char>& turned) {
  turned.assign(charts.size(), 0);
  const size_t all_faces = faces_in(charts, 0, charts.size());
  for_each_index(int(charts.size()), [&](int i, int) {
    SolvedChart& c = charts[size_t(i)];
    const Options share = for_share(options.disk, c.faces.size(), all_faces);
    if (!tiled[size_t(i)]) {
      map_at_own_shape(c, share);
      return;
    }
    const double cell = cells[size_t(i)].sizes().x() / cells[size_t(i)].sizes().y();
    turned[size_t(i)] = std::abs(std::log(c.aspect() * cell)) < std::abs(std::log(c.aspect() / cell));
    // A cell far from the chart's shape (a small chart beside a large one gets a strip) is
    // filled only in part: stretching the chart to fit would cost more than the empty texels.
    const double fits = turned[size_t(i)] ? 1 / cell : cell;
    const double wanted = std::min(c.aspect() * kTuning.most_cell_mismatch, std::max(c.aspect() / kTuning.most_cell_mismatch, fits));
    if (c.free_boundary) {  // stretched to its cell's shape as far as a rectangle would be
      if (std::abs(std::log(wanted / c.aspect())) > 0.02) stretch_to_aspect(c, wanted);
      return;
    }
    // A map made while deciding where to cut had fewer passes and a looser solve.
    if (std::abs(std::log(wanted / c.aspect())) > 0.02 || c.deciding_map) solve_chart(c, share, wanted);
  }, largest_first(charts, 0, charts.size()));
}

// The tiled charts' corners: each chart fitted into its cell less half the gutter on each side.
Error write_tiled_corners(const std::vector<SolvedChart>& charts, const std::vector<char>& tiled,
                          const std::vector<Eigen::AlignedBox2d>& cells, const std::vector<char>& turned,
                          const ChartOptions& options, ChartsResult& result) {
  const double g = options.gutter / options.texture_size, inset = 0.5 * g / (1 - 2 * g);
  for (size_t c = 0; c < charts.size(); ++c) {
    if (charts[c].map.error) return charts[c].map.error;
    if (!tiled[c]) continue;
    const ChartMesh& mesh = charts[c].mesh;
    const Eigen::MatrixXd& uv = charts[c].map.uv;
    const Eigen::AlignedBox2d& box = charts[c].box;
    Eigen::AlignedBox2d target = cells[c];
    target.min().array() += inset;
    target.max().array() -= inset;
    if (!(target.sizes().minCoeff() > 0) || !(box.sizes().minCoeff() > 0))
      return {ErrorCode::ChartsNotPacked, static_cast<long long>(charts.size()), ""};
    const double chart = turned[c] ? box.sizes().y() / box.sizes().x() : box.sizes().x() / box.sizes().y();
    Eigen::Vector2d size = target.sizes();
    if (std::abs(std::log(chart * size.y() / size.x())) > 0.02) {  // the part of the cell of the chart's shape
      if (chart > size.x() / size.y()) size.y() = size.x() / chart;
      else size.x() = size.y() * chart;
      target.max() = target.min() + size;
    }
    for (size_t j = 0; j < charts[c].faces.size(); ++j) {
      const int f = charts[c].faces[j];
      result.face_chart[size_t(f)] = int(c);
      for (int k = 0; k < 3; ++k) {
        Eigen::Vector2d p = ((uv.row(mesh.F(Eigen::Index(j), k)).transpose() - box.min()).array() / box.sizes().array()).matrix();
        if (turned[c]) p = Eigen::Vector2d(1 - p.y(), p.x());  // a quarter turn counter-clockwise
        p = target.min() + p.cwiseProduct(target.sizes());
        result.corner_uv.block(f, 2 * k, 1, 2) = p.transpose();
      }
    }
  }
  return {};
}

}  // namespace

Error lay_out(std::vector<SolvedChart>& charts, const ChartOptions& options, Eigen::Index face_count,
              const std::vector<int>& guests, ChartsResult& result, double& outline_density) {
  std::vector<char> tiled(charts.size(), 1);
  for (const int i : guests) tiled[size_t(i)] = 0;
  if (!charts.empty() && guests.size() == charts.size()) {  // no tiling: every chart by its outline
    std::vector<char> turned;
    fit_to_cells(charts, tiled, {}, options, turned);
    for (const SolvedChart& c : charts)
      if (c.map.error) return c.map.error;
    result.corner_uv.resize(face_count, 6);
    result.face_chart.assign(size_t(face_count), 0);
    if (!pack_by_outline(charts, options, result.corner_uv, result.face_chart, outline_density))
      return {ErrorCode::ChartsNotPacked, static_cast<long long>(charts.size()), ""};
    return {};
  }
  for (int round = 0;; ++round) {
    std::vector<Eigen::AlignedBox2d> cells;
    std::vector<std::string> notes;
    if (Error e = tile(charts, tiled, options, cells, notes)) return e;
    std::vector<char> turned;
    fit_to_cells(charts, tiled, cells, options, turned);
    result.corner_uv.resize(face_count, 6);
    result.face_chart.assign(size_t(face_count), 0);
    if (Error e = write_tiled_corners(charts, tiled, cells, turned, options, result)) return e;
    std::vector<int> left;
    for (size_t i = 0; i < charts.size(); ++i)
      if (!tiled[i]) left.push_back(int(i));
    const std::vector<int> unplaced = left.empty() ? left : put_in_empty_texels(charts, left, options, result.corner_uv, result.face_chart);
    if (unplaced.empty()) {
      result.notes.insert(result.notes.end(), notes.begin(), notes.end());
      if (!left.empty()) result.notes.push_back(std::to_string(left.size()) + " small charts put into texels the tiling left empty");
      return {};
    }
    if (round + 1 == kTuning.most_guest_rounds) return {ErrorCode::ChartsNotPacked, static_cast<long long>(charts.size()), ""};
    for (const int i : unplaced) tiled[size_t(i)] = 1;
  }
}

bool lay_out_around(std::vector<SolvedChart>& charts, const ChartOptions& options, const Eigen::MatrixXd& last_uv,
                    const std::vector<int>& was, ChartsResult& result) {
  std::vector<char> turned;
  fit_to_cells(charts, std::vector<char>(charts.size(), 0), {}, options, turned);
  result.corner_uv = last_uv;
  result.face_chart.assign(size_t(last_uv.rows()), 0);
  std::vector<int> pieces;
  for (size_t c = 0; c < charts.size(); ++c) {
    if (charts[c].map.error) return false;
    if (was[c] < 0) pieces.push_back(int(c));
    else
      for (const int f : charts[c].faces) result.face_chart[size_t(f)] = int(c);
  }
  return put_in_empty_texels(charts, pieces, options, result.corner_uv, result.face_chart).empty();
}

}  // namespace lowstretch
