// METIS, which CHOLMOD and UMFPACK call to order a matrix, keeps its random state in globals:
// two orderings at once, on two threads, can differ from run to run (and so can every map solved
// with them, in its last bits). Every analysis that may call METIS holds this lock.
#pragma once
#include <mutex>

namespace lowstretch {

inline std::mutex& metis_lock() {
  static std::mutex lock;
  return lock;
}

}  // namespace lowstretch
