#include "core/disk_mesh.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <tuple>

#include "core/boundary_loops.h"
#include "core/half_edges.h"
#include "core/union_find.h"

namespace lowstretch {

namespace {

Error check_indices(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F) {
  const long long nv = V.rows(), m = F.rows();
  if (m == 0) return {ErrorCode::NoFaces, nv, ""};
  if (F.cols() != 3 || (V.cols() != 3 && nv > 0)) return {ErrorCode::IndexOutOfRange, m, ""};
  long long bad_index = 0, repeated = 0;
  for (Eigen::Index f = 0; f < m; ++f) {
    const int a = F(f, 0), b = F(f, 1), c = F(f, 2);
    if (a < 0 || b < 0 || c < 0 || a >= nv || b >= nv || c >= nv) ++bad_index;
    else if (a == b || b == c || a == c) ++repeated;
  }
  if (bad_index) return {ErrorCode::IndexOutOfRange, bad_index, ""};
  if (repeated) return {ErrorCode::RepeatedVertexInFace, repeated, ""};
  return {};
}

// Keeps the vertices that faces use, in order of first use; the others are ignored whatever
// their coordinates.
Error compact_vertices(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, DiskMesh& disk) {
  std::vector<int> compact(size_t(V.rows()), -1);
  disk.input_vertex.clear();
  for (Eigen::Index f = 0; f < F.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      int& c = compact[size_t(F(f, k))];
      if (c < 0) {
        c = int(disk.input_vertex.size());
        disk.input_vertex.push_back(F(f, k));
      }
    }
  const int n = int(disk.input_vertex.size());
  disk.V.resize(n, 3);
  long long non_finite = 0;
  for (int i = 0; i < n; ++i) {
    disk.V.row(i) = V.row(disk.input_vertex[size_t(i)]);
    if (!disk.V.row(i).allFinite()) ++non_finite;
  }
  if (non_finite) return {ErrorCode::NonFiniteCoordinates, non_finite, ""};
  // Huge coordinates would otherwise give NaN texture coordinates.
  const UnitBox box = unit_box(disk.V);
  for (int i = 0; i < n; ++i) disk.V.row(i) = box.map(disk.V.row(i));
  disk.F.resize(F.rows(), 3);
  for (Eigen::Index f = 0; f < F.rows(); ++f)
    for (int k = 0; k < 3; ++k) disk.F(f, k) = compact[size_t(F(f, k))];
  return {};
}

// Pairs each half-edge with the opposite one (twin, -1 on the boundary) and lists every
// undirected edge once, counting the edges that are not manifold or not consistently oriented.
Error pair_half_edges(const Eigen::MatrixXi& F, std::vector<int>& twin, DiskMesh& disk) {
  const std::vector<std::pair<uint64_t, int>> keyed = half_edges_by_edge(F);
  EdgePairing pairing = pair_manifold_half_edges(F, keyed);
  if (pairing.non_manifold) return {ErrorCode::NonManifoldEdges, pairing.non_manifold, ""};
  if (pairing.misoriented) return {ErrorCode::InconsistentOrientation, pairing.misoriented, ""};
  twin = std::move(pairing.twin);
  std::vector<std::pair<int, int>> edges;
  disk.edge_on_boundary.clear();
  for (size_t s = 0; s < keyed.size();) {
    size_t e = s;
    while (e < keyed.size() && keyed[e].first == keyed[s].first) ++e;
    const int h0 = keyed[s].second;
    edges.push_back({half_edge_tail(F, h0), half_edge_head(F, h0)});
    disk.edge_on_boundary.push_back(e - s == 1);
    s = e;
  }
  disk.edges.resize(Eigen::Index(edges.size()), 2);
  for (size_t e = 0; e < edges.size(); ++e) disk.edges.row(Eigen::Index(e)) << edges[e].first, edges[e].second;
  return {};
}

}  // namespace

long long vertices_on_others(const Eigen::MatrixXd& V) {
  std::vector<int> order(size_t(V.rows()));
  std::iota(order.begin(), order.end(), 0);
  const auto position = [&](int i) { return std::make_tuple(V(i, 0), V(i, 1), V(i, 2)); };
  std::sort(order.begin(), order.end(), [&](int a, int b) { return position(a) < position(b); });
  long long on_others = 0;
  for (size_t s = 0; s < order.size();) {
    size_t e = s + 1;
    while (e < order.size() && position(order[e]) == position(order[s])) ++e;
    if (e - s > 1) on_others += (long long)(e - s);
    s = e;
  }
  return on_others;
}

namespace {

// Several components; a triangle soup (each face with vertices of its own, as STL stores them)
// is named as such, since the way out is to weld it, not to keep one part or make charts.
Error check_connected(const DiskMesh& disk) {
  const int n = int(disk.V.rows());
  UnionFind components(n);
  for (Eigen::Index e = 0; e < disk.edges.rows(); ++e) components.unite(disk.edges(e, 0), disk.edges(e, 1));
  long long count = 0;
  for (int i = 0; i < n; ++i) count += components.find(i) == i;
  if (count <= 1) return {};
  const long long on_others = vertices_on_others(disk.V);
  if (2 * on_others >= n) return {ErrorCode::UnweldedVertices, on_others, ""};
  return {ErrorCode::SeveralComponents, count, ""};
}

// On a manifold the corners around a vertex form one fan: count the vertices with several.
Error check_vertex_fans(const Eigen::MatrixXi& F, const std::vector<int>& twin, int n) {
  const std::vector<int> fan = corner_fans(twin);
  std::vector<int> fan_of_vertex(size_t(n), -1);
  long long non_manifold = 0;
  for (int h = 0; h < int(twin.size()); ++h) {
    int& seen = fan_of_vertex[size_t(half_edge_tail(F, h))];
    if (seen == -1) seen = fan[size_t(h)];
    else if (seen != fan[size_t(h)] && seen != -2) {
      seen = -2;  // counted once
      ++non_manifold;
    }
  }
  if (non_manifold) return {ErrorCode::NonManifoldVertices, non_manifold, ""};
  return {};
}

Error find_boundary_loop(const Eigen::MatrixXi& F, const std::vector<int>& twin, int n, std::vector<int>& loop) {
  const std::vector<std::vector<int>> loops = boundary_loops(F, twin, n);
  if (loops.empty()) return {ErrorCode::Closed, 0, ""};
  if (loops.size() > 1) return {ErrorCode::SeveralBoundaryLoops, (long long)loops.size(), ""};
  loop = loops.front();
  return {};
}

Error check_genus_and_area(const DiskMesh& disk) {
  const long long euler = disk.V.rows() - disk.edges.rows() + disk.F.rows();  // 2 - 2g - 1 for one loop
  if (euler != 1) return {ErrorCode::NotGenusZero, (1 - euler) / 2, ""};
  double total_area = 0;
  for (Eigen::Index f = 0; f < disk.F.rows(); ++f) {
    const Eigen::RowVector3d a = disk.V.row(disk.F(f, 0)), b = disk.V.row(disk.F(f, 1)), c = disk.V.row(disk.F(f, 2));
    total_area += (b - a).cross(c - a).norm();
  }
  if (!(total_area > 0)) return {ErrorCode::ZeroAreaMesh, disk.F.rows(), ""};
  return {};
}

// Neighbours of every vertex counter-clockwise: in face (v, a, b) the fan turns from a to b. A
// boundary fan starts at the head of its outgoing boundary edge and has one more neighbour
// than faces.
void build_rings(const std::vector<int>& twin, DiskMesh& disk) {
  const Eigen::MatrixXi& F = disk.F;
  const int n = int(disk.V.rows()), nh = int(twin.size());
  std::vector<int> corner_start(size_t(n) + 1, 0), corner(static_cast<size_t>(nh));
  for (int h = 0; h < nh; ++h) ++corner_start[size_t(half_edge_tail(F, h)) + 1];
  std::partial_sum(corner_start.begin(), corner_start.end(), corner_start.begin());
  std::vector<int> fill(corner_start.begin(), corner_start.end() - 1);
  for (int h = 0; h < nh; ++h) corner[size_t(fill[size_t(half_edge_tail(F, h))]++)] = h;

  disk.ring_start.assign(size_t(n) + 1, 0);
  for (int i = 0; i < n; ++i)
    disk.ring_start[size_t(i) + 1] = disk.ring_start[size_t(i)] + (corner_start[size_t(i) + 1] - corner_start[size_t(i)]) +
                                     disk.is_boundary[size_t(i)];
  disk.ring.assign(size_t(disk.ring_start[size_t(n)]), -1);
  for (int v = 0; v < n; ++v) {
    const int c0 = corner_start[size_t(v)], c1 = corner_start[size_t(v) + 1];
    int h = corner[size_t(c0)];
    if (disk.is_boundary[size_t(v)])
      for (int c = c0; c < c1; ++c)
        if (twin[size_t(corner[size_t(c)])] < 0) h = corner[size_t(c)];
    int slot = disk.ring_start[size_t(v)];
    for (int step = 0; step < c1 - c0; ++step) {
      disk.ring[size_t(slot++)] = half_edge_head(F, h);
      if (twin[size_t(previous_half_edge(h))] < 0) {  // reached the incoming boundary edge
        disk.ring[size_t(slot++)] = half_edge_tail(F, previous_half_edge(h));
        break;
      }
      h = twin[size_t(previous_half_edge(h))];
    }
  }
}

}  // namespace

UnitBox unit_box(const Eigen::MatrixXd& points) {
  UnitBox box;
  if (points.rows() == 0) return box;
  const Eigen::RowVector3d low = points.colwise().minCoeff() / 2, high = points.colwise().maxCoeff() / 2;
  box.centre_half = low / 2 + high / 2;
  const double extent = (high - low).maxCoeff();
  if (extent > 0) box.extent = extent;
  return box;
}

Error make_disk_mesh(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, DiskMesh& disk) {
  if (Error e = check_indices(V, F)) return e;
  if (Error e = compact_vertices(V, F, disk)) return e;
  std::vector<int> twin;
  if (Error e = pair_half_edges(disk.F, twin, disk)) return e;
  if (Error e = check_connected(disk)) return e;
  const int n = int(disk.V.rows());
  if (Error e = check_vertex_fans(disk.F, twin, n)) return e;
  if (Error e = find_boundary_loop(disk.F, twin, n, disk.boundary)) return e;
  if (Error e = check_genus_and_area(disk)) return e;
  disk.is_boundary.assign(size_t(n), 0);
  for (int v : disk.boundary) disk.is_boundary[size_t(v)] = 1;
  build_rings(twin, disk);
  return {};
}

}  // namespace lowstretch
