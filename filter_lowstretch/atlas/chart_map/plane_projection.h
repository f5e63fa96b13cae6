// A chart that is nearly flat (a face of a CAD part) has an exact map: its shape seen along its
// normal. No boundary to choose and no stretch beyond its curvature.
#include "atlas/base/tuning.h"
#pragma once
#include <Eigen/Core>

namespace lowstretch {

// The vertices of V projected onto the plane across the area-weighted normal of faces F, turned so
// that the box of the faces' corners is smallest (to kTuning.projection_turns steps of a quarter turn).
// Returns #V x 2 (rows of vertices that F does not use are projected too).
Eigen::MatrixXd project_onto_own_plane(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F);

}  // namespace lowstretch
