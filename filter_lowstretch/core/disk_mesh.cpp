#include "disk_mesh.h"

#include <algorithm>
#include <Eigen/Geometry>
#include <cmath>
#include <cstdint>
#include <numeric>

namespace lowstretch {

namespace {

struct UnionFind {
  std::vector<int> parent;
  explicit UnionFind(int n) : parent(size_t(n)) { std::iota(parent.begin(), parent.end(), 0); }
  int find(int x) {
    while (parent[size_t(x)] != x) x = parent[size_t(x)] = parent[size_t(parent[size_t(x)])];
    return x;
  }
  void unite(int a, int b) { parent[size_t(find(a))] = find(b); }
};

// Half-edge h = 3 f + k runs from F(f, k) to F(f, (k + 1) % 3).
int tail(const Eigen::MatrixXi& F, int h) { return F(h / 3, h % 3); }
int head(const Eigen::MatrixXi& F, int h) { return F(h / 3, (h % 3 + 1) % 3); }

}  // namespace

Error make_disk_mesh(const Eigen::MatrixXd& Vin, const Eigen::MatrixXi& Fin, DiskMesh& disk) {
  const long long nv_in = Vin.rows(), m = Fin.rows();
  if (m == 0) return {ErrorCode::NoFaces, nv_in, ""};
  if (Fin.cols() != 3 || (Vin.cols() != 3 && nv_in > 0)) return {ErrorCode::IndexOutOfRange, m, ""};

  long long bad_index = 0, repeated = 0;
  for (Eigen::Index f = 0; f < m; ++f) {
    const int a = Fin(f, 0), b = Fin(f, 1), c = Fin(f, 2);
    if (a < 0 || b < 0 || c < 0 || a >= nv_in || b >= nv_in || c >= nv_in) ++bad_index;
    else if (a == b || b == c || a == c) ++repeated;
  }
  if (bad_index) return {ErrorCode::IndexOutOfRange, bad_index, ""};
  if (repeated) return {ErrorCode::RepeatedVertexInFace, repeated, ""};

  // Compact the referenced vertices; the others are ignored whatever their coordinates.
  std::vector<int> compact(size_t(nv_in), -1);
  disk.input_vertex.clear();
  for (Eigen::Index f = 0; f < m; ++f)
    for (int k = 0; k < 3; ++k) {
      int& c = compact[size_t(Fin(f, k))];
      if (c < 0) { c = int(disk.input_vertex.size()); disk.input_vertex.push_back(Fin(f, k)); }
    }
  const int n = int(disk.input_vertex.size());
  disk.V.resize(n, 3);
  long long non_finite = 0;
  for (int i = 0; i < n; ++i) {
    disk.V.row(i) = Vin.row(disk.input_vertex[size_t(i)]);
    if (!disk.V.row(i).allFinite()) ++non_finite;
  }
  if (non_finite) return {ErrorCode::NonFiniteCoordinates, non_finite, ""};
  disk.F.resize(m, 3);
  for (Eigen::Index f = 0; f < m; ++f)
    for (int k = 0; k < 3; ++k) disk.F(f, k) = compact[size_t(Fin(f, k))];
  const Eigen::MatrixXi& F = disk.F;

  // Group half-edges by undirected edge: sorting beats hashing at a million half-edges.
  const int nh = int(3 * m);
  std::vector<std::pair<uint64_t, int>> keyed(static_cast<size_t>(nh));
  for (int h = 0; h < nh; ++h) {
    const uint64_t a = uint64_t(tail(F, h)), b = uint64_t(head(F, h));
    keyed[size_t(h)] = {std::min(a, b) << 32 | std::max(a, b), h};
  }
  std::sort(keyed.begin(), keyed.end());
  std::vector<int> twin(size_t(nh), -1);
  std::vector<std::pair<int, int>> edge_list;
  std::vector<char> edge_boundary;
  long long non_manifold_edges = 0, misoriented = 0;
  for (size_t s = 0; s < keyed.size();) {
    size_t e = s;
    while (e < keyed.size() && keyed[e].first == keyed[s].first) ++e;
    const int h0 = keyed[s].second;
    edge_list.push_back({tail(F, h0), head(F, h0)});
    edge_boundary.push_back(e - s == 1);
    if (e - s > 2) ++non_manifold_edges;
    else if (e - s == 2) {
      const int h1 = keyed[s + 1].second;
      if (tail(F, h0) == tail(F, h1)) ++misoriented;  // both run the same way
      twin[size_t(h0)] = h1;
      twin[size_t(h1)] = h0;
    }
    s = e;
  }
  if (non_manifold_edges) return {ErrorCode::NonManifoldEdges, non_manifold_edges, ""};
  if (misoriented) return {ErrorCode::InconsistentOrientation, misoriented, ""};

  UnionFind components(n);
  for (const auto& e : edge_list) components.unite(e.first, e.second);
  long long component_count = 0;
  for (int i = 0; i < n; ++i) component_count += components.find(i) == i;
  if (component_count > 1) return {ErrorCode::SeveralComponents, component_count, ""};

  // Corners around a vertex form one fan on a manifold: join each corner to the corner across
  // its incoming edge, then count fans per vertex.
  UnionFind fans(nh);
  for (int h = 0; h < nh; ++h) {
    const int incoming = (h / 3) * 3 + (h % 3 + 2) % 3;  // ends at tail(h)
    if (twin[size_t(incoming)] >= 0) fans.unite(h, twin[size_t(incoming)]);
  }
  std::vector<int> fan_of_vertex(size_t(n), -1);
  long long non_manifold_vertices = 0;
  for (int h = 0; h < nh; ++h) {
    const int v = tail(F, h), root = fans.find(h);
    if (fan_of_vertex[size_t(v)] < 0) fan_of_vertex[size_t(v)] = root;
    else if (fan_of_vertex[size_t(v)] != root && fan_of_vertex[size_t(v)] != -2) {
      fan_of_vertex[size_t(v)] = -2;
      ++non_manifold_vertices;
    }
  }
  if (non_manifold_vertices) return {ErrorCode::NonManifoldVertices, non_manifold_vertices, ""};

  // Boundary loops: on a manifold each boundary vertex has one outgoing boundary half-edge.
  std::vector<int> next_on_boundary(size_t(n), -1);
  for (int h = 0; h < nh; ++h)
    if (twin[size_t(h)] < 0) next_on_boundary[size_t(tail(F, h))] = head(F, h);
  std::vector<char> visited(size_t(n), 0);
  long long loops = 0;
  disk.boundary.clear();
  for (int i = 0; i < n; ++i) {
    if (next_on_boundary[size_t(i)] < 0 || visited[size_t(i)]) continue;
    ++loops;
    for (int v = i; !visited[size_t(v)]; v = next_on_boundary[size_t(v)]) {
      visited[size_t(v)] = 1;
      if (loops == 1) disk.boundary.push_back(v);
    }
  }
  if (loops == 0) return {ErrorCode::Closed, 0, ""};
  if (loops > 1) return {ErrorCode::SeveralBoundaryLoops, loops, ""};
  const long long euler = n - (long long)edge_list.size() + m;  // 2 - 2g - 1 for one loop
  if (euler != 1) return {ErrorCode::NotGenusZero, (1 - euler) / 2, ""};

  double total_area = 0;
  for (Eigen::Index f = 0; f < m; ++f) {
    const Eigen::RowVector3d a = disk.V.row(F(f, 0)), b = disk.V.row(F(f, 1)), c = disk.V.row(F(f, 2));
    total_area += (b - a).cross(c - a).norm();
  }
  if (!(total_area > 0)) return {ErrorCode::ZeroAreaMesh, m, ""};

  disk.is_boundary.assign(size_t(n), 0);
  for (int v : disk.boundary) disk.is_boundary[size_t(v)] = 1;
  disk.edges.resize(Eigen::Index(edge_list.size()), 2);
  for (size_t e = 0; e < edge_list.size(); ++e) {
    disk.edges(Eigen::Index(e), 0) = edge_list[e].first;
    disk.edges(Eigen::Index(e), 1) = edge_list[e].second;
  }
  disk.edge_on_boundary = edge_boundary;

  // Rings in counter-clockwise order: in face (v, a, b) the fan turns from a to b around v.
  std::vector<int> degree(size_t(n), 0);
  for (int h = 0; h < nh; ++h) ++degree[size_t(tail(F, h))];
  for (int v : disk.boundary) ++degree[size_t(v)];  // a boundary fan has one more neighbour than faces
  disk.ring_start.assign(size_t(n) + 1, 0);
  for (int i = 0; i < n; ++i) disk.ring_start[size_t(i) + 1] = disk.ring_start[size_t(i)] + degree[size_t(i)];
  std::vector<int> corner_start(size_t(n) + 1, 0), corner(static_cast<size_t>(nh));
  for (int h = 0; h < nh; ++h) ++corner_start[size_t(tail(F, h)) + 1];
  std::partial_sum(corner_start.begin(), corner_start.end(), corner_start.begin());
  std::vector<int> fill(corner_start.begin(), corner_start.end() - 1);
  for (int h = 0; h < nh; ++h) corner[size_t(fill[size_t(tail(F, h))]++)] = h;
  disk.ring.assign(size_t(disk.ring_start[size_t(n)]), -1);
  for (int v = 0; v < n; ++v) {
    const int c0 = corner_start[size_t(v)], c1 = corner_start[size_t(v) + 1];
    // Start at the corner whose outgoing edge is the boundary edge (any corner inside).
    int start = corner[size_t(c0)];
    if (disk.is_boundary[size_t(v)])
      for (int c = c0; c < c1; ++c)
        if (twin[size_t(corner[size_t(c)])] < 0) start = corner[size_t(c)];
    int slot = disk.ring_start[size_t(v)];
    int h = start;
    for (int step = 0; step < c1 - c0; ++step) {
      disk.ring[size_t(slot++)] = head(F, h);
      const int incoming = (h / 3) * 3 + (h % 3 + 2) % 3;  // from b back to v
      if (twin[size_t(incoming)] < 0) {                     // reached the other boundary edge
        disk.ring[size_t(slot++)] = tail(F, incoming);
        break;
      }
      h = twin[size_t(incoming)];
    }
  }
  return {};
}

}  // namespace lowstretch
