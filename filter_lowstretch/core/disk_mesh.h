// Checks that a triangle mesh is a topological disk and builds the connectivity the solver needs.
#pragma once
#include <Eigen/Core>
#include <vector>

#include "error.h"

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

// Fills `disk` or returns the first problem found: indices, finiteness, edge manifoldness,
// orientation, components, vertex manifoldness, boundary loops, genus, zero total area.
Error make_disk_mesh(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, DiskMesh& disk);

}  // namespace lowstretch
