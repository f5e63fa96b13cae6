#include "plugin_common/one_blas_thread.h"

#include <dlfcn.h>

namespace lowstretch {

OneBlasThread::OneBlasThread() {
  // Looked up at run time: the BLAS is whichever Debian's alternatives point at.
  const auto get = reinterpret_cast<int (*)()>(dlsym(RTLD_DEFAULT, "openblas_get_num_threads"));
  set_threads_ = reinterpret_cast<void (*)(int)>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads"));
  if (!get || !set_threads_) {
    set_threads_ = nullptr;
    return;
  }
  previous_ = get();
  set_threads_(1);
}

OneBlasThread::~OneBlasThread() {
  if (set_threads_ && previous_ > 0) set_threads_(previous_);
}

}  // namespace lowstretch
