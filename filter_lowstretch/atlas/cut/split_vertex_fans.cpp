#include "atlas/cut/split_vertex_fans.h"

#include <Eigen/Geometry>
#include <cmath>
#include <map>
#include <utility>

#include "core/half_edges.h"
#include "core/stretch.h"

namespace lowstretch {

namespace {

// Gives every corner of `face` a new vertex at its position.
void detach_face(Eigen::Index face, Eigen::MatrixXi& F, std::vector<int>& origin) {
  for (int k = 0; k < 3; ++k) {
    origin.push_back(origin[size_t(F(face, k))]);
    F(face, k) = int(origin.size()) - 1;
  }
}

// Every fan of faces around a vertex but its first (in corner order) gets a new vertex.
void split_fans(const std::vector<int>& twin, Eigen::MatrixXi& F, std::vector<int>& origin) {
  const std::vector<int> fan = corner_fans(twin);
  std::vector<int> first_fan(origin.size(), -1);
  std::map<int, int> copy_of_fan;  // fan -> its new vertex
  for (int h = 0; h < int(fan.size()); ++h) {
    const int v = half_edge_tail(F, h);
    int& first = first_fan[size_t(v)];
    if (first == -1) first = fan[size_t(h)];
    if (first == fan[size_t(h)]) continue;
    const auto found = copy_of_fan.emplace(fan[size_t(h)], int(origin.size()));
    if (found.second) origin.push_back(origin[size_t(v)]);
    F(h / 3, h % 3) = found.first->second;
  }
}

}  // namespace

SplitFans split_vertex_fans(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F) {
  SplitFans split;
  split.F = F;
  split.origin.resize(size_t(V.rows()));
  for (Eigen::Index v = 0; v < V.rows(); ++v) split.origin[size_t(v)] = int(v);
  for (Eigen::Index f = 0; f < F.rows(); ++f)
    if (F(f, 0) == F(f, 1) || F(f, 1) == F(f, 2) || F(f, 0) == F(f, 2)) {
      detach_face(f, split.F, split.origin);
      ++split.repeated_vertex_faces;
    }
  // The charts are cut open across every edge not shared by exactly two faces of opposite
  // orientation (pair_manifold_half_edges leaves those unpaired).
  EdgePairing pairing = pair_manifold_half_edges(split.F, half_edges_by_edge(split.F));
  split.non_manifold_edges = int(pairing.non_manifold);
  split.misoriented_edges = int(pairing.misoriented);
  split_fans(pairing.twin, split.F, split.origin);
  // Faces joined around both ends of a cut edge get one copy of each end again, and so share the
  // edge again; where that edge is still not manifold (faces pinched together elsewhere), its
  // faces get corners of their own. Each round detaches faces, so this ends.
  for (;;) {
    const std::vector<std::pair<uint64_t, int>> keyed = half_edges_by_edge(split.F);
    pairing = pair_manifold_half_edges(split.F, keyed);
    if (pairing.non_manifold + pairing.misoriented == 0) break;
    std::vector<char> detach(size_t(F.rows()), 0);
    for (size_t s = 0; s < keyed.size();) {
      size_t e = s;
      while (e < keyed.size() && keyed[e].first == keyed[s].first) ++e;
      const bool joined = e - s == 2 && pairing.twin[size_t(keyed[s].second)] >= 0;
      if (e - s >= 2 && !joined)
        for (size_t j = s; j < e; ++j) detach[size_t(keyed[j].second / 3)] = 1;
      s = e;
    }
    for (Eigen::Index f = 0; f < F.rows(); ++f)
      if (detach[size_t(f)]) detach_face(f, split.F, split.origin);
    split_fans(pair_manifold_half_edges(split.F, half_edges_by_edge(split.F)).twin, split.F, split.origin);
  }
  split.new_vertices = int(split.origin.size()) - int(V.rows());
  split.V.resize(Eigen::Index(split.origin.size()), V.cols());
  std::vector<char> counted(size_t(V.rows()), 0);
  for (size_t v = 0; v < split.origin.size(); ++v) {
    split.V.row(Eigen::Index(v)) = V.row(split.origin[v]);
    if (v >= size_t(V.rows()) && !counted[size_t(split.origin[v])]) {
      counted[size_t(split.origin[v])] = 1;
      ++split.split_vertices;
    }
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
