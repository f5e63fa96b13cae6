// Half-edges of a triangle array: half-edge h = 3 f + k runs from F(f, k) to F(f, (k + 1) % 3),
// and corner h is vertex F(f, k) in face f (the tail of half-edge h).
#pragma once
#include <Eigen/Core>
#include <cstdint>
#include <utility>
#include <vector>

namespace lowstretch {

inline int half_edge_tail(const Eigen::MatrixXi& F, int h) { return F(h / 3, h % 3); }
inline int half_edge_head(const Eigen::MatrixXi& F, int h) { return F(h / 3, (h % 3 + 1) % 3); }
inline int next_half_edge(int h) { return (h / 3) * 3 + (h % 3 + 1) % 3; }
inline int previous_half_edge(int h) { return (h / 3) * 3 + (h % 3 + 2) % 3; }  // ends at the tail of h

// Every half-edge with the key of its undirected edge (smaller vertex in the high 32 bits),
// sorted by key (ties by h): the half-edges of one edge are neighbours.
std::vector<std::pair<uint64_t, int>> half_edges_by_edge(const Eigen::MatrixXi& F);

// The half-edges of each edge that exactly two faces of opposite orientation share, paired
// (twin: the opposite of each half-edge, -1 across any other edge), and the count of edges shared
// by more than two faces or by two that run the same way. keyed: half_edges_by_edge(F).
struct EdgePairing {
  std::vector<int> twin;
  long long non_manifold = 0, misoriented = 0;
};
EdgePairing pair_manifold_half_edges(const Eigen::MatrixXi& F, const std::vector<std::pair<uint64_t, int>>& keyed);

// The opposite half-edge of each half-edge, -1 on the boundary. Meant for edge-manifold,
// consistently oriented meshes (checked beforehand by make_disk_mesh); on others the pairing of
// an edge shared by more than two faces is arbitrary.
std::vector<int> opposite_half_edges(const Eigen::MatrixXi& F);

// The fan of each corner (half-edge h's tail): corners around one vertex joined across the
// edges their faces share, one number per fan (the smallest corner in it). On a manifold every
// vertex has one fan; where parts or holes touch at a vertex only, it has several.
std::vector<int> corner_fans(const std::vector<int>& twin);

}  // namespace lowstretch
