#include "atlas/cut/zero_area_parts.h"

#include <algorithm>
#include <array>
#include <map>
#include <string>
#include <utility>

#include "atlas/cut/mesh_components.h"
#include "core/stretch.h"

namespace lowstretch {

std::vector<int> faces_of_zero_area_parts(const Eigen::MatrixXd& unit_V, const Eigen::MatrixXi& F) {
  int count = 0;
  const std::vector<int> component = face_components(F, count);
  std::vector<char> has_area(size_t(count), 0);
  for (Eigen::Index f = 0; f < F.rows(); ++f)
    if (!is_flat_face(unit_V, F, f)) has_area[size_t(component[size_t(f)])] = 1;
  std::vector<int> faces;
  for (Eigen::Index f = 0; f < F.rows(); ++f)
    if (!has_area[size_t(component[size_t(f)])]) faces.push_back(int(f));
  return faces;
}

namespace {

using Position = std::array<double, 3>;
using UvInCharts = std::map<Position, std::vector<std::pair<int, Eigen::RowVector2d>>>;

Position position(const Eigen::MatrixXd& V, Eigen::Index v) { return {V(v, 0), V(v, 1), V(v, 2)}; }

// A zero-area face on its neighbours' corners: the first chart (in the order of its first
// corner's) that has a vertex at each of its corners' positions where they have zero UV area too
// (a collapsed edge's face: two corners on one), so that no seam runs around it; -1 if none has.
// Three corners on a line in 3D but not in the chart's UV would cover texels of it. By position:
// a collapsed edge's faces reach this with corners of their own, copies of the welded vertices
// (split_vertex_fans.h).
int chart_holding(const UvInCharts& uv_in_chart, const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, Eigen::Index f,
                  Eigen::RowVector2d corners[3]) {
  const std::vector<std::pair<int, Eigen::RowVector2d>>* at[3];
  for (int k = 0; k < 3; ++k) {
    const auto found = uv_in_chart.find(position(V, F(f, k)));
    if (found == uv_in_chart.end()) return -1;
    at[k] = &found->second;
  }
  for (const auto& first : *at[0]) {
    int held = 0;
    for (int k = 0; k < 3; ++k)
      for (const auto& entry : *at[k])
        if (entry.first == first.first) {
          corners[k] = entry.second;
          ++held;
          break;
        }
    if (held == 3 && signed_uv_area(corners[0].transpose(), corners[1].transpose(), corners[2].transpose()) == 0)
      return first.first;
  }
  return -1;
}

}  // namespace

ChartsResult with_zero_area_faces(ChartsResult atlas, const Eigen::MatrixXd& V, const Eigen::MatrixXi& F,
                                  const std::vector<int>& mapped, const std::vector<int>& zero_area, const ChartOptions& options) {
  const Eigen::MatrixXd mapped_uv = std::move(atlas.corner_uv);
  const Eigen::VectorXd mapped_stretch = std::move(atlas.face_stretch);
  const std::vector<int> mapped_chart = std::move(atlas.face_chart);
  atlas.corner_uv.resize(F.rows(), 6);
  atlas.face_stretch = Eigen::VectorXd::Zero(F.rows());
  atlas.face_chart.assign(size_t(F.rows()), int(atlas.charts.size()));
  const double inside = double(float(options.gutter / options.texture_size));
  Eigen::MatrixXd vertex_uv = Eigen::MatrixXd::Constant(atlas.vertex_stretch.rows(), 2, inside);
  std::vector<char> has_uv(size_t(vertex_uv.rows()), 0);
  // The texture coordinate at each vertex position in each chart that has one there (a vertex on
  // a seam has several).
  UvInCharts uv_in_chart;
  for (size_t j = 0; j < mapped.size(); ++j) {
    const Eigen::Index f = mapped[j];
    atlas.corner_uv.row(f) = mapped_uv.row(Eigen::Index(j));
    atlas.face_stretch(f) = mapped_stretch(Eigen::Index(j));
    atlas.face_chart[size_t(f)] = mapped_chart[j];
    for (int k = 0; k < 3; ++k) {
      const Eigen::RowVector2d uv = mapped_uv.block(Eigen::Index(j), 2 * k, 1, 2);
      auto& charts = uv_in_chart[position(V, F(f, k))];
      if (std::none_of(charts.begin(), charts.end(), [&](const auto& e) { return e.first == mapped_chart[j]; }))
        charts.emplace_back(mapped_chart[j], uv);
      if (!has_uv[size_t(F(f, k))]) {
        has_uv[size_t(F(f, k))] = 1;
        vertex_uv.row(F(f, k)) = uv;
      }
    }
  }
  int on_a_point = 0;
  for (const int f : zero_area) {
    Eigen::RowVector2d corners[3];
    const int chart = chart_holding(uv_in_chart, V, F, f, corners);
    if (chart >= 0) {
      atlas.face_chart[size_t(f)] = chart;
      ++atlas.charts[size_t(chart)].faces;
    } else {
      ++on_a_point;
    }
    for (int k = 0; k < 3; ++k) atlas.corner_uv.block(f, 2 * k, 1, 2) = chart >= 0 ? corners[k] : vertex_uv.row(F(f, 0));
  }
  if (on_a_point > 0) {
    Chart points;
    points.faces = on_a_point;
    atlas.charts.push_back(points);
  }
  atlas.subtexel_triangles += int(zero_area.size());
  atlas.notes.insert(atlas.notes.begin(), std::to_string(zero_area.size()) +
                                              (zero_area.size() == 1 ? " face" : " faces") +
                                              " in parts of zero 3D area (no surface to texture) get zero-area texture "
                                              "coordinates: their neighbours' where one chart has all three corners, on "
                                              "zero area (no seam around them), else one point each");
  return atlas;
}

}  // namespace lowstretch
