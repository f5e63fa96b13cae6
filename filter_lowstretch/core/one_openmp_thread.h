// CHOLMOD's factorizations start OpenMP teams of four threads (a fixed num_threads, which
// OMP_NUM_THREADS does not lower) for loops over a factor's columns, from every thread that
// calls them: charts factored on all threads at once leave more threads than cores, and each team
// spins while it waits. While one of these lives, the OpenMP regions its thread starts run on that
// thread alone (libgomp keeps the limit per thread: other threads are not touched).
#pragma once
#include <omp.h>

namespace lowstretch {

class OneOpenMpThread {
 public:
  OneOpenMpThread() : levels_(omp_get_max_active_levels()) { omp_set_max_active_levels(0); }
  ~OneOpenMpThread() { omp_set_max_active_levels(levels_); }
  OneOpenMpThread(const OneOpenMpThread&) = delete;
  OneOpenMpThread& operator=(const OneOpenMpThread&) = delete;

 private:
  int levels_;
};

}  // namespace lowstretch
