// Where a model made of flat and gently curved faces (a CAD part) falls apart naturally: along its
// sharp edges. Each patch between them is nearly developable (a plane, a cylinder, a cone), so a
// free boundary maps it with almost no stretch.
#pragma once
#include <Eigen/Core>
#include <vector>

namespace lowstretch {

// The faces that share an edge and whose normals differ by less than `angle_degrees` are joined (an
// edge with a zero-area face on either side joins too). Returns the patches, each a list of face
// indices in input order, ordered by their first face.
std::vector<std::vector<int>> patches_between_sharp_edges(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F,
                                                          double angle_degrees);

}  // namespace lowstretch
