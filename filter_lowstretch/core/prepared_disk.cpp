#include "core/prepared_disk.h"

#include "core/ring_weights.h"

namespace lowstretch {

Error prepare_disk(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, InitialWeights kind, PreparedDisk& prepared) {
  if (Error e = make_disk_mesh(V, F, prepared.disk)) return e;
  prepared.kind = kind;
  prepared.uniform_fallbacks = 0;
  prepared.weights = initial_weights(prepared.disk, kind, prepared.uniform_fallbacks);
  prepared.ordering = std::make_shared<LuOrdering>();
  return {};
}

}  // namespace lowstretch
