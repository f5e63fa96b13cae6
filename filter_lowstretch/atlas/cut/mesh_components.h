// Splitting a triangle array into its connected components.
#pragma once
#include <Eigen/Core>
#include <functional>
#include <vector>

namespace lowstretch {

// Edge-connected components: faces that share an edge are in one component, or only across the
// edges that `joins(h, t)` accepts (h and t the edge's two half-edges) if it is given. Returns the
// component of each face, numbered 0..count-1 in the order of their first face.
std::vector<int> face_components(const Eigen::MatrixXi& F, int& count, const std::function<bool(int, int)>& joins = nullptr);

// The vertices used by faces of more than one component (a mesh whose parts touch at a vertex
// only): such a vertex is not manifold.
int vertices_shared_by_components(const Eigen::MatrixXi& F, int vertex_count, const std::vector<int>& component);

}  // namespace lowstretch
