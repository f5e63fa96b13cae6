// The vertices a mesh's faces use, and those moved into a unit box: an input may list vertices no
// face uses, which must not widen the box or count as duplicates.
#pragma once
#include <Eigen/Core>

namespace lowstretch {

// The rows of V that faces use.
Eigen::MatrixXd used_rows(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F);
// The used vertices moved into make_disk_mesh's unit box, so that huge coordinates do not
// overflow lengths and areas; `unit` converts lengths back to the input's units. Unused rows are 0.
Eigen::MatrixXd unit_box_of_used(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, double& unit);

}  // namespace lowstretch
