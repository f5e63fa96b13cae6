#include "atlas/cut/cheapest_seam.h"

#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/boykov_kolmogorov_max_flow.hpp>

#include "atlas/cut/seam_path.h"

namespace lowstretch {

namespace {

using Traits = boost::adjacency_list_traits<boost::vecS, boost::vecS, boost::directedS>;
using FlowGraph = boost::adjacency_list<
    boost::vecS, boost::vecS, boost::directedS,
    boost::property<boost::vertex_color_t, boost::default_color_type,
                    boost::property<boost::vertex_distance_t, long, boost::property<boost::vertex_predecessor_t, Traits::edge_descriptor>>>,
    boost::property<boost::edge_capacity_t, double,
                    boost::property<boost::edge_residual_capacity_t, double, boost::property<boost::edge_reverse_t, Traits::edge_descriptor>>>>;

}  // namespace

std::vector<char> cheapest_seam_by_max_flow(const std::vector<std::array<int, 3>>& neighbour,
                                            const std::vector<std::array<double, 3>>& cost, const std::vector<signed char>& fixed) {
  const size_t n = fixed.size();
  // Graph nodes: 0 the faces fixed on side 1 (the source), 1 those on side 0 (the sink), then one
  // per free face.
  std::vector<int> node(n);
  int nodes = 2;
  for (size_t i = 0; i < n; ++i) node[i] = fixed[i] == 1 ? 0 : fixed[i] == 0 ? 1 : nodes++;
  std::vector<char> side(n);
  for (size_t i = 0; i < n; ++i) side[i] = fixed[i] == 1;
  if (nodes == 2) return side;
  FlowGraph graph{size_t(nodes)};
  auto capacity = boost::get(boost::edge_capacity, graph);
  auto reverse = boost::get(boost::edge_reverse, graph);
  for (size_t i = 0; i < n; ++i)
    for (size_t k = 0; k < 3; ++k) {
      const int j = neighbour[i][k];
      if (j < int(i)) continue;  // each edge once (and none across the border)
      const int u = node[i], v = node[size_t(j)];
      if (u == v && u < 2) continue;  // inside one fixed side
      const auto there = boost::add_edge(size_t(u), size_t(v), graph).first;
      const auto back = boost::add_edge(size_t(v), size_t(u), graph).first;
      capacity[there] = capacity[back] = cost[i][k];
      reverse[there] = back;
      reverse[back] = there;
    }
  boost::boykov_kolmogorov_max_flow(graph, 0, 1);
  // The source's tree is coloured black: the faces on side 1 of the cut.
  const auto colour = boost::get(boost::vertex_color, graph);
  for (size_t i = 0; i < n; ++i)
    if (node[i] >= 2) side[i] = colour[size_t(node[i])] == boost::black_color;
  return side;
}

std::vector<char> cheapest_seam(const std::vector<std::array<int, 3>>& corners, const std::vector<std::array<int, 3>>& neighbour,
                                const std::vector<std::array<double, 3>>& cost, const std::vector<signed char>& fixed) {
  std::vector<char> side;
  if (cheapest_seam_as_path(corners, neighbour, cost, fixed, side)) return side;
  return cheapest_seam_by_max_flow(neighbour, cost, fixed);
}

}  // namespace lowstretch
