#include "atlas/cut/zero_area_parts.h"

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

ChartsResult with_zero_area_faces(ChartsResult atlas, const Eigen::MatrixXi& F, const std::vector<int>& mapped,
                                  const std::vector<int>& zero_area, const ChartOptions& options) {
  const Eigen::MatrixXd mapped_uv = std::move(atlas.corner_uv);
  const Eigen::VectorXd mapped_stretch = std::move(atlas.face_stretch);
  const std::vector<int> mapped_chart = std::move(atlas.face_chart);
  atlas.corner_uv.resize(F.rows(), 6);
  atlas.face_stretch = Eigen::VectorXd::Zero(F.rows());
  atlas.face_chart.assign(size_t(F.rows()), int(atlas.charts.size()));
  const double inside = double(float(options.gutter / options.texture_size));
  Eigen::MatrixXd vertex_uv = Eigen::MatrixXd::Constant(atlas.vertex_stretch.rows(), 2, inside);
  std::vector<char> has_uv(size_t(vertex_uv.rows()), 0);
  for (size_t j = 0; j < mapped.size(); ++j) {
    const Eigen::Index f = mapped[j];
    atlas.corner_uv.row(f) = mapped_uv.row(Eigen::Index(j));
    atlas.face_stretch(f) = mapped_stretch(Eigen::Index(j));
    atlas.face_chart[size_t(f)] = mapped_chart[j];
    for (int k = 0; k < 3; ++k)
      if (!has_uv[size_t(F(f, k))]) {
        has_uv[size_t(F(f, k))] = 1;
        vertex_uv.row(F(f, k)) = mapped_uv.block(Eigen::Index(j), 2 * k, 1, 2);
      }
  }
  for (const int f : zero_area)
    for (int k = 0; k < 3; ++k) atlas.corner_uv.block(f, 2 * k, 1, 2) = vertex_uv.row(F(f, 0));
  Chart points;
  points.faces = int(zero_area.size());
  atlas.charts.push_back(points);
  atlas.subtexel_triangles += int(zero_area.size());
  atlas.notes.insert(atlas.notes.begin(), std::to_string(zero_area.size()) +
                                              (zero_area.size() == 1 ? " face" : " faces") +
                                              " in parts of zero 3D area (no surface to texture) get zero-area texture "
                                              "coordinates, on one point each");
  return atlas;
}

}  // namespace lowstretch
