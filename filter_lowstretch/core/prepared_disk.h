// A disk and the initial weights of its interior (the method's step 2). Both depend on the mesh
// alone, not on where its boundary goes: a mesh mapped onto many boundaries prepares them once.
#pragma once
#include <Eigen/Core>
#include <vector>

#include "core/disk_mesh.h"
#include "core/errors.h"
#include "core/method_types.h"

namespace lowstretch {

struct PreparedDisk {
  DiskMesh disk;
  InitialWeights kind = InitialWeights::Floater;
  std::vector<double> weights;  // aligned with disk.ring (ring_weights.h)
  int uniform_fallbacks = 0;    // interior vertices whose degenerate one-ring got uniform weights
};

// make_disk_mesh, then the weights of `kind`; the first problem found, if any.
Error prepare_disk(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, InitialWeights kind, PreparedDisk& prepared);

}  // namespace lowstretch
