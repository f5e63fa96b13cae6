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

// The border's loops, each as the corners (3 * face + k) its edges leave from, in order; none
// where a vertex has two border edges leaving it or a border edge leads to none. Looks only at the
// border, so that closed charts (which the max flow takes) cost little here.
std::vector<std::vector<int>> border_loops(const Corners& corners, const std::vector<std::array<int, 3>>& neighbour) {
  std::unordered_map<int, int> leaving;  // vertex -> the corner its border edge leaves from
  std::vector<int> starts;
  for (size_t i = 0; i < neighbour.size(); ++i)
    for (size_t k = 0; k < 3; ++k) {
      if (neighbour[i][k] >= 0) continue;
      if (!leaving.emplace(corners[i][k], int(3 * i + k)).second) return {};
      starts.push_back(int(3 * i + k));
    }
  std::vector<char> seen(3 * neighbour.size(), 0);
  std::vector<std::vector<int>> loops;
  for (const int start : starts) {
    if (seen[size_t(start)]) continue;
    std::vector<int> loop;
    for (int c = start; !seen[size_t(c)];) {
      seen[size_t(c)] = 1;
      loop.push_back(c);
      const auto next = leaving.find(corners[size_t(c) / 3][(size_t(c) % 3 + 1) % 3]);
      if (next == leaving.end()) return {};
      c = next->second;
    }
    loops.push_back(std::move(loop));
  }
  return loops;
}

// The loops by local vertex, or none unless the faces are of genus 0: Euler characteristic
// V - E + F = 2 - (the number of border loops).
std::vector<BorderLoop> genus_zero_border(const std::vector<std::vector<int>>& loop_corners, const std::vector<int>& vertex_of,
                                          int vertices) {
  const size_t n = vertex_of.size() / 3;
  size_t border = 0;
  for (const auto& l : loop_corners) border += l.size();
  const long edges = long(3 * n + border) / 2;  // each inner edge seen from both faces
  if ((3 * n + border) % 2 != 0 || long(vertices) - edges + long(n) != 2 - long(loop_corners.size())) return {};
  std::vector<BorderLoop> loops(loop_corners.size());
  for (size_t l = 0; l < loops.size(); ++l)
    for (const int c : loop_corners[l]) {
      loops[l].vertex.push_back(vertex_of[size_t(c)]);
      loops[l].face.push_back(c / 3);
    }
  return loops;
}

// Whether a loop (its corners, as border_loops gives them) meets the faces fixed on each side in
// one run of its edges.
bool meets_each_side_once(const std::vector<int>& loop, const std::vector<signed char>& fixed) {
  const size_t m = loop.size();
  const auto side_of_edge = [&](size_t t) { return fixed[size_t(loop[t % m] / 3)]; };
  int runs[2] = {0, 0};
  for (size_t t = 0; t < m; ++t)
    if (side_of_edge(t) >= 0 && side_of_edge(t) != side_of_edge(t + m - 1)) ++runs[side_of_edge(t)];
  return runs[0] == 1 && runs[1] == 1;
}

// Marks the vertices of a loop that meets each side once between the run of faces fixed on side
// 1 and that on side 0: 1 going from the first run to the second along the loop, 2 from the
// second to the first (ends included).
void mark_arcs(const BorderLoop& loop, const std::vector<signed char>& fixed, std::vector<char>& arc) {
  const size_t m = loop.face.size();
  const auto side_of_edge = [&](size_t t) { return fixed[size_t(loop.face[t % m])]; };
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
}

// The edges a seam may follow, from each vertex (compressed rows): inner edges not between two
// faces fixed on one side, each with its half-edge (3 * face + k) and seam cost; and, at no cost
// (half-edge -1), the border edges of every loop but `outer`: a hole is one point that a seam
// passes through, leaving it anywhere on its border.
struct SeamEdges {
  std::vector<int> first, to, half;
  std::vector<double> cost;
};

SeamEdges seam_edges(const std::vector<int>& vertex_of, int vertices, const std::vector<std::array<int, 3>>& neighbour,
                     const std::vector<std::array<double, 3>>& cost, const std::vector<signed char>& fixed,
                     const std::vector<BorderLoop>& loops, size_t outer) {
  struct Entry {
    int from, to, half;
    double cost;
  };
  std::vector<Entry> entries;
  for (size_t i = 0; i < neighbour.size(); ++i)
    for (size_t k = 0; k < 3; ++k) {
      const int j = neighbour[i][k];
      if (j <= int(i) || (fixed[i] >= 0 && fixed[i] == fixed[size_t(j)])) continue;  // each edge once
      const int a = vertex_of[3 * i + k], b = vertex_of[3 * i + (k + 1) % 3];
      entries.push_back({a, b, int(3 * i + k), cost[i][k]});
      entries.push_back({b, a, int(3 * i + k), cost[i][k]});
    }
  for (size_t l = 0; l < loops.size(); ++l)
    for (size_t t = 0; l != outer && t < loops[l].vertex.size(); ++t) {
      const int a = loops[l].vertex[t], b = loops[l].vertex[(t + 1) % loops[l].vertex.size()];
      entries.push_back({a, b, -1, 0.0});
      entries.push_back({b, a, -1, 0.0});
    }
  SeamEdges e;
  e.first.assign(size_t(vertices) + 1, 0);
  for (const Entry& x : entries) ++e.first[size_t(x.from) + 1];
  for (size_t v = 0; v < size_t(vertices); ++v) e.first[v + 1] += e.first[v];
  e.to.resize(entries.size()), e.half.resize(entries.size()), e.cost.resize(entries.size());
  std::vector<int> filled(e.first.begin(), e.first.end() - 1);
  for (const Entry& x : entries) {
    const size_t at = size_t(filled[size_t(x.from)]++);
    e.to[at] = x.to, e.half[at] = x.half, e.cost[at] = x.cost;
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
  for (int v = end; v >= 0 && via_vertex[size_t(v)] >= 0; v = via_vertex[size_t(v)])
    if (via_half[size_t(v)] >= 0) path.push_back(via_half[size_t(v)]);
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
  // The outer loop: the first that meets each side's fixed faces in one run (found from the
  // border alone, before the chart's vertices are numbered: most charts the max flow takes fail here).
  const std::vector<std::vector<int>> loop_corners = border_loops(corners, neighbour);
  size_t outer = 0;
  while (outer < loop_corners.size() && !meets_each_side_once(loop_corners[outer], fixed)) ++outer;
  if (outer == loop_corners.size()) return false;
  int vertices = 0;
  const std::vector<int> vertex_of = local_vertices(corners, vertices);
  const std::vector<BorderLoop> loops = genus_zero_border(loop_corners, vertex_of, vertices);
  if (loops.empty()) return false;
  std::vector<char> arc(size_t(vertices), 0);
  mark_arcs(loops[outer], fixed, arc);
  double length = 0;
  const std::vector<int> path = shortest_path(seam_edges(vertex_of, vertices, neighbour, cost, fixed, loops, outer), arc, length);
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
