// A map turned in its plane keeps its stretch; turned so that its box is smallest, it leaves the
// least of the box empty, in a tiling cell or on the packing grid (which turns only by quarters).
#pragma once
#include <Eigen/Core>

namespace lowstretch {

// uv (#V x 2) turned about the origin so that the box of faces F's corners is smallest (to
// kTuning.projection_turns steps of a quarter turn).
Eigen::MatrixXd turned_to_smallest_box(const Eigen::MatrixXd& uv, const Eigen::MatrixXi& F);

}  // namespace lowstretch
