// Checks that a triangle mesh is a topological disk and builds the connectivity the solver needs.
#pragma once
#include <Eigen/Core>
#include <vector>

#include "core/errors.h"

namespace lowstretch {

// A validated disk, with only the vertices that faces use ("compact" indices 0..n-1).
struct DiskMesh {
  Eigen::MatrixXd V;                 // n x 3 positions
  Eigen::MatrixXi F;                 // m x 3 compact vertex indices, counter-clockwise
  std::vector<int> input_vertex;     // compact index -> row of the input V
  std::vector<int> boundary;         // the boundary loop, interior on its left
  std::vector<char> is_boundary;     // per compact vertex
  Eigen::MatrixXi edges;             // E x 2, each undirected edge once
  std::vector<char> edge_on_boundary;  // per edge
  // Neighbours of every vertex in counter-clockwise order, as CSR: ring[ring_start[i] ..
  // ring_start[i+1]). For a boundary vertex the fan starts at its boundary successor.
  std::vector<int> ring_start, ring;
};

// Centres the bounding box of `points` (rows) and scales it into [-1/2, 1/2]^3. Every measure the
// core takes is scale-invariant, and finite but huge coordinates (1e200, DBL_MAX) would overflow
// edge lengths, areas and arc lengths to infinity; the map works on halves, which never overflow.
struct UnitBox {
  Eigen::RowVector3d centre_half = Eigen::RowVector3d::Zero();  // a quarter of (min + max)
  double extent = 1;                                             // half the largest side (1 if none)
  Eigen::RowVector3d map(const Eigen::RowVector3d& p) const { return (p / 2 - centre_half) / extent; }
  double unit() const { return 2 * extent; }  // one unit-box length in the input's units
};
UnitBox unit_box(const Eigen::MatrixXd& points);

// The vertices (rows of V) that sit exactly where another vertex sits: half or more of a mesh's
// vertices do in a triangle soup.
long long vertices_on_others(const Eigen::MatrixXd& V);

// Fills `disk` or returns the first problem found: indices, finiteness, edge manifoldness,
// orientation, components, vertex manifoldness, boundary loops, genus, zero total area.
Error make_disk_mesh(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, DiskMesh& disk);

}  // namespace lowstretch
