#include "atlas/cut/seam_path.h"

#include <algorithm>
#include <functional>
#include <limits>
#include <queue>
#include <unordered_map>
#include <utility>

namespace lowstretch {

namespace {

using Corners = std::vector<std::array<int, 3>>;

// Each corner's vertex (corner 3 * face + k), numbered 0 to count - 1.
std::vector<int> local_vertices(const Corners& corners, int& count) {
  std::vector<int> vertex_of;
  vertex_of.reserve(3 * corners.size());
  for (const auto& c : corners) vertex_of.insert(vertex_of.end(), c.begin(), c.end());
  std::vector<int> ids = vertex_of;
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  for (int& v : vertex_of) v = int(std::lower_bound(ids.begin(), ids.end(), v) - ids.begin());
  count = int(ids.size());
  return vertex_of;
}

// The border loop in order: its t-th edge runs from vertex[t] to vertex[t + 1] along face[t].
struct BorderLoop {
  std::vector<int> vertex, face;
};

// The corners (3 * face + k) that the border's edges leave from, in order along the one border
// loop; empty where the border is not one loop (none, more than one, or a vertex two border edges
// leave). Looks only at the border, so that the max flow's charts (holes, closed) cost little here.
std::vector<int> one_border_loop(const Corners& corners, const std::vector<std::array<int, 3>>& neighbour) {
  std::unordered_map<int, int> leaving;  // vertex -> the corner its border edge leaves from
  int start = -1;
  for (size_t i = 0; i < neighbour.size(); ++i)
    for (size_t k = 0; k < 3; ++k) {
      if (neighbour[i][k] >= 0) continue;
      if (!leaving.emplace(corners[i][k], int(3 * i + k)).second) return {};
      if (start < 0) start = int(3 * i + k);
    }
  std::vector<int> loop;
  for (int c = start; c >= 0 && loop.size() < leaving.size();) {
    loop.push_back(c);
    const auto next = leaving.find(corners[size_t(c) / 3][(size_t(c) % 3 + 1) % 3]);
    c = next == leaving.end() ? -1 : next->second;
    if (c == start) return loop.size() == leaving.size() ? loop : std::vector<int>{};
  }
  return {};
}

// The loop by local vertex, or empty unless the faces are a disk: Euler characteristic
// V - E + F = 1 with one border loop.
BorderLoop disk_border(const std::vector<int>& loop_corners, const std::vector<int>& vertex_of, int vertices) {
  const size_t n = vertex_of.size() / 3, border = loop_corners.size();
  const long edges = long(3 * n + border) / 2;  // each inner edge seen from both faces
  if ((3 * n + border) % 2 != 0 || long(vertices) - edges + long(n) != 1) return {};
  BorderLoop loop;
  for (const int c : loop_corners) {
    loop.vertex.push_back(vertex_of[size_t(c)]);
    loop.face.push_back(c / 3);
  }
  return loop;
}

// Marks the border's vertices between the run of faces fixed on side 1 and that on side 0: 1
// going from the first run to the second along the loop, 2 from the second to the first (ends
// included). False unless each side's fixed faces meet the border in one run.
bool mark_arcs(const BorderLoop& loop, const std::vector<signed char>& fixed, std::vector<char>& arc) {
  const size_t m = loop.face.size();
  const auto side_of_edge = [&](size_t t) { return fixed[size_t(loop.face[t % m])]; };
  int runs[2] = {0, 0};
  for (size_t t = 0; t < m; ++t)
    if (side_of_edge(t) >= 0 && side_of_edge(t) != side_of_edge(t + m - 1)) ++runs[side_of_edge(t)];
  if (runs[0] != 1 || runs[1] != 1) return false;
  // Per border vertex t: the side of the last fixed edge before it and of the first from it on.
  std::vector<signed char> before(m), after(m);
  signed char last = -1;
  for (size_t s = 0; s < 2 * m; ++s) {
    before[s % m] = last;
    if (side_of_edge(s) >= 0) last = side_of_edge(s);
  }
  for (size_t s = 2 * m; s-- > 0;) {
    if (side_of_edge(s) >= 0) last = side_of_edge(s);
    after[s % m] = last;
  }
  for (size_t t = 0; t < m; ++t)
    arc[size_t(loop.vertex[t])] = before[t] == 1 && after[t] == 0 ? 1 : before[t] == 0 && after[t] == 1 ? 2 : 0;
  return true;
}

// The edges a seam may follow, from each vertex (compressed rows): inner edges not between two
// faces fixed on one side, each with its half-edge (3 * face + k) and seam cost.
struct SeamEdges {
  std::vector<int> first, to, half;
  std::vector<double> cost;
};

SeamEdges seam_edges(const std::vector<int>& vertex_of, int vertices, const std::vector<std::array<int, 3>>& neighbour,
                     const std::vector<std::array<double, 3>>& cost, const std::vector<signed char>& fixed) {
  std::vector<std::array<int, 2>> half_of;  // (half-edge, direction) of each entry
  std::vector<int> count(size_t(vertices) + 1, 0);
  for (size_t i = 0; i < neighbour.size(); ++i)
    for (size_t k = 0; k < 3; ++k) {
      const int j = neighbour[i][k];
      if (j <= int(i) || (fixed[i] >= 0 && fixed[i] == fixed[size_t(j)])) continue;  // each edge once
      for (int direction = 0; direction < 2; ++direction) {
        half_of.push_back({int(3 * i + k), direction});
        ++count[size_t(vertex_of[3 * i + (k + size_t(direction)) % 3]) + 1];
      }
    }
  SeamEdges e;
  e.first.assign(size_t(vertices) + 1, 0);
  for (size_t v = 0; v < size_t(vertices); ++v) e.first[v + 1] = e.first[v] + count[v + 1];
  e.to.resize(half_of.size()), e.half.resize(half_of.size()), e.cost.resize(half_of.size());
  std::vector<int> filled(e.first.begin(), e.first.end() - 1);
  for (const auto& h : half_of) {
    const size_t i = size_t(h[0]) / 3, k = size_t(h[0]) % 3;
    const int from = vertex_of[3 * i + (k + size_t(h[1])) % 3], to = vertex_of[3 * i + (k + 1 - size_t(h[1])) % 3];
    const int at = filled[size_t(from)]++;
    e.to[size_t(at)] = to, e.half[size_t(at)] = h[0], e.cost[size_t(at)] = cost[i][k];
  }
  return e;
}

// The half-edges of the shortest path from an arc-1 vertex to an arc-2 vertex, and its length
// (infinite where there is none).
std::vector<int> shortest_path(const SeamEdges& e, const std::vector<char>& arc, double& length) {
  const size_t vertices = arc.size();
  std::vector<double> distance(vertices, std::numeric_limits<double>::infinity());
  std::vector<int> via_half(vertices, -1), via_vertex(vertices, -1);
  using Entry = std::pair<double, int>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
  for (size_t v = 0; v < vertices; ++v)
    if (arc[v] == 1) distance[v] = 0, queue.push({0.0, int(v)});
  int end = -1;
  while (!queue.empty() && end < 0) {
    const Entry top = queue.top();
    queue.pop();
    const size_t v = size_t(top.second);
    if (top.first > distance[v]) continue;
    if (arc[v] == 2) end = int(v);
    for (int at = e.first[v]; at < e.first[v + 1] && end < 0; ++at) {
      const size_t w = size_t(e.to[size_t(at)]);
      const double through = top.first + e.cost[size_t(at)];
      if (through < distance[w]) {
        distance[w] = through, via_half[w] = e.half[size_t(at)], via_vertex[w] = int(v);
        queue.push({through, int(w)});
      }
    }
  }
  length = end < 0 ? std::numeric_limits<double>::infinity() : distance[size_t(end)];
  std::vector<int> path;
  for (int v = end; v >= 0 && via_half[size_t(v)] >= 0; v = via_vertex[size_t(v)]) path.push_back(via_half[size_t(v)]);
  return path;
}

// Each face's side: 1 for those reached from the faces fixed on side 1 without crossing the path.
// False where a face fixed on side 0 is reached or a path edge has no twin.
bool sides_beside(const std::vector<int>& path, const std::vector<int>& vertex_of, const std::vector<std::array<int, 3>>& neighbour,
                  const std::vector<signed char>& fixed, std::vector<char>& side) {
  const size_t n = neighbour.size();
  std::vector<char> blocked(3 * n, 0);
  for (const int h : path) {
    const size_t i = size_t(h) / 3, k = size_t(h) % 3, j = size_t(neighbour[i][k]);
    int twin = -1;
    for (size_t l = 0; l < 3; ++l)
      if (neighbour[j][l] == int(i) && vertex_of[3 * j + l] == vertex_of[3 * i + (k + 1) % 3]) twin = int(3 * j + l);
    if (twin < 0) return false;
    blocked[size_t(h)] = blocked[size_t(twin)] = 1;
  }
  side.assign(n, 0);
  std::vector<int> stack;
  for (size_t i = 0; i < n; ++i)
    if (fixed[i] == 1) side[i] = 1, stack.push_back(int(i));
  while (!stack.empty()) {
    const size_t f = size_t(stack.back());
    stack.pop_back();
    for (size_t k = 0; k < 3; ++k) {
      const int g = neighbour[f][k];
      if (g < 0 || blocked[3 * f + k] || side[size_t(g)]) continue;
      if (fixed[size_t(g)] == 0) return false;
      side[size_t(g)] = 1;
      stack.push_back(g);
    }
  }
  return true;
}

}  // namespace

bool cheapest_seam_as_path(const Corners& corners, const std::vector<std::array<int, 3>>& neighbour,
                           const std::vector<std::array<double, 3>>& cost, const std::vector<signed char>& fixed,
                           std::vector<char>& side) {
  const std::vector<int> loop_corners = one_border_loop(corners, neighbour);
  if (loop_corners.empty()) return false;
  int vertices = 0;
  const std::vector<int> vertex_of = local_vertices(corners, vertices);
  const BorderLoop loop = disk_border(loop_corners, vertex_of, vertices);
  std::vector<char> arc(size_t(vertices), 0);
  if (loop.face.empty() || !mark_arcs(loop, fixed, arc)) return false;
  double length = 0;
  const std::vector<int> path = shortest_path(seam_edges(vertex_of, vertices, neighbour, cost, fixed), arc, length);
  std::vector<char> found;
  if (!(length < std::numeric_limits<double>::infinity()) || !sides_beside(path, vertex_of, neighbour, fixed, found)) return false;
  // The sides' seam is part of the path; more would mean the path did not separate them.
  double seam = 0;
  for (size_t i = 0; i < neighbour.size(); ++i)
    for (size_t k = 0; k < 3; ++k)
      if (neighbour[i][k] > int(i) && found[i] != found[size_t(neighbour[i][k])]) seam += cost[i][k];
  if (seam > length * (1 + 1e-9) + 1e-300) return false;
  side = std::move(found);
  return true;
}

}  // namespace lowstretch
