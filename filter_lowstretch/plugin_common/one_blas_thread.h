// While the atlas solves its charts on the thread pool, OpenBLAS's own threads (UMFPACK's and
// CHOLMOD's dense fronts) only spin: a quarter of the time on a 1.5k-vertex mesh went to
// sched_yield. And a BLAS splitting its work by its thread count could give other last digits on
// another machine (issue 51: no result depends on threads). This guard asks OpenBLAS for one
// thread while it lives and restores the count after; with another BLAS (no such symbols) it does
// nothing. The tool holds one for its run, both MeshLab filters one for each call
// (plugin::run).
#pragma once

namespace lowstretch {

class OneBlasThread {
 public:
  OneBlasThread();
  ~OneBlasThread();
  OneBlasThread(const OneBlasThread&) = delete;
  OneBlasThread& operator=(const OneBlasThread&) = delete;

 private:
  void (*set_threads_)(int) = nullptr;
  int previous_ = 0;
};

}  // namespace lowstretch
