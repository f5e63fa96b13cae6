// A disk, the initial weights of its interior (the method's step 2) and the LU ordering of its pass
// system. All depend on the mesh alone, not on where its boundary goes: a mesh mapped onto many
// boundaries prepares them once.
#pragma once
#include <Eigen/Core>
#include <memory>
#include <vector>

#include "core/disk_mesh.h"
#include "core/errors.h"
#include "core/method_types.h"
#include "core/small_system_lu.h"

namespace lowstretch {

struct PreparedDisk {
  DiskMesh disk;
  InitialWeights kind = InitialWeights::Floater;
  std::vector<double> weights;  // aligned with disk.ring (ring_weights.h)
  int uniform_fallbacks = 0;    // interior vertices whose degenerate one-ring got uniform weights
  // The LU's ordering of the pass system, whose pattern is the mesh's too: found by the first
  // direct solve of any map of this disk, from any thread.
  std::shared_ptr<LuOrdering> ordering;
};

// make_disk_mesh, then the weights of `kind`; the first problem found, if any.
Error prepare_disk(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, InitialWeights kind, PreparedDisk& prepared);

}  // namespace lowstretch
