#include "split_vertex_fans.h"

#include <Eigen/Geometry>
#include <cmath>
#include <map>
#include <utility>

#include "half_edges.h"
#include "stretch.h"

namespace lowstretch {

SplitFans split_vertex_fans(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F) {
  SplitFans split;
  split.F = F;
  const std::vector<int> fan = corner_fans(opposite_half_edges(F));
  std::vector<int> first_fan(static_cast<size_t>(V.rows()), -1);
  std::map<int, int> copy_of_fan;  // fan -> its new vertex, for the fans that are not a vertex's first
  std::vector<int> copied;         // input vertex of each new vertex
  for (int h = 0; h < int(fan.size()); ++h) {
    const int v = half_edge_tail(F, h);
    int& first = first_fan[size_t(v)];
    if (first == -1) first = fan[size_t(h)];
    if (first == fan[size_t(h)]) continue;
    const auto found = copy_of_fan.emplace(fan[size_t(h)], int(V.rows() + Eigen::Index(copied.size())));
    if (found.second) copied.push_back(v);
    split.F(h / 3, h % 3) = found.first->second;
  }
  split.V.resize(V.rows() + Eigen::Index(copied.size()), V.cols());
  split.V.topRows(V.rows()) = V;
  split.origin.resize(size_t(split.V.rows()));
  for (Eigen::Index v = 0; v < V.rows(); ++v) split.origin[size_t(v)] = int(v);
  std::vector<char> counted(static_cast<size_t>(V.rows()), 0);
  for (size_t k = 0; k < copied.size(); ++k) {
    split.V.row(V.rows() + Eigen::Index(k)) = V.row(copied[k]);
    split.origin[size_t(V.rows()) + k] = copied[k];
    if (!counted[size_t(copied[k])]) ++split.split_vertices;
    counted[size_t(copied[k])] = 1;
  }
  return split;
}

Eigen::VectorXd join_vertex_values(const SplitFans& split, const Eigen::VectorXd& value, int input_vertices) {
  Eigen::VectorXd area = Eigen::VectorXd::Zero(split.V.rows());
  for (Eigen::Index f = 0; f < split.F.rows(); ++f) {
    const double face_area = face_area_3d(split.V, split.F, f);
    for (int k = 0; k < 3; ++k) area(split.F(f, k)) += face_area;
  }
  Eigen::VectorXd weighted = Eigen::VectorXd::Zero(input_vertices), total = Eigen::VectorXd::Zero(input_vertices);
  Eigen::VectorXd joined = value.head(input_vertices);
  for (Eigen::Index v = 0; v < split.V.rows(); ++v) {
    const int o = split.origin[size_t(v)];
    weighted(o) += area(v) * value(v) * value(v);
    total(o) += area(v);
  }
  for (int o = 0; o < input_vertices; ++o)
    if (total(o) > 0) joined(o) = std::isfinite(weighted(o)) ? std::sqrt(weighted(o) / total(o)) : weighted(o);
  return joined;
}

}  // namespace lowstretch
