// Scans carry parts whose faces all have zero 3D area (collapsed dust, a face that names a vertex
// twice, given corners of its own). They have no surface to texture and no shape to map, so the
// atlas is made without them, and their faces get zero-area texture coordinates afterwards.
#pragma once
#include <Eigen/Core>
#include <vector>

#include "atlas/base/atlas_types.h"

namespace lowstretch {

// The faces of the edge-connected parts whose faces are all flat (is_flat_face; unit_V in the unit
// box), in input order.
std::vector<int> faces_of_zero_area_parts(const Eigen::MatrixXd& unit_V, const Eigen::MatrixXi& F);

// The atlas of the other faces (`mapped`: the input face of each of its rows) given back for all
// of F. A face of a zero-area part takes the texture coordinates at its corners' positions in the
// first chart that has all three with zero area (a collapsed edge's faces: no seam runs around
// them) and joins that chart; any other sits on one point, the texture coordinate of its first
// vertex where a mapped face has one, else the corner of the area inside the gutter. Those form
// one more chart, of zero stretch.
ChartsResult with_zero_area_faces(ChartsResult atlas, const Eigen::MatrixXd& V, const Eigen::MatrixXi& F,
                                  const std::vector<int>& mapped, const std::vector<int>& zero_area, const ChartOptions& options);

}  // namespace lowstretch
