#include "lay_out_charts.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

#include "chart_threads.h"
#include "rectangle_layout.h"

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

// Above this share of the texture in cells raised to the smallest a gutter allows, a note says so.
const double kMostFlooredShare = 0.1;

}  // namespace

Error lay_out(std::vector<SolvedChart>& charts, const ChartOptions& options, Eigen::Index face_count, ChartsResult& result) {
  // Half the gutter around every cell, in [0,1]^2 before store() moves it into [g, 1 - g]^2.
  const double g = options.gutter / options.texture_size, inset = 0.5 * g / (1 - 2 * g);
  // A chart that does not fill its box (a free chart, a rectangle with closed holes) gets a cell
  // that holds its box at the texel density of the others.
  std::vector<double> own_area;
  double total = 0;
  for (const SolvedChart& c : charts) {
    own_area.push_back(c.free_boundary || c.mesh.closed_holes > 0 ? c.kept.area_3d / std::max(c.fill(), 0.05) : c.kept.area_3d);
    total += own_area.back();
  }
  std::vector<double> preferred;
  // Cells no longer than four times their width, whatever the chart: a long thin cell has no
  // room for its gutter (the chart then fills part of it, kMostCellMismatch).
  for (const SolvedChart& c : charts) preferred.push_back(std::min(4.0, std::max(0.25, c.aspect())));
  // Every cell at least a few texels wide inside its gutter, whatever its chart's area: tiny
  // charts get a floor of area, raised until no cell is thinner than that (rows of many tiny
  // charts can be thin).
  std::vector<Eigen::AlignedBox2d> cells;
  double least = 0, floored_share = 0;
  int floored = 0;
  for (double texels = 2 * options.gutter + 4;; texels *= 1.5) {
    least = total * texels * texels / (double(options.texture_size) * options.texture_size);
    std::vector<double> areas;
    for (const double area : own_area) areas.push_back(std::max({area, least, 1e-300}));
    cells = slice_unit_square(areas, preferred);
    double thinnest = 1;
    for (const Eigen::AlignedBox2d& cell : cells) thinnest = std::min(thinnest, cell.sizes().minCoeff());
    floored = int(std::count_if(own_area.begin(), own_area.end(), [&](double a) { return a < least; }));
    floored_share = floored * least / std::accumulate(areas.begin(), areas.end(), 0.0);
    if (thinnest > 2 * inset + 2.0 / options.texture_size) break;
    if (least * double(charts.size()) > total) return {ErrorCode::ChartsNotPacked, static_cast<long long>(charts.size()), ""};
  }
  // Scan debris: tiny parts, each given a cell it cannot fill, leave the rest of the mesh little
  // texture (tests/bench/make_defects.py's debris30000: 66% of it, efficiency 0.25).
  if (floored_share > kMostFlooredShare)
    result.notes.push_back(std::to_string(floored) + " charts too small for the " + std::to_string(options.texture_size) +
                           "-texel texture take " + std::to_string(int(std::lround(100 * floored_share))) +
                           "% of it: remove tiny parts (MeshLab: Cleaning and Repairing > Remove Isolated pieces) "
                           "or use a larger texture");
  std::vector<char> turned(charts.size(), 0);
  const size_t all_faces = faces_in(charts, 0, charts.size());
  for_each_index(int(charts.size()), [&](int i, int) {
    SolvedChart& c = charts[size_t(i)];
    const double cell = cells[size_t(i)].sizes().x() / cells[size_t(i)].sizes().y();
    turned[size_t(i)] = std::abs(std::log(c.aspect() * cell)) < std::abs(std::log(c.aspect() / cell));
    // A cell far from the chart's shape (a small chart beside a large one gets a strip) is
    // filled only in part: stretching the chart to fit would cost more than the empty texels.
    const double fits = turned[size_t(i)] ? 1 / cell : cell;
    const double wanted = std::min(c.aspect() * kMostCellMismatch, std::max(c.aspect() / kMostCellMismatch, fits));
    if (c.free_boundary) {  // stretched to its cell's shape as far as a rectangle would be
      if (std::abs(std::log(wanted / c.aspect())) > 0.02) stretch_to_aspect(c, wanted);
      return;
    }
    // A map made while deciding where to cut had fewer passes and a looser solve.
    if (std::abs(std::log(wanted / c.aspect())) > 0.02 || c.deciding_map) solve_chart(c, for_share(options.disk, c.faces.size(), all_faces), wanted);
  }, largest_first(charts, 0, charts.size()));
  result.corner_uv.resize(face_count, 6);
  result.face_chart.assign(size_t(face_count), 0);
  for (size_t c = 0; c < charts.size(); ++c) {
    if (charts[c].map.error) return charts[c].map.error;
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

}  // namespace lowstretch
