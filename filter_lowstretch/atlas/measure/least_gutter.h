// The gutter a stored atlas keeps, measured from its texture coordinates: the least distance from a
// chart to another chart or to the texture's border. Baking writes a chart's texels up to the
// gutter around it; closer charts bleed into each other, and mipmaps mix them.
#pragma once
#include <Eigen/Core>
#include <vector>

namespace lowstretch {

// corner_uv: #F x 6, the stored layout; face_chart: each face's chart. Faces of zero UV area (a
// part of no 3D area on a point) are left out. Returns the least distance, in UV units, from a
// chart's triangles to another chart's or to the border of [0,1]^2; a distance between charts
// above `within` is not looked for (the result is then at least min(within, the border's)).
double least_gutter(const Eigen::MatrixXd& corner_uv, const std::vector<int>& face_chart, double within);

}  // namespace lowstretch
